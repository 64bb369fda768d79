// The one process module: see process.hpp.
#include "process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <thread>

extern char** environ;

namespace t2proc {

namespace {

using Clock = std::chrono::steady_clock;

// An owned file descriptor.
struct Fd {
  int fd = -1;
  Fd() = default;
  explicit Fd(int f) : fd(f) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() { reset(); }
  void reset(int f = -1) {
    if (fd >= 0) ::close(fd);
    fd = f;
  }
};

bool make_pipe(Fd& r, Fd& w) {
  int p[2];
  if (pipe2(p, O_CLOEXEC) != 0) return false;
  r.reset(p[0]);
  w.reset(p[1]);
  return true;
}

// The program argv[0] names: itself when it has a '/', else the first executable file of that
// name in the PATH of the child's environment.
std::string find_program(const std::string& name, const std::optional<std::vector<std::string>>& env) {
  if (name.find('/') != std::string::npos) return name;
  std::string path = "/usr/local/bin:/usr/bin:/bin";
  if (env) {
    for (const auto& e : *env)
      if (e.rfind("PATH=", 0) == 0) path = e.substr(5);
  } else if (const char* p = std::getenv("PATH")) {
    path = p;
  }
  size_t start = 0;
  for (;;) {
    const size_t colon = path.find(':', start);
    std::string dir = path.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
    if (dir.empty()) dir = ".";
    const std::string cand = dir + "/" + name;
    struct stat st{};
    if (::stat(cand.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(cand.c_str(), X_OK) == 0) return cand;
    if (colon == std::string::npos) return {};
    start = colon + 1;
  }
}

void set_limit(int what, rlim_t soft, rlim_t hard) {
  const rlimit r{soft, hard};
  ::setrlimit(what, &r);
}

// Closes every fd from `from` up that is not in `keep` (sorted). Async-signal-safe.
void close_others(int from, const int* keep, size_t nkeep) {
  unsigned lo = static_cast<unsigned>(from);
  for (size_t i = 0; i <= nkeep; ++i) {
    const unsigned hi = i < nkeep ? static_cast<unsigned>(keep[i]) : ~0u;
    if (i < nkeep && hi < lo) continue;
    if (hi > lo) {
      const unsigned last = i < nkeep ? hi - 1 : ~0u;
      if (::syscall(SYS_close_range, lo, last, 0) != 0) {
        const unsigned cap = std::min<unsigned>(last, 65535);
        for (unsigned fd = lo; fd <= cap; ++fd) ::close(static_cast<int>(fd));
      }
    }
    if (i < nkeep) lo = hi + 1;
  }
}

// Appends to `into`, keeping at most `cap` bytes (0: all).
void keep_bounded(std::string& into, const char* data, size_t n, size_t cap, bool& truncated) {
  if (cap == 0) {
    into.append(data, n);
    return;
  }
  const size_t room = into.size() < cap ? cap - into.size() : 0;
  into.append(data, std::min(room, n));
  if (n > room) truncated = true;
}

double seconds(const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6; }

// Everything the child needs, prepared before fork (after fork only async-signal-safe calls).
struct Prepared {
  std::string program;
  std::vector<std::string> argv_s, env_s;
  std::vector<char*> argv, envp;
  std::vector<int> keep;  // sorted, includes the exec-error pipe
};

}  // namespace

namespace {

// Closes the fds a spec hands over to its child, once (on every path out of the start).
struct Handover {
  const std::vector<int>& fds;
  bool done = false;
  void close_all() {
    if (done) return;
    done = true;
    for (int fd : fds) ::close(fd);
  }
  ~Handover() { close_all(); }
};

Result run_child(const Spec& spec, Handover& handover);

}  // namespace

Result run(const Spec& spec) {
  Handover handover{spec.close_in_parent};
  return run_child(spec, handover);
}

namespace {

Result run_child(const Spec& spec, Handover& handover) {
  Result r;
  const auto start = Clock::now();
  if (spec.argv.empty()) {
    r.error = "nothing to run (empty argv)";
    return r;
  }
  Prepared p;
  p.program = find_program(spec.argv[0], spec.env);
  if (p.program.empty()) {
    r.error = "cannot run " + spec.argv[0] + ": not found in PATH";
    return r;
  }
  p.argv_s = spec.argv;
  for (auto& s : p.argv_s) p.argv.push_back(s.data());
  p.argv.push_back(nullptr);
  if (spec.env) {
    p.env_s = *spec.env;
    for (auto& s : p.env_s) p.envp.push_back(s.data());
    p.envp.push_back(nullptr);
  }
  char* const* envp = spec.env ? p.envp.data() : environ;

  Fd in_r, in_w, out_r, out_w, err_r, err_w, exec_r, exec_w, null_in, null_out, err_file;
  const bool feed = !spec.inherit_stdin && !spec.stdin_data.empty();
  if (!make_pipe(exec_r, exec_w) || (feed && !make_pipe(in_r, in_w)) ||
      (spec.out == Stream::capture && !make_pipe(out_r, out_w)) ||
      (spec.err_file.empty() && spec.err == Stream::capture && !make_pipe(err_r, err_w))) {
    r.error = std::string("cannot create a pipe: ") + std::strerror(errno);
    return r;
  }
  null_in.reset(::open("/dev/null", O_RDONLY | O_CLOEXEC));
  null_out.reset(::open("/dev/null", O_WRONLY | O_CLOEXEC));
  if (!spec.err_file.empty()) {
    err_file.reset(::open(spec.err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
    if (err_file.fd < 0) {
      r.error = "cannot write " + spec.err_file.string() + ": " + std::strerror(errno);
      return r;
    }
  }
  const int child_in = spec.inherit_stdin ? 0 : feed ? in_r.fd : null_in.fd;
  const int child_out = spec.out == Stream::capture ? out_w.fd : spec.out == Stream::discard ? null_out.fd : 1;
  const int child_err = !spec.err_file.empty() ? err_file.fd
                        : spec.err == Stream::capture ? err_w.fd
                        : spec.err == Stream::discard ? null_out.fd : 2;
  p.keep = spec.keep_fds;
  p.keep.push_back(exec_w.fd);
  std::sort(p.keep.begin(), p.keep.end());
  p.keep.erase(std::unique(p.keep.begin(), p.keep.end()), p.keep.end());
  const Limits& lim = spec.limits;
  const std::string cwd = spec.cwd.string();

  // SIGPIPE stays blocked in this thread while it feeds stdin (a child that stops reading must
  // not kill the caller); the child gets the caller's mask back.
  sigset_t pipe_set, old_mask;
  sigemptyset(&pipe_set);
  sigaddset(&pipe_set, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_set, &old_mask);

  const pid_t pid = ::fork();
  if (pid == 0) {
    if (!spec.inherit_stdin) ::setpgid(0, 0);
    for (int s = 1; s < NSIG; ++s)
      if (s != SIGKILL && s != SIGSTOP) ::signal(s, SIG_DFL);
    ::sigprocmask(SIG_SETMASK, &old_mask, nullptr);
    // Move the three streams to fds above every fd we keep, then down to 0, 1, 2.
    int fds[3] = {child_in, child_out, child_err};
    const int base = std::max(3, p.keep.empty() ? 3 : p.keep.back() + 1);
    for (int i = 0; i < 3; ++i) fds[i] = ::fcntl(fds[i], F_DUPFD_CLOEXEC, base);
    for (int i = 0; i < 3; ++i)
      if (fds[i] < 0 || ::dup2(fds[i], i) < 0) _exit(127);
    for (int fd : spec.keep_fds) ::fcntl(fd, F_SETFD, 0);
    close_others(3, p.keep.data(), p.keep.size());
    if (!cwd.empty() && ::chdir(cwd.c_str()) != 0) {
      const int e = errno;
      ssize_t n = ::write(exec_w.fd, &e, sizeof e);
      (void)n;
      _exit(127);
    }
    if (lim.cpu_seconds > 0) {
      const auto s = static_cast<rlim_t>(std::ceil(lim.cpu_seconds));
      set_limit(RLIMIT_CPU, s, s + 1);
    }
    if (lim.memory_bytes > 0) set_limit(RLIMIT_AS, lim.memory_bytes, lim.memory_bytes);
    if (lim.file_bytes > 0) set_limit(RLIMIT_FSIZE, lim.file_bytes, lim.file_bytes);
    if (lim.processes > 0) set_limit(RLIMIT_NPROC, static_cast<rlim_t>(lim.processes), static_cast<rlim_t>(lim.processes));
    ::execve(p.program.c_str(), p.argv.data(), envp);
    const int e = errno;
    ssize_t n = ::write(exec_w.fd, &e, sizeof e);
    (void)n;
    _exit(127);
  }
  handover.close_all();
  if (pid < 0) {
    pthread_sigmask(SIG_SETMASK, &old_mask, nullptr);
    r.error = std::string("cannot fork: ") + std::strerror(errno);
    return r;
  }
  if (!spec.inherit_stdin) ::setpgid(pid, pid);  // also here: no race with a kill of the group
  exec_w.reset();
  in_r.reset();
  out_w.reset();
  err_w.reset();
  int exec_errno = 0;
  const ssize_t got = ::read(exec_r.fd, &exec_errno, sizeof exec_errno);  // EOF once exec succeeds
  if (got == static_cast<ssize_t>(sizeof exec_errno)) {
    ::waitpid(pid, nullptr, 0);
    pthread_sigmask(SIG_SETMASK, &old_mask, nullptr);
    r.error = "cannot run " + spec.argv[0] + ": " + std::strerror(exec_errno);
    return r;
  }
  r.started = true;
  if (in_w.fd >= 0) ::fcntl(in_w.fd, F_SETFL, O_NONBLOCK);
  size_t fed = 0;
  const bool has_deadline = lim.wall_seconds > 0;
  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(lim.wall_seconds));
  bool exited = false;
  Clock::time_point drain_until{};
  char buf[65536];
  for (;;) {
    // The child has ended (not yet reaped, so its pid cannot be reused): end its group too.
    if (!exited) {
      siginfo_t si{};
      if (::waitid(P_PID, static_cast<id_t>(pid), &si, WEXITED | WNOHANG | WNOWAIT) == 0 && si.si_pid == pid) {
        exited = true;
        ::kill(-pid, SIGKILL);
        drain_until = Clock::now() + std::chrono::seconds(2);
        in_w.reset();
      } else if (has_deadline && Clock::now() >= deadline) {
        r.timed_out = true;
        ::kill(-pid, SIGKILL);
        ::kill(pid, SIGKILL);
        continue;
      }
    }
    if (exited && (out_r.fd < 0 && err_r.fd < 0)) break;
    if (exited && Clock::now() >= drain_until) break;  // a escaped descendant still holds a pipe
    pollfd fds[3];
    int nf = 0;
    if (out_r.fd >= 0) fds[nf++] = {out_r.fd, POLLIN, 0};
    if (err_r.fd >= 0) fds[nf++] = {err_r.fd, POLLIN, 0};
    if (in_w.fd >= 0) fds[nf++] = {in_w.fd, POLLOUT, 0};
    ::poll(fds, static_cast<nfds_t>(nf), 10);
    for (int i = 0; i < nf; ++i) {
      if (!fds[i].revents) continue;
      if (fds[i].fd == in_w.fd) {
        const ssize_t n = ::write(in_w.fd, spec.stdin_data.data() + fed, spec.stdin_data.size() - fed);
        if (n > 0) fed += static_cast<size_t>(n);
        if ((n < 0 && errno != EAGAIN && errno != EINTR) || fed == spec.stdin_data.size()) in_w.reset();
        continue;
      }
      const bool is_out = fds[i].fd == out_r.fd;
      const ssize_t n = ::read(fds[i].fd, buf, sizeof buf);
      if (n > 0) {
        keep_bounded(is_out ? r.out : r.err, buf, static_cast<size_t>(n), lim.output_bytes,
                     is_out ? r.out_truncated : r.err_truncated);
      } else if (n == 0 || (errno != EAGAIN && errno != EINTR)) {
        (is_out ? out_r : err_r).reset();
      }
    }
  }
  int status = 0;
  rusage ru{};
  while (::wait4(pid, &status, 0, &ru) < 0 && errno == EINTR) {
  }
  in_w.reset();
  // A SIGPIPE raised by feeding a child that stopped reading is consumed, not delivered.
  const timespec zero{0, 0};
  while (sigtimedwait(&pipe_set, nullptr, &zero) > 0) {
  }
  pthread_sigmask(SIG_SETMASK, &old_mask, nullptr);
  if (WIFSIGNALED(status)) {
    r.signal = WTERMSIG(status);
  } else if (WIFEXITED(status)) {
    r.exit_code = WEXITSTATUS(status);
  }
  r.cpu_seconds = seconds(ru.ru_utime) + seconds(ru.ru_stime);
  r.peak_rss_kb = ru.ru_maxrss;
  r.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return r;
}

}  // namespace

std::vector<Result> run_all(const std::vector<Spec>& specs, int jobs) {
  std::vector<Result> results(specs.size());
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i; (i = next++) < specs.size();) results[i] = run(specs[i]);
  };
  const size_t n = std::min<size_t>(specs.size(), static_cast<size_t>(std::max(1, jobs)));
  std::vector<std::thread> threads;
  for (size_t i = 1; i < n; ++i) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  return results;
}

RemoveWhenGone::RemoveWhenGone(const std::filesystem::path& folder) {
  int p[2];
  if (pipe2(p, O_CLOEXEC) != 0) return;
  // Prepared before fork: after it the child makes async-signal-safe calls only.
  const std::string script = "sleep 1; exec rm -rf -- \"$1\"", path = folder.string();
  const char* argv[] = {"/bin/sh", "-c", script.c_str(), "t2-cleanup", path.c_str(), nullptr};
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setsid();
    for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE}) ::signal(sig, SIG_IGN);
    const int keep[] = {p[0]};
    close_others(0, keep, 1);
    char c;
    ssize_t n;
    while ((n = ::read(p[0], &c, 1)) < 0 && errno == EINTR) {
    }
    if (n == 0) ::execv(argv[0], const_cast<char* const*>(argv));  // the caller is gone
    ::_exit(0);
  }
  ::close(p[0]);
  if (pid < 0) {
    ::close(p[1]);
    return;
  }
  fd_ = p[1];
  pid_ = pid;
}

RemoveWhenGone::~RemoveWhenGone() {
  if (fd_ < 0) return;
  ::kill(pid_, SIGKILL);  // our child, not yet waited for: the pid is still its own
  ::close(fd_);
  while (::waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
  }
}

}  // namespace t2proc
