// The grader's sandbox: see grader_sandbox.hpp.
#include "grader_sandbox.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sched.h>
#include <seccomp.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <algorithm>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

#include <fmt/format.h>

namespace t2grader {

namespace {

// System calls no graded program needs and every escape uses.
constexpr const char* kDenied[] = {
    "mount", "umount2", "unshare", "setns", "ptrace", "open_by_handle_at", "name_to_handle_at",
    "bpf", "keyctl", "add_key", "request_key", "pivot_root", "chroot", "kexec_load",
    "kexec_file_load", "init_module", "finit_module", "delete_module", "perf_event_open",
    "userfaultfd", "fsopen", "fsmount", "fsconfig", "move_mount", "open_tree", "mount_setattr",
    "process_vm_readv", "process_vm_writev", "swapon", "swapoff", "reboot", "acct", "quotactl",
    "io_uring_setup", "io_uring_enter", "io_uring_register"};  // io_uring: system calls no filter sees

// The seccomp program (BPF), built once with libseccomp.
const std::string& seccomp_program() {
  static const std::string prog = [] {
    scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ALLOW);
    if (!ctx) throw GraderError("libseccomp: cannot create a filter");
    for (const char* name : kDenied) {
      const int nr = seccomp_syscall_resolve_name(name);
      if (nr != __NR_SCMP_ERROR) seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), nr, 0);
    }
    // New namespaces through clone: refused flag by flag; clone3 (flags in memory) not at all,
    // so that the C library falls back to clone.
    for (unsigned long flag : {CLONE_NEWUSER, CLONE_NEWNS, CLONE_NEWNET, CLONE_NEWPID, CLONE_NEWIPC,
                               CLONE_NEWUTS, CLONE_NEWCGROUP})
      seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(clone), 1, scmp_arg_cmp{0, SCMP_CMP_MASKED_EQ, flag, flag});
    seccomp_rule_add(ctx, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3), 0);
    // Netlink sockets talk to the kernel's configuration (routes, audit, uevents ...). (The
    // comparisons are written as structs: SCMP_A0 is a C compound literal, which C++ lacks.)
    seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(socket), 1, scmp_arg_cmp{0, SCMP_CMP_EQ, AF_NETLINK, 0});
    const int fd = memfd_create("t2-seccomp", MFD_CLOEXEC);
    std::string bytes;
    if (fd >= 0 && seccomp_export_bpf(ctx, fd) == 0 && lseek(fd, 0, SEEK_SET) == 0) {
      char buf[4096];
      for (ssize_t n; (n = read(fd, buf, sizeof buf)) > 0;) bytes.append(buf, static_cast<size_t>(n));
    }
    if (fd >= 0) close(fd);
    seccomp_release(ctx);
    if (bytes.empty()) throw GraderError("libseccomp: cannot export the filter");
    return bytes;
  }();
  return prog;
}

// A fresh fd holding the seccomp program at offset 0 (bubblewrap reads it to the end).
int seccomp_fd() {
  const int fd = memfd_create("t2-seccomp", MFD_CLOEXEC);
  if (fd < 0) throw GraderError("cannot create a memfd for the seccomp filter");
  const std::string& p = seccomp_program();
  if (write(fd, p.data(), p.size()) != static_cast<ssize_t>(p.size()) || lseek(fd, 0, SEEK_SET) != 0) {
    close(fd);
    throw GraderError("cannot write the seccomp filter");
  }
  return fd;
}

bool write_text(const fs::path& f, const std::string& s) {
  std::ofstream o(f);
  o << s;
  o.flush();
  return static_cast<bool>(o);
}

