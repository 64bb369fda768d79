// The grader: see grader_core.hpp. POSIX only (fork, rlimits, pipes); bubblewrap when it works.
#include "grader_core.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include <fmt/format.h>

#include "command.hpp"
#include "t2/error.hpp"

#ifndef T2_SOURCE_DIR
#define T2_SOURCE_DIR "."
#endif
#ifndef T2_BINARY_DIR
#define T2_BINARY_DIR "./build"
#endif

namespace t2grader {

namespace {

using Clock = std::chrono::steady_clock;

std::string read_text(const fs::path& p, size_t cap = std::string::npos) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return {};
  std::string s;
  char buf[65536];
  while (in && s.size() < cap) {
    in.read(buf, sizeof buf);
    s.append(buf, static_cast<size_t>(in.gcount()));
  }
  if (s.size() > cap) s.resize(cap);
  return s;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::uint64_t fnv1a(const std::string& s, std::uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::string random_secret() {
  unsigned char b[16] = {};
  std::ifstream r("/dev/urandom", std::ios::binary);
  r.read(reinterpret_cast<char*>(b), sizeof b);
  if (!r) {
    // Not expected on Linux; fall back to clock and address entropy.
    const auto t = static_cast<std::uint64_t>(Clock::now().time_since_epoch().count());
    std::uint64_t h = fnv1a(std::to_string(t) + std::to_string(reinterpret_cast<std::uintptr_t>(&r)));
    std::memcpy(b, &h, 8);
    h = fnv1a(std::to_string(h), t);
    std::memcpy(b + 8, &h, 8);
  }
  std::string s;
  for (unsigned char c : b) s += fmt::format("{:02x}", c);
  return s;
}

fs::path lib_include_dir() { return fs::path(T2_SOURCE_DIR) / "lib" / "include"; }
fs::path lib_archive() { return fs::path(T2_BINARY_DIR) / "lib" / "libt2.a"; }

bool sanitized_tool() {
#if defined(__SANITIZE_ADDRESS__)
  return true;
#else
  return false;
#endif
}

// ---- running a process with limits ---------------------------------------------------------

struct Limits {
  int cpu_s = 10;          // RLIMIT_CPU (soft; hard = soft + 1)
  long mem_mb = 512;       // RLIMIT_AS; 0 = none
  long fsize = 1 << 20;    // RLIMIT_FSIZE: caps captured output and every file written
  double wall_s = 22;      // wall clock, then SIGKILL of the whole process group
};

struct Proc {
  bool started = false;
  bool via_bwrap = false;  // ran inside bubblewrap
  bool timed_out = false;
  int status = 0;          // from waitpid
  std::string output;      // stdout + stderr, capped
  std::string record;      // what the test process wrote on fd 4
};

void set_limit(int what, rlim_t v) {
  rlimit r{v, v};
  if (what == RLIMIT_CPU) r.rlim_max = v + 1;
  setrlimit(what, &r);
}

std::vector<std::string> sandbox_prefix(const fs::path& work, const std::vector<fs::path>& ro) {
  std::vector<std::string> a = {"bwrap", "--unshare-all", "--die-with-parent", "--new-session",
                                "--ro-bind", "/usr", "/usr"};
  for (const char* d : {"/bin", "/sbin", "/lib", "/lib64", "/lib32"}) {
    std::error_code ec;
    if (fs::is_symlink(d, ec)) {
      a.insert(a.end(), {"--symlink", fs::read_symlink(d, ec).string(), d});
    } else if (fs::is_directory(d, ec)) {
      a.insert(a.end(), {"--ro-bind", d, d});
    }
  }
  a.insert(a.end(), {"--ro-bind-try", "/etc/ld.so.cache", "/etc/ld.so.cache", "--dev", "/dev",
                     "--proc", "/proc", "--tmpfs", "/tmp"});
  for (const auto& p : ro) a.insert(a.end(), {"--ro-bind", p.string(), p.string()});
  a.insert(a.end(), {"--bind", work.string(), work.string(), "--chdir", work.string(), "--"});
  return a;
}

// Runs argv (inside bubblewrap when `sandboxed`) in `work`, with limits; the secret (if any) is
// readable on fd 3, and fd 4 collects the record.
Proc run_limited(std::vector<std::string> argv, const fs::path& work, const Limits& lim,
                 bool sandboxed, const std::vector<fs::path>& ro_binds, const std::string& secret,
                 const std::string& out_name) {
  Proc pr;
  pr.via_bwrap = sandboxed;
  if (sandboxed) {
    auto pre = sandbox_prefix(work, ro_binds);
    argv.insert(argv.begin(), pre.begin(), pre.end());
  }
  int sec[2], rec[2];
  if (pipe(sec) != 0) return pr;
  if (pipe(rec) != 0) {
    close(sec[0]);
    close(sec[1]);
    return pr;
  }
  // The secret is tiny: it fits in the pipe buffer, so writing before fork cannot block.
  if (!secret.empty()) {
    ssize_t n = write(sec[1], secret.data(), secret.size());
    (void)n;
  }
  close(sec[1]);
  const fs::path out_path = work / out_name;
  std::vector<std::string> env = {"PATH=/usr/bin:/bin", "HOME=" + work.string(), "LANG=C",
                                  "LC_ALL=C", "TMPDIR=/tmp", "GTEST_COLOR=no"};
  // Children of a sanitized tool are linked with the sanitizers (libt2.a needs them): let
  // crashes end in their signal, as in an ordinary build, so that reports name them alike.
  if (sanitized_tool())
    env.push_back("ASAN_OPTIONS=detect_leaks=0:handle_segv=0:handle_sigbus=0:handle_sigfpe=0:handle_sigill=0:"
                  "handle_abort=0:allocator_may_return_null=1:max_allocation_size_mb=" + std::to_string(lim.mem_mb > 0 ? lim.mem_mb : 4096));
  std::vector<char*> cargv, cenv;
  for (auto& s : argv) cargv.push_back(s.data());
  cargv.push_back(nullptr);
  for (auto& s : env) cenv.push_back(s.data());
  cenv.push_back(nullptr);

  const pid_t pid = fork();
  if (pid < 0) {
    close(sec[0]);
    close(rec[0]);
    close(rec[1]);
    return pr;
  }
  if (pid == 0) {
    setpgid(0, 0);
    const int out = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int nul = open("/dev/null", O_RDONLY);
    if (out < 0 || nul < 0) _exit(125);
    dup2(nul, 0);
    dup2(out, 1);
    dup2(out, 2);
    // Move the pipes to fds 3 and 4 without clobbering each other.
    int s = fcntl(sec[0], F_DUPFD, 10), r = fcntl(rec[1], F_DUPFD, 10);
    dup2(s, 3);
    dup2(r, 4);
    for (int fd = 5; fd < 1024; ++fd) close(fd);
    if (chdir(work.c_str()) != 0) _exit(125);
    set_limit(RLIMIT_CPU, static_cast<rlim_t>(lim.cpu_s));
    if (lim.mem_mb > 0 && !sanitized_tool()) set_limit(RLIMIT_AS, static_cast<rlim_t>(lim.mem_mb) << 20);
    set_limit(RLIMIT_FSIZE, static_cast<rlim_t>(lim.fsize));
    set_limit(RLIMIT_CORE, 0);
    set_limit(RLIMIT_NPROC, 512);  // not enforced for root: the pid namespace and group kill are
    signal(SIGPIPE, SIG_DFL);
    execve(argv[0].find('/') == std::string::npos ? ("/usr/bin/" + argv[0]).c_str() : argv[0].c_str(),
           cargv.data(), cenv.data());
    _exit(126);
  }
  pr.started = true;
  setpgid(pid, pid);
  close(sec[0]);
  close(rec[1]);
  fcntl(rec[0], F_SETFL, O_NONBLOCK);
  const auto deadline = Clock::now() + std::chrono::duration<double>(lim.wall_s);
  char buf[4096];
  for (;;) {
    for (;;) {  // drain the record pipe so that the child never blocks on it
      const ssize_t n = read(rec[0], buf, sizeof buf);
      if (n <= 0) break;
      if (pr.record.size() < 65536) pr.record.append(buf, static_cast<size_t>(n));
    }
    int st = 0;
    const pid_t w = waitpid(pid, &st, WNOHANG);
    if (w == pid) {
      pr.status = st;
      break;
    }
    if (Clock::now() > deadline) {
      pr.timed_out = true;
      kill(-pid, SIGKILL);
      kill(pid, SIGKILL);
      waitpid(pid, &st, 0);
      pr.status = st;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(-pid, SIGKILL);  // whatever the test left behind in its process group
  for (;;) {
    const ssize_t n = read(rec[0], buf, sizeof buf);
    if (n <= 0) break;
    if (pr.record.size() < 65536) pr.record.append(buf, static_cast<size_t>(n));
  }
  close(rec[0]);
  pr.output = read_text(out_path, 1 << 16);
  return pr;
}

// Exit code and signal, seen through bubblewrap (which exits 128 + signal for a killed child).
std::pair<int, int> code_and_signal(const Proc& p) {
  if (WIFSIGNALED(p.status)) return {-1, WTERMSIG(p.status)};
  const int c = WIFEXITED(p.status) ? WEXITSTATUS(p.status) : -1;
  if (p.via_bwrap && c > 128 && c < 128 + 65) return {c, c - 128};
  return {c, 0};
}

std::string signal_words(int sig, const Limits& lim) {
  switch (sig) {
    case SIGSEGV:
      return "crashed with a segmentation fault (SIGSEGV): a bad pointer or index, or a stack "
             "overflow from runaway recursion";
    case SIGBUS: return "crashed with a bus error (SIGBUS): a bad pointer";
    case SIGABRT:
      return "aborted (SIGABRT): an assert failed, std::terminate was called (an exception "
             "escaped a noexcept function?), or memory ran out";
    case SIGFPE: return "crashed with an arithmetic error (SIGFPE): an integer division by zero?";
    case SIGILL: return "crashed on an illegal instruction (SIGILL)";
    case SIGXCPU:
      return fmt::format("used more than {} s of CPU time and was stopped: an infinite loop?", lim.cpu_s);
    case SIGXFSZ:
      return fmt::format("wrote more than {} KB of output and was stopped: printing in a loop?",
                         lim.fsize / 1024);
    case SIGKILL:
      return fmt::format("was killed (SIGKILL): it exceeded the CPU limit of {} s or memory", lim.cpu_s);
    default: return fmt::format("was killed by signal {} ({})", sig, strsignal(sig));
  }
}

// ---- building ------------------------------------------------------------------------------

std::string compiler_version() {
  static const std::string v = [] {
    std::string s;
    if (FILE* f = popen("g++ --version 2>/dev/null", "r")) {
      char b[256];
      while (fgets(b, sizeof b, f)) s += b;
      pclose(f);
    }
    return s;
  }();
  return v;
}

const std::vector<std::string>& cxxflags() {
  static const std::vector<std::string> f = {"-std=c++20", "-O1", "-g0", "-w"};
  return f;
}

std::uint64_t library_fingerprint() {
  std::uint64_t h = fnv1a(compiler_version());
  std::error_code ec;
  std::vector<fs::path> hs;
  for (const auto& e : fs::directory_iterator(lib_include_dir() / "t2", ec)) hs.push_back(e.path());
  std::sort(hs.begin(), hs.end());
  for (const auto& p : hs) h = fnv1a(p.filename().string() + read_text(p), h);
  return h;
}

fs::path cache_dir(const fs::path& work) {
  fs::path c = fs::path(T2_BINARY_DIR) / "grader-cache";
  std::error_code ec;
  fs::create_directories(c, ec);
  if (!ec && access(c.c_str(), W_OK) == 0) return c;
  return work;
}

Limits compile_limits() {
  Limits l;
  l.cpu_s = 120;
  l.mem_mb = 4096;
  l.fsize = 256L << 20;
  l.wall_s = 240;
  return l;
}

std::string shorten_compiler_output(const std::string& out, const fs::path& work) {
  std::string s = out;
  const std::string w = work.string() + "/";
  for (size_t p; (p = s.find(w)) != std::string::npos;) s.erase(p, w.size());
  std::istringstream in(s);
  std::string line, errors, all;
  int n = 0, ne = 0;
  while (std::getline(in, line)) {
    if (n++ < 25) all += line + "\n";
    if (line.find("error") != std::string::npos && ne++ < 12) errors += line + "\n";
  }
  std::string r = errors.empty() ? all : errors;
  if (r.size() > 3000) r = r.substr(0, 3000) + "...\n";
  return r;
}

// Compiles a trusted source (tests, harness, stub) once per content; returns the object.
fs::path trusted_object(const fs::path& src, const Exercise* ex, const fs::path& work,
                        std::string& error) {
  std::string key = read_text(src) + "\n#flags " + fmt::format("{}", fmt::join(cxxflags(), " "));
  if (ex) key += read_text(ex->dir / ex->header);
  const std::uint64_t h = fnv1a(key, library_fingerprint());
  const fs::path obj = cache_dir(work) / fmt::format("{}-{:016x}.o", src.stem().string(), h);
  if (fs::exists(obj)) return obj;
  // Compiled next to its final name, so that the rename is atomic (same file system).
  const fs::path tmp = obj.parent_path() / fmt::format("{}-{:016x}.o.tmp{}-{}", src.stem().string(), h, getpid(), random_secret().substr(0, 8));
  std::vector<std::string> a = {"g++"};
  a.insert(a.end(), cxxflags().begin(), cxxflags().end());
  a.insert(a.end(), {"-I", lib_include_dir().string()});
  if (ex) a.insert(a.end(), {"-I", ex->dir.string()});
  a.insert(a.end(), {"-c", src.string(), "-o", tmp.string()});
  const Proc p = run_limited(a, work, compile_limits(), false, {}, "", "trusted-compile.txt");
  if (!p.started || !WIFEXITED(p.status) || WEXITSTATUS(p.status) != 0) {
    error = fmt::format("internal error: {} does not compile:\n{}", src.string(), p.output.substr(0, 4000));
    return {};
  }
  std::error_code ec;
  fs::rename(tmp, obj, ec);
  if (ec) return tmp;
  return obj;
}

bool link(const std::vector<fs::path>& objs, const fs::path& out, const fs::path& work,
          std::string& output) {
  std::vector<std::string> a = {"g++"};
  if (sanitized_tool()) a.push_back("-fsanitize=address,undefined");
  for (const auto& o : objs) a.push_back(o.string());
  a.push_back(lib_archive().string());
  for (const char* l : {"-lgtest", "-lgmpxx", "-lgmp", "-lfmt", "-lcairo", "-lpthread"}) a.push_back(l);
  a.insert(a.end(), {"-o", out.string()});
  const Proc p = run_limited(a, work, compile_limits(), false, {}, "", "link.txt");
  output = p.output;
  return p.started && WIFEXITED(p.status) && WEXITSTATUS(p.status) == 0;
}

struct TempDir {
  fs::path path;
  TempDir() {
    std::string t = (fs::temp_directory_path() / "t2grade-XXXXXX").string();
    if (!mkdtemp(t.data())) throw std::runtime_error("cannot create a temporary directory");
    path = t;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

// Lists the tests of a trusted binary (tests + stub).
std::vector<std::string> list_tests(const fs::path& bin, const fs::path& work) {
  const std::string secret = random_secret();
  Limits l;
  l.cpu_s = 30;
  l.wall_s = 60;
  const Proc p = run_limited({bin.string(), "--t2-list"}, work, l, false, {}, secret, "list.txt");
  std::vector<std::string> names;
  std::istringstream in(p.record);
  std::string line;
  if (!std::getline(in, line) || line != secret) return names;
  if (!std::getline(in, line) || line != "LIST") return names;
  while (std::getline(in, line))
    if (!line.empty()) names.push_back(line);
  return names;
}

}  // namespace

// ---- exercises -----------------------------------------------------------------------------

double Exercise::points_of(const std::string& test) const {
  const auto it = points.find(test);
  return it == points.end() ? 1.0 : it->second;
}

fs::path exercises_root(const std::optional<std::string>& override_dir) {
  if (override_dir) return *override_dir;
  if (const char* e = std::getenv("T2_EXERCISES_DIR"); e && *e) return e;
  return fs::path(T2_SOURCE_DIR) / "exercises";
}

Exercise read_exercise(const fs::path& dir) {
  Exercise ex;
  ex.dir = fs::absolute(dir).lexically_normal();
  if (ex.dir.filename().empty()) ex.dir = ex.dir.parent_path();
  ex.id = ex.dir.filename().string();
  const fs::path m = ex.dir / "exercise.txt";
  std::ifstream in(m);
  if (!in) throw t2::BadInput(fmt::format("{}: cannot read the manifest", m.string()));
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    line = trim(line);
    if (line.empty() || line[0] == '#') continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos)
      throw t2::BadInput(fmt::format("{}:{}: expected 'key: value'", m.string(), n));
    const std::string k = trim(line.substr(0, colon)), v = trim(line.substr(colon + 1));
    auto number = [&](const std::string& s) {
      char* end = nullptr;
      const double d = std::strtod(s.c_str(), &end);
      if (s.empty() || *end || !(d > 0) || d > 1e6)
        throw t2::BadInput(fmt::format("{}:{}: '{}' is not a positive number", m.string(), n, s));
      return d;
    };
    if (k == "title") ex.title = v;
    else if (k == "chapter") ex.chapter = v;
    else if (k == "header") ex.header = v;
    else if (k == "source") ex.source = v;
    else if (k == "time_limit") ex.time_limit = static_cast<int>(number(v));
    else if (k == "memory_mb") ex.memory_mb = static_cast<int>(number(v));
    else if (k == "points") {
      const auto sp = v.find_last_of(" \t");
      if (sp == std::string::npos)
        throw t2::BadInput(fmt::format("{}:{}: expected 'points: Suite.Test N'", m.string(), n));
      ex.points[trim(v.substr(0, sp))] = number(trim(v.substr(sp + 1)));
    } else {
      throw t2::BadInput(fmt::format("{}:{}: unknown key '{}'", m.string(), n, k));
    }
  }
  for (auto [key, val] : {std::pair{"title", &ex.title}, {"header", &ex.header}, {"source", &ex.source}})
    if (val->empty()) throw t2::BadInput(fmt::format("{}: missing '{}:'", m.string(), key));
  return ex;
}

std::vector<Exercise> all_exercises(const fs::path& root) {
  std::vector<Exercise> r;
  std::error_code ec;
  std::vector<fs::path> dirs;
  for (const auto& e : fs::directory_iterator(root, ec))
    if (e.is_directory() && fs::exists(e.path() / "exercise.txt") && e.path().filename().string()[0] != '_')
      dirs.push_back(e.path());
  std::sort(dirs.begin(), dirs.end());
  for (const auto& d : dirs) r.push_back(read_exercise(d));
  return r;
}

Exercise find_exercise(const fs::path& root, const std::string& name) {
  std::error_code ec;
  if (name.find('/') != std::string::npos && fs::exists(fs::path(name) / "exercise.txt", ec))
    return read_exercise(name);
  for (auto& e : all_exercises(root))
    if (e.id == name || e.id.rfind(name + "-", 0) == 0) return e;
  std::string known;
  for (auto& e : all_exercises(root)) known += " " + e.id;
  throw t2cli::UsageError(fmt::format("no exercise '{}' in {} (there are:{})", name, root.string(),
                                      known.empty() ? " none" : known));
}

const Sandbox& sandbox() {
  static const Sandbox s = [] {
    Sandbox r;
    const char* off = std::getenv("T2_GRADER_NO_BWRAP");
    const bool have = fs::exists("/usr/bin/bwrap");
    if (off && std::string(off) == "1") {
      r.description = "rlimits only (bubblewrap turned off by T2_GRADER_NO_BWRAP=1): student code "
                      "can use the network and write where this user can";
      return r;
    }
    if (!have) {
      r.description = "rlimits only (bubblewrap is not installed): student code can use the "
                      "network and write where this user can";
      return r;
    }
    TempDir t;
    Limits l;
    l.wall_s = 20;
    const Proc p = run_limited({"/bin/sh", "-c", "echo x > probe && exit 0"}, t.path, l, true, {}, "", "probe-out.txt");
    r.bwrap = p.started && WIFEXITED(p.status) && WEXITSTATUS(p.status) == 0 && fs::exists(t.path / "probe");
    r.description = r.bwrap
        ? "bubblewrap: no network, new pid/ipc/uts namespaces, read-only /usr, only a temporary "
          "directory writable, plus CPU, memory, output-size and wall-clock limits"
        : "rlimits only (bubblewrap does not work here: " + trim(p.output).substr(0, 200) +
              "): student code can use the network and write where this user can";
    return r;
  }();
  return s;
}

// ---- running an exercise ---------------------------------------------------------------------

double Report::score() const {
  double s = 0;
  for (const auto& t : tests) s += t.passed ? t.max_score : 0;
  return s;
}
double Report::max_score() const {
  double s = 0;
  for (const auto& t : tests) s += t.max_score;
  return s;
}

Report run_exercise(const Exercise& ex, const fs::path& submission_dir, const RunOptions& opt) {
  Report rep;
  rep.exercise = ex;
  const auto start = Clock::now();
  auto remaining = [&] {
    return opt.overall_limit - std::chrono::duration<double>(Clock::now() - start).count();
  };
  auto say = [&](const std::string& s) {
    if (opt.verbose) fmt::print(stderr, "{}\n", s);
  };
  if (!fs::exists(lib_archive()))
    throw std::runtime_error(fmt::format("the library {} is not built: run ./build.sh first",
                                         lib_archive().string()));
  if (opt.include_hidden && !fs::exists(ex.hidden_tests()))
    throw std::runtime_error(fmt::format("{} has no hidden tests (is this a student release?): grading needs the "
                                         "instructor's tree; `t2 check {}` runs the public tests",
                                         ex.id, ex.id.substr(0, ex.id.find('-'))));
  TempDir tmp;
  const fs::path work = tmp.path;
  std::string err;

  // Trusted parts, compiled once per content and cached.
  say("building the tests (cached after the first time)");
  const fs::path harness = trusted_object(ex.dir.parent_path() / "harness" / "harness_main.cpp", nullptr, work, err);
  const fs::path pub = harness.empty() ? fs::path() : trusted_object(ex.public_tests(), &ex, work, err);
  fs::path hid;
  if (opt.include_hidden && !pub.empty()) hid = trusted_object(ex.hidden_tests(), &ex, work, err);
  const fs::path stub = (pub.empty() || (opt.include_hidden && hid.empty())) ? fs::path()
                                                                            : trusted_object(ex.stub(), &ex, work, err);
  if (stub.empty()) throw std::runtime_error(err);

  // Which tests exist: listed from trusted binaries (tests + stub), never from student code.
  auto listing = [&](const fs::path& tests_obj, const std::string& tag) {
    const std::uint64_t h = fnv1a(tests_obj.string() + stub.string());
    const fs::path bin = cache_dir(work) / fmt::format("list-{}-{:016x}", tag, h);
    if (!fs::exists(bin)) {
      std::string out;
      const fs::path tmp_bin = bin.string() + fmt::format(".tmp{}-{}", getpid(), random_secret().substr(0, 8));
      if (!link({harness, tests_obj, stub}, tmp_bin, work, out))
        throw std::runtime_error("internal error: the tests do not link with the stub:\n" + out.substr(0, 3000));
      std::error_code ec;
      fs::rename(tmp_bin, bin, ec);
      if (ec) return list_tests(tmp_bin, work);
    }
    return list_tests(bin, work);
  };
  for (const auto& n : listing(pub, "public")) {
    TestResult t;
    t.name = n;
    t.max_score = ex.points_of(n);
    rep.tests.push_back(t);
  }
  if (opt.include_hidden)
    for (const auto& n : listing(hid, "hidden")) {
      TestResult t;
      t.name = n;
      t.hidden = true;
      t.max_score = ex.points_of(n);
      rep.tests.push_back(t);
    }
  if (rep.tests.empty()) throw std::runtime_error("internal error: no tests found for " + ex.id);

  // The student's code: copied into the temporary directory, compiled in the sandbox.
  const fs::path src_dir = work / "submission";
  fs::create_directories(src_dir);
  const fs::path student_src = submission_dir / ex.source;
  auto fail_all = [&](const std::string& what) {
    for (auto& t : rep.tests) t.what = what;
    return rep;
  };
  if (!fs::is_regular_file(student_src)) {
    rep.compiler_output = fmt::format("no file named {} in the submission {}", ex.source, submission_dir.string());
    return fail_all("not run: the submission has no " + ex.source);
  }
  fs::copy_file(student_src, src_dir / ex.source);
  fs::copy_file(ex.dir / ex.header, src_dir / ex.header);
  say("compiling " + ex.source);
  {
    std::vector<std::string> a = {"g++"};
    a.insert(a.end(), cxxflags().begin(), cxxflags().end());
    a.insert(a.end(), {"-Wall", "-I", lib_include_dir().string(), "-I", src_dir.string(), "-c",
                       (src_dir / ex.source).string(), "-o", (work / "student.o").string()});
    // -w in cxxflags silences warnings of trusted code; the student's warnings are not graded.
    Limits l = compile_limits();
    l.wall_s = std::max(1.0, std::min(l.wall_s, remaining()));
    const Proc p = run_limited(a, work, l, sandbox().bwrap, {lib_include_dir()}, "", "compile.txt");
    if (p.timed_out) {
      rep.compiler_output = "the compiler ran out of time";
      rep.overall_timeout = remaining() <= 0;
      return fail_all("not run: the code does not compile");
    }
    if (!WIFEXITED(p.status) || WEXITSTATUS(p.status) != 0) {
      rep.compiler_output = shorten_compiler_output(p.output, work);
      return fail_all("not run: the code does not compile");
    }
  }
  const fs::path bin_pub = work / "public.bin", bin_hid = work / "hidden.bin";
  {
    std::string out;
    // Public tests run from a binary that holds no hidden test: what they print cannot leak one.
    if (!link({harness, pub, work / "student.o"}, bin_pub, work, out) ||
        (opt.include_hidden && !link({harness, hid, work / "student.o"}, bin_hid, work, out))) {
      rep.compiler_output = shorten_compiler_output(out, work);
      return fail_all("not run: the code does not link (a function of " + ex.header + " is missing or defined twice?)");
    }
  }
  rep.compiled = true;

  Limits lim;
  lim.cpu_s = opt.time_limit > 0 ? opt.time_limit : ex.time_limit;
  lim.mem_mb = ex.memory_mb;
  lim.fsize = 1 << 20;
  int k = 0;
  for (auto& t : rep.tests) {
    ++k;
    const double left = remaining();
    if (left <= 1) {
      rep.overall_timeout = true;
      t.what = "not run: the overall time limit of the grading run ran out";
      continue;
    }
    say(fmt::format("running {} ({}/{})", t.name, k, rep.tests.size()));
    Limits l = lim;
    l.wall_s = std::min(2.0 * lim.cpu_s + 2, left);
    const std::string secret = random_secret();
    const fs::path run_dir = work / fmt::format("run{}", k);
    fs::create_directories(run_dir);
    const fs::path bin = t.hidden ? bin_hid : bin_pub;
    fs::copy_file(bin, run_dir / "test.bin");
    const Proc p = run_limited({(run_dir / "test.bin").string(), "--gtest_filter=" + t.name},
                               run_dir, l, sandbox().bwrap, {}, secret, "output.txt");
    std::error_code ec;
    fs::remove_all(run_dir, ec);
    const auto [code, sig] = code_and_signal(p);
    std::istringstream rec(p.record);
    std::string got_secret, verdict, messages;
    std::getline(rec, got_secret);
    std::getline(rec, verdict);
    messages.assign(std::istreambuf_iterator<char>(rec), {});
    const bool record_ok = got_secret == secret && (verdict == "PASS" || verdict == "FAIL");
    if (!p.started) {
      t.what = "could not be started (internal error)";
    } else if (p.timed_out) {
      t.what = fmt::format("timed out: still running after {:.0f} s of wall-clock time (an infinite loop, or waiting for input?)", l.wall_s);
    } else if (sig != 0 && !(record_ok && verdict == "PASS" && sig == 0)) {
      t.what = signal_words(sig, l);
    } else if (!record_ok && p.output.find("SUMMARY: AddressSanitizer: ") != std::string::npos) {
      // Only when the tool itself is sanitized (its children then are too): name the error kind.
      const auto at = p.output.find("SUMMARY: AddressSanitizer: ") + 27;
      const std::string kind = p.output.substr(at, p.output.find_first_of(" \n", at) - at);
      t.what = fmt::format("was stopped by AddressSanitizer ({}): a memory error, or more memory than allowed", kind);
    } else if (!record_ok) {
      t.what = got_secret.empty() && code == 0
          ? "stopped before the test finished, with exit status 0: does your code call exit()?"
          : fmt::format("stopped before the test finished (exit status {}): does your code call exit() or abort()?", code);
    } else if (verdict == "PASS" && code == 0) {
      t.passed = true;
      t.what = "passed";
    } else if (verdict == "PASS") {
      t.what = fmt::format("passed its checks but then exited with status {}", code);
    } else {
      t.what = "failed";
      if (messages.find("std::bad_alloc") != std::string::npos)
        t.what = fmt::format("ran out of memory (the limit is {} MB)", lim.mem_mb);
      else if (messages.find("not implemented yet") != std::string::npos)
        t.what = "failed: not implemented yet";
      else if (messages.find("thrown in the test body") != std::string::npos)
        t.what = "failed: an exception escaped your code";
      if (!t.hidden) t.detail = trim(messages);
    }
  }
  return rep;
}

// ---- reports ---------------------------------------------------------------------------------

std::string json_string(const std::string& s) {
  std::string r = "\"";
  for (unsigned char c : s) {
    switch (c) {
      case '"': r += "\\\""; break;
      case '\\': r += "\\\\"; break;
      case '\n': r += "\\n"; break;
      case '\r': r += "\\r"; break;
      case '\t': r += "\\t"; break;
      default:
        if (c < 0x20) r += fmt::format("\\u{:04x}", c);
        else r += static_cast<char>(c);
    }
  }
  return r + "\"";
}

namespace {
std::string num(double v) { return fmt::format("{}", v); }
}  // namespace

std::string results_json(const Report& r, const std::string& hidden_visibility) {
  std::string out = "{\n";
  out += "  \"score\": " + num(r.score()) + ",\n";
  std::string top = fmt::format("{}: {} of {} points. Protection: {}.", r.exercise.title, num(r.score()),
                                num(r.max_score()), sandbox().description);
  if (!r.compiled) top += "\nYour code does not compile:\n" + r.compiler_output;
  if (r.overall_timeout) top += "\nThe grading run hit its overall time limit.";
  out += "  \"output\": " + json_string(top) + ",\n";
  out += "  \"tests\": [\n";
  for (size_t i = 0; i < r.tests.size(); ++i) {
    const auto& t = r.tests[i];
    std::string o = t.what;
    if (!t.hidden && !t.detail.empty()) o += "\n" + t.detail;
    out += "    {\"name\": " + json_string(t.name) + ", \"score\": " + num(t.passed ? t.max_score : 0) +
           ", \"max_score\": " + num(t.max_score) + ", \"output\": " + json_string(o) +
           ", \"visibility\": \"" + (t.hidden ? hidden_visibility : "visible") + "\"}";
    out += i + 1 < r.tests.size() ? ",\n" : "\n";
  }
  out += "  ]\n}\n";
  return out;
}

std::string grade_summary(const Report& r) {
  std::string s = fmt::format("{} ({})\n", r.exercise.title, r.exercise.id);
  if (!r.compiled) s += "does not compile (score 0):\n" + r.compiler_output;
  for (const auto& t : r.tests)
    s += fmt::format("  {:<4} {:<45} {:>4}/{:<4} {}\n", t.passed ? "ok" : "FAIL",
                     t.name + (t.hidden ? " (hidden)" : ""), num(t.passed ? t.max_score : 0),
                     num(t.max_score), t.what);
  s += fmt::format("score: {} of {}\nprotection: {}\n", num(r.score()), num(r.max_score()), sandbox().description);
  if (r.overall_timeout) s += "the overall time limit stopped the run\n";
  return s;
}

std::string check_summary(const Report& r) {
  std::string s = fmt::format("Exercise {}: {}\n\n", r.exercise.id, r.exercise.title);
  if (!r.compiled) {
    s += "Your code does not compile yet. The compiler says:\n\n" + r.compiler_output +
         "\nFix the first error first: the others often follow from it.\n";
    return s;
  }
  int passed = 0;
  for (const auto& t : r.tests) {
    if (t.passed) {
      ++passed;
      s += fmt::format("  passed  {}\n", t.name);
    } else {
      s += fmt::format("  FAILED  {}: {}\n", t.name, t.what);
      std::istringstream in(t.detail);
      std::string line;
      int n = 0;
      while (std::getline(in, line) && n++ < 12) s += "          " + line + "\n";
    }
  }
  s += fmt::format("\n{} of {} public tests pass; score so far {} of {} public points.\n", passed,
                   r.tests.size(), num(r.score()), num(r.max_score()));
  if (passed == static_cast<int>(r.tests.size()))
    s += "Next: the hidden tests try more of T2 (back side, points at infinity, antipodes, degenerate "
         "input). Think about each of those cases before you submit.\n";
  else
    s += "Next: fix the first failing test above, read its hint, and run `t2 check " + r.exercise.id +
         "` again.\n";
  return s;
}

}  // namespace t2grader
