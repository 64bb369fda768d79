// The sandbox probe: run by the grader inside the same sandbox as student code, it tries what a
// hostile submission would and prints one `name=value` per line. The grader's "protection"
// line is made of these findings, not of fixed text.
// Usage: probe SECRET_PATH...   (host paths that must be unreadable, e.g. the hidden tests)
#include <fcntl.h>
#include <linux/io_uring.h>
#include <linux/netlink.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/statvfs.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

int main(int argc, char** argv) {
  std::printf("uid=%d\n", static_cast<int>(::geteuid()));
  std::string cap = "?";
  std::ifstream st("/proc/self/status");
  for (std::string l; std::getline(st, l);)
    if (l.rfind("CapEff:", 0) == 0) cap = l.substr(l.find_first_not_of(" \t", 7));
  std::printf("caps=%s\n", cap == "0000000000000000" ? "none" : cap.c_str());
  const int w = ::open("/usr/.t2-probe", O_WRONLY | O_CREAT | O_EXCL, 0600);
  std::printf("write_usr=%s\n", w >= 0 ? "yes" : "no");
  if (w >= 0) ::unlink("/usr/.t2-probe");
  std::printf("remount_usr=%s\n", ::mount("none", "/usr", nullptr, MS_REMOUNT | MS_BIND, nullptr) == 0 ? "yes" : "no");
  std::printf("new_userns=%s\n", ::unshare(CLONE_NEWUSER) == 0 ? "yes" : "no");
  std::printf("new_mountns=%s\n", ::unshare(CLONE_NEWNS) == 0 ? "yes" : "no");
  // Network: a namespace with no interface but a (down) loopback.
  int ifaces = 0;
  std::ifstream dev("/proc/net/dev");
  for (std::string l; std::getline(dev, l);)
    if (l.find(':') != std::string::npos && l.find("lo:") == std::string::npos) ++ifaces;
  std::printf("network_interfaces=%d\n", ifaces);
  // io_uring runs system calls the seccomp filter never sees; netlink talks to the kernel's
  // configuration. Both must be refused.
  io_uring_params params{};
  const long ring = ::syscall(__NR_io_uring_setup, 1, &params);
  std::printf("io_uring=%s\n", ring >= 0 ? "yes" : "no");
  const int nl = ::socket(AF_NETLINK, SOCK_RAW, NETLINK_ROUTE);
  std::printf("netlink=%s\n", nl >= 0 ? "yes" : "no");
  // Host paths: a mount of a host file system whose source folder is not where it is mounted
  // (/usr on /usr says nothing; /tmp/t2grade-x/driver.bin on /t2/driver would).
  int host_paths = 0;
  std::ifstream mi("/proc/self/mountinfo");
  for (std::string l; std::getline(mi, l);) {
    std::istringstream f(l);
    std::string id, parent, dev, root, point, fstype;
    f >> id >> parent >> dev >> root >> point;
    const auto dash = l.find(" - ");
    if (dash != std::string::npos) std::istringstream(l.substr(dash + 3)) >> fstype;
    if (root != point && fstype != "tmpfs" && fstype != "proc" && fstype != "devtmpfs" && fstype != "devpts") ++host_paths;
  }
  std::printf("host_paths=%d\n", host_paths);
  int unread = 0, total = 0;
  for (int i = 1; i < argc; ++i, ++total)
    if (::open(argv[i], O_RDONLY) < 0) ++unread;
  std::printf("secrets_unreadable=%d/%d\n", unread, total);
  // /dev is a tmpfs of the sandbox: read-only, or it would be memory no limit bounds (issue 29).
  bool dev_writable = false;
  for (const char* f : {"/dev/.t2-probe", "/dev/shm/.t2-probe"}) {
    const int d = ::open(f, O_WRONLY | O_CREAT | O_EXCL, 0600);
    if (d >= 0) dev_writable = true, ::close(d), ::unlink(f);
  }
  std::printf("write_dev=%s\n", dev_writable ? "yes" : "no");
  struct statvfs v{};
  if (::statvfs("/tmp", &v) == 0) std::printf("tmp_mb=%llu\n", static_cast<unsigned long long>(v.f_blocks) * v.f_frsize >> 20);
  rlimit np{};
  ::getrlimit(RLIMIT_NPROC, &np);
  std::printf("nproc=%lld\n", np.rlim_cur == RLIM_INFINITY ? -1LL : static_cast<long long>(np.rlim_cur));
  std::printf("no_new_privs=%d\n", ::prctl(PR_GET_NO_NEW_PRIVS, 0, 0, 0, 0));
  std::printf("seccomp=%s\n", [] {
    std::ifstream s("/proc/self/status");
    for (std::string l; std::getline(s, l);)
      if (l.rfind("Seccomp:", 0) == 0) return l.find('2') != std::string::npos ? "filter" : "none";
    return "unknown";
  }());
  return 0;
}