// A cgroup (v2, else v1 memory + pids + cpu) for the whole tree of one run, removed afterwards.
class Cgroup {
 public:
  Cgroup(std::uint64_t memory, int pids) {
    static std::atomic<int> serial{0};
    const std::string name = fmt::format("t2grade-{}-{}", getpid(), serial++);
    const fs::path root = "/sys/fs/cgroup";
    std::error_code ec;
    if (fs::exists(root / "cgroup.controllers", ec)) {
      write_text(root / "cgroup.subtree_control", "+memory +pids +cpu");
      add(root / name, {{"pids.max", std::to_string(pids)}, {"cpu.max", "100000 100000"}});
      if (memory) add(root / name, {{"memory.max", std::to_string(memory)}, {"memory.swap.max", "0"}});
      usage_ = {root / name / "cpu.stat", 1e-6};
    } else {
      add(root / "pids" / name, {{"pids.max", std::to_string(pids)}});
      if (memory) add(root / "memory" / name, {{"memory.limit_in_bytes", std::to_string(memory)}});
      add(root / "cpu" / name, {{"cpu.cfs_period_us", "100000"}, {"cpu.cfs_quota_us", "100000"}});
      // CPU time used: cpuacct, mounted with cpu (cpu,cpuacct) or on its own.
      const fs::path acct = fs::exists(root / "cpu" / name / "cpuacct.usage", ec) ? root / "cpu" / name : root / "cpuacct" / name;
      if (acct != root / "cpu" / name) add(acct, {});
      usage_ = {acct / "cpuacct.usage", 1e-9};
    }
  }
  /// CPU seconds the whole tree has used so far (-1 when unknown).
  double cpu_seconds() const {
    std::ifstream in(usage_.first);
    std::string word;
    double v = -1;
    if (usage_.second == 1e-6) {  // cgroup v2: "usage_usec N" in cpu.stat
      for (std::string key; in >> key >> word;)
        if (key == "usage_usec") v = std::stod(word);
    } else if (in >> word) {
      v = std::stod(word);
    }
    return v < 0 ? -1 : v * usage_.second;
  }
  /// Kills every process of the tree.
  void kill_all() const {
    for (const auto& d : dirs_) {
      std::ifstream procs(d / "cgroup.procs");
      for (long pid; procs >> pid;) kill(static_cast<pid_t>(pid), SIGKILL);
    }
  }
  Cgroup(const Cgroup&) = delete;
  Cgroup& operator=(const Cgroup&) = delete;
  ~Cgroup() {
    for (const auto& d : dirs_) {
      // Whatever is left (nothing, normally: the pid namespace died with its first process).
      std::ifstream procs(d / "cgroup.procs");
      for (long pid; procs >> pid;) kill(static_cast<pid_t>(pid), SIGKILL);
      for (int i = 0; i < 100 && rmdir(d.c_str()) != 0 && errno == EBUSY; ++i) usleep(10000);
    }
  }
  /// The limits that were set, in words.
  std::string summary() const { return said_; }
  /// The cgroup.procs files to write the child's pid into.
  std::vector<std::string> procs() const {
    std::vector<std::string> r;
    for (const auto& d : dirs_) r.push_back((d / "cgroup.procs").string());
    return r;
  }

 private:
  std::vector<fs::path> dirs_;
  std::string said_;
  std::pair<fs::path, double> usage_;  // the file of the CPU time used, and its unit in seconds
  void add(const fs::path& d, const std::vector<std::pair<std::string, std::string>>& settings) {
    std::error_code ec;
    const bool fresh = fs::create_directory(d, ec) && !ec;
    if (!fresh && std::find(dirs_.begin(), dirs_.end(), d) == dirs_.end()) return;
    if (fresh) dirs_.push_back(d);
    for (const auto& [file, value] : settings)
      if (write_text(d / file, value)) said_ += (said_.empty() ? "" : ", ") + file + " " + value;
  }
};

// A run's cgroup and, when the tree has a CPU limit, the thread that enforces it: it reads the
// tree's CPU time every 50 ms and kills the tree when it is over (RLIMIT_CPU counts one process
// only: a forked worker doubled the limit, issue 29). It is woken when the run ends, so that
// ending costs no wait for the next reading (25 ms a run on average, thousands of runs in the
// exercise tests).
struct TreeHold {
  std::shared_ptr<Cgroup> cg;
  std::shared_ptr<std::atomic<bool>> over = std::make_shared<std::atomic<bool>>(false);
  std::mutex m;
  std::condition_variable wake;
  bool stop = false;  // guarded by m
  std::thread watcher;
  TreeHold(std::shared_ptr<Cgroup> c, double cpu_limit) : cg(std::move(c)) {
    if (cpu_limit <= 0 || cg->cpu_seconds() < 0) return;
    watcher = std::thread([this, cpu_limit] {
      std::unique_lock<std::mutex> lock(m);
      while (!stop) {
        if (cg->cpu_seconds() > cpu_limit) {
          *over = true;
          cg->kill_all();
        }
        wake.wait_for(lock, std::chrono::milliseconds(50), [this] { return stop; });
      }
    });
  }
  TreeHold(const TreeHold&) = delete;
  TreeHold& operator=(const TreeHold&) = delete;
  ~TreeHold() {
    {
      std::lock_guard<std::mutex> lock(m);
      stop = true;
    }
    wake.notify_all();
    if (watcher.joinable()) watcher.join();
  }
};

bool running_as_root() { return geteuid() == 0; }

// The system folders of the host, read-only (merged-/usr hosts have symlinks instead).
void system_binds(std::vector<std::string>& a) {
  a.insert(a.end(), {"--ro-bind", "/usr", "/usr"});
  for (const char* d : {"/bin", "/sbin", "/lib", "/lib64", "/lib32", "/libx32"}) {
    std::error_code ec;
    if (fs::is_symlink(d, ec)) a.insert(a.end(), {"--symlink", fs::read_symlink(d, ec).string(), d});
    else if (fs::is_directory(d, ec)) a.insert(a.end(), {"--ro-bind", d, d});
  }
  for (const char* f : {"/etc/ld.so.cache", "/etc/alternatives"}) a.insert(a.end(), {"--ro-bind-try", f, f});
}

}  // namespace

unsigned sandbox_uid() {
  // As root: a uid of its own per grading process (so that RLIMIT_NPROC counts this run only).
  static const unsigned uid = running_as_root() ? 1900000000u + static_cast<unsigned>(getpid()) % 1000000u
                                                : static_cast<unsigned>(getuid());
  return uid;
}

Prepared prepare_sandboxed(const SandboxRun& r) {
  const int sfd = seccomp_fd();
  std::vector<std::string> a;
  std::shared_ptr<Cgroup> cg;
  if (running_as_root()) {
    cg = std::make_shared<Cgroup>(r.tree_memory_bytes, r.tree_processes);
    const auto procs = cg->procs();
    if (!procs.empty()) {
      a = {"/bin/sh", "-c", "while [ \"$1\" != -- ]; do echo $$ > \"$1\" || exit 125; shift; done; shift; exec \"$@\"", "t2-cgroup"};
      a.insert(a.end(), procs.begin(), procs.end());
      a.push_back("--");
    }
    const std::string u = std::to_string(sandbox_uid());
    a.insert(a.end(), {"setpriv", "--reuid", u, "--regid", u, "--clear-groups", "--inh-caps=-all",
                       "--bounding-set=-all", "--"});
  }
  a.insert(a.end(), {"bwrap", "--unshare-all", "--unshare-user", "--disable-userns", "--die-with-parent",
                     "--new-session", "--cap-drop", "ALL"});
  if (r.system) system_binds(a);
  // /dev read-only: bubblewrap's /dev is a tmpfs that no size or cgroup bounds (issue 29, break 7).
  a.insert(a.end(), {"--proc", "/proc", "--dev", "/dev", "--remount-ro", "/dev", "--size", std::to_string(r.tmp_bytes),
                     "--tmpfs", "/tmp"});
  for (const auto& d : r.masked) a.insert(a.end(), {"--size", "65536", "--tmpfs", d.string()});
  for (const auto& [host, inside] : r.read_only) a.insert(a.end(), {"--ro-bind", host.string(), inside.string()});
  for (const auto& d : r.masked) a.insert(a.end(), {"--remount-ro", d.string()});
  for (const auto& [host, inside] : r.writable) a.insert(a.end(), {"--bind", host.string(), inside.string()});
  std::vector<int> copies;
  for (const auto& [host, inside] : r.copied) {
    const int fd = ::open(host.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw GraderError("cannot open " + host.string());
    copies.push_back(fd);
    a.insert(a.end(), {"--perms", "0555", "--ro-bind-data", std::to_string(fd), inside.string()});
  }
  a.insert(a.end(), {"--chdir", r.chdir, "--seccomp", std::to_string(sfd), "--"});
  a.insert(a.end(), r.argv.begin(), r.argv.end());
  t2proc::Spec s;
  s.argv = std::move(a);
  s.env = std::vector<std::string>{"PATH=/usr/bin:/bin", "HOME=/tmp", "TMPDIR=/tmp", "LANG=C", "LC_ALL=C"};
#if defined(T2_SANITIZE)
  // An ASan build of t2 builds sandboxed programs with ASan too; LeakSanitizer stops the world
  // with ptrace at exit, which the seccomp filter forbids: no leak check inside the sandbox.
  // And crashes stay crashes: signals are left to kill the program, as in a plain build.
  s.env->push_back("ASAN_OPTIONS=detect_leaks=0:handle_segv=0:handle_sigbus=0:handle_sigfpe=0:handle_abort=0");
#endif
  s.out = r.out;
  s.err = r.err;
  s.limits = r.limits;
  if (s.limits.processes == 0) s.limits.processes = r.tree_processes;
  s.keep_fds = r.handover_fds;
  s.keep_fds.push_back(sfd);
  s.keep_fds.insert(s.keep_fds.end(), copies.begin(), copies.end());
  s.close_in_parent = s.keep_fds;
  std::shared_ptr<TreeHold> hold = cg ? std::make_shared<TreeHold>(cg, r.tree_cpu_seconds) : nullptr;
  std::string said = cg ? cg->summary() : std::string();
  if (hold && hold->watcher.joinable()) said += fmt::format(", CPU time of the tree {} s", r.tree_cpu_seconds);
  std::shared_ptr<const std::atomic<bool>> over = hold ? hold->over : std::make_shared<std::atomic<bool>>(false);
  std::function<void()> kill;
  if (cg) kill = [cg] { cg->kill_all(); };
  return {std::move(s), hold, said, over, std::move(kill)};
}

t2proc::Result run_sandboxed(const SandboxRun& r) {
  const Prepared p = prepare_sandboxed(r);
  return t2proc::run(p.spec);
}

const Sandbox& sandbox(const fs::path& probe, const std::vector<fs::path>& secrets) {
  static std::mutex m;
  static std::unique_ptr<Sandbox> done;
  std::lock_guard<std::mutex> lock(m);
  if (done) return *done;
  Sandbox s;
  SandboxRun r;
  r.argv = {"/t2/probe"};
  for (const auto& p : secrets) r.argv.push_back(p.string());
  r.copied = {{probe, "/t2/probe"}};
  r.limits.wall_seconds = 30;
  r.limits.output_bytes = 8192;
  r.tree_memory_bytes = 256u << 20;
  const Prepared prepared = prepare_sandboxed(r);
  const t2proc::Result res = t2proc::run(prepared.spec);
  s.probe_output = res.out;
  s.tree_bounded = prepared.tree_limits.find("memory") != std::string::npos;
  std::map<std::string, std::string> f;
  std::istringstream in(res.out);
  for (std::string l; std::getline(in, l);)
    if (const auto eq = l.find('='); eq != std::string::npos) f[l.substr(0, eq)] = l.substr(eq + 1);
  const std::string secrets_ok = fmt::format("{}/{}", secrets.size(), secrets.size());
  s.works = res.ok() && f["uid"] != "" && f["uid"] != "0" && f["caps"] == "none" && f["write_usr"] == "no" &&
            f["remount_usr"] == "no" && f["new_userns"] == "no" && f["network_interfaces"] == "0" &&
            f["io_uring"] == "no" && f["netlink"] == "no" && f["host_paths"] == "0" && f["write_dev"] == "no" &&
            f["secrets_unreadable"] == secrets_ok;
  if (!res.ok()) {
    s.mode = "bubblewrap does not work here: " + (res.error.empty() ? res.err.substr(0, 300) : res.error);
    s.description = "no sandbox (" + s.mode + "): student code is not run";
  } else {
    s.mode = fmt::format("bubblewrap as uid {}{}", f["uid"], running_as_root() ? " (setpriv from root)" : "");
    s.description = fmt::format(
        "{}; probed inside: capabilities {}, seccomp {}, /usr writable {}, remount {}, new user "
        "namespace {}, network interfaces {}, io_uring {}, netlink {}, host paths in mountinfo {}, /dev writable {}, "
        "hidden files unreadable {}, /tmp tmpfs {} MB, process limit {}",
        s.mode, f["caps"], f["seccomp"], f["write_usr"], f["remount_usr"], f["new_userns"],
        f["network_interfaces"], f["io_uring"], f["netlink"], f["host_paths"], f["write_dev"], f["secrets_unreadable"],
        f["tmp_mb"], f["nproc"]);
    s.description += prepared.tree_limits.empty() ? "; no cgroup (per-process limits only)"
                                                  : "; a cgroup for the whole tree of each run (the probe run's: " + prepared.tree_limits + ")";
    if (!s.works) s.description = "UNSAFE sandbox, student code is not run: " + s.description;
  }
  done = std::make_unique<Sandbox>(s);
  return *done;
}

}  // namespace t2grader
