// Building for the grader: see grader_build.hpp.
#include "grader_build.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "grader_allow.hpp"
#include "grader_cache.hpp"
#include "grader_elf.hpp"
#include "process.hpp"

#ifndef T2_SOURCE_DIR
#define T2_SOURCE_DIR "."
#endif
#ifndef T2_BINARY_DIR
#define T2_BINARY_DIR "./build"
#endif

namespace t2grader {

namespace {

fs::path lib_include_dir() { return library_include_dir(); }

bool sanitized_tool() {
#if defined(T2_SANITIZE)
  return true;
#else
  return false;
#endif
}

// The compiler that links a program with the kernel archive: g++, but in a sanitized tool the
// compiler that built it, whose sanitizer runtime matches the archive's instrumentation (clang's
// code reports nothing through GCC's libasan).
const char* linker() {
#if defined(T2_SANITIZE) && defined(__clang__)
  return "clang++";
#else
  return "g++";
#endif
}

// Everything a trusted build depends on besides its own sources.
std::uint64_t toolchain_key() {
  static const std::uint64_t k = [] {
    std::uint64_t h = fnv1a(run_out({"g++", "--version"}));
    std::vector<fs::path> hs;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(lib_include_dir(), ec); it != fs::recursive_directory_iterator(); it.increment(ec))
      if (it->is_regular_file()) hs.push_back(it->path());
    std::sort(hs.begin(), hs.end());
    for (const auto& p : hs) h = fnv1a(p.string() + read_text(p), h);
    return fnv1a(sanitized_tool() ? "asan" : "plain", h);
  }();
  return k;
}

const std::vector<std::string>& trusted_flags() {
  static const std::vector<std::string> f = {"-std=c++20", "-O1", "-g0", "-w"};
  return f;
}

std::vector<std::string> link_libraries(bool with_gtest) {
  std::vector<std::string> l = {library_archive().string()};
  if (with_gtest) l.push_back("-lgtest");
  for (const char* x : {"-lgmpxx", "-lgmp", "-lfmt", "-lpthread"}) l.push_back(x);
  return l;
}

// The driver's, the same in both builds: GMP linked in (its shared library is not in the
// driver's sandbox), the rest shared (there is no static fmt on Debian). A sanitized tool's
// kernel archive needs the sanitizers' runtimes: linked in statically too, so that the driver
// needs no shared library the plain build's does not (a dynamic libasan brought the host's /usr
// into the sandbox, and with it libgmp.so for dlopen: issue 29, break 3).
std::vector<std::string> driver_libraries() {
  std::vector<std::string> l;
  if (sanitized_tool()) l = {"-fsanitize=address,undefined"};
#if !defined(__clang__)
  if (sanitized_tool()) l.insert(l.end(), {"-static-libasan", "-static-libubsan"});  // clang's default
#endif
  l.insert(l.end(), {library_archive().string(), "-Wl,-Bstatic", "-lgmpxx", "-lgmp", "-Wl,-Bdynamic", "-lfmt", "-lpthread"});
  return l;
}

// The shared libraries of a driver (see TrustedParts::runtime), read by ldd from a trusted
// program linked with the same shared libraries (the checker), allowed by name: never GMP,
// never a sanitizer's runtime (the driver has both linked in).
std::vector<std::pair<fs::path, fs::path>> driver_runtime(const fs::path& checker) {
  std::vector<std::pair<fs::path, fs::path>> r;
  static const char* const kAllowed[] = {"ld-linux", "libc.so", "libm.so", "libstdc++.so", "libgcc_s.so", "libfmt.so",
                                         "libpthread.so", "libmvec.so"};
  // The checker may not need fmt (linked as needed); this tool always does.
  std::istringstream in(run_out({"ldd", checker.string()}) + run_out({"ldd", fs::read_symlink("/proc/self/exe").string()}));
  for (std::string line; std::getline(in, line);) {
    // "\tlibfmt.so.9 => /lib/x86_64-linux-gnu/libfmt.so.9 (0x...)" or "\t/lib64/ld-linux-x86-64.so.2 (0x...)"
    std::istringstream w(line);
    std::string name, arrow, path;
    w >> name >> arrow >> path;
    if (arrow != "=>") path = name;
    if (path.empty() || path[0] != '/') continue;
    const std::string base = fs::path(name).filename().string();
    for (const char* a : kAllowed)
      if (base.rfind(a, 0) == 0 && std::find_if(r.begin(), r.end(), [&](const auto& e) { return e.second == path; }) == r.end())
        r.push_back({fs::canonical(path), path});
  }
  if (r.empty()) throw GraderError("internal error: ldd finds no shared library in " + checker.string());
  return r;
}

// GoogleTest's header precompiled with the trusted flags, in a folder of its own (once per
// process) that a trusted compile searches first: `#include <gtest/gtest.h>`, the first line of
// every test file and of the checker's main, is then read from gtest/gtest.h.gch. GCC takes a
// precompiled header only as the first include and made with the same flags, and reads the
// header itself otherwise: an object is the same with it or without it (12b's hidden tests:
// byte for byte). Cached per toolchain and the text of every header it holds (g++ -M); made on
// the first trusted compile that needs it (~3 s, 86 MB). A cold exercise's trusted build (its
// reference graded first): 01 8.5 -> 6.2 s of CPU, 05 9.8 -> 6.6 s, 12b 16.5 -> 10.2 s.
fs::path gtest_pch_dir(const fs::path& work) {
  static const fs::path dir = [&] {
    const fs::path wrapper = work / "gtest-pch.hpp", d = work / "gtest-pch";
    std::ofstream(wrapper) << "#include <gtest/gtest.h>\n";
    std::vector<std::string> argv = {"g++"};
    argv.insert(argv.end(), trusted_flags().begin(), trusted_flags().end());
    std::string key = fmt::format("{}", fmt::join(argv, " "));
    argv.insert(argv.end(), {"-M", wrapper.string()});
    std::istringstream deps(run_out(argv));
    for (std::string w; deps >> w;)
      if (!w.empty() && w[0] == '/' && w != wrapper.string()) key += w + "\n" + read_text(w);
    const fs::path gch = cached(work, "gtest.h.gch", fnv1a(key, toolchain_key()), [&](const fs::path& tmp) {
      t2proc::Spec s;
      s.argv = {"g++"};
      s.argv.insert(s.argv.end(), trusted_flags().begin(), trusted_flags().end());
      s.argv.insert(s.argv.end(), {"-x", "c++-header", wrapper.string(), "-o", tmp.string()});
      s.limits.wall_seconds = 600;
      s.limits.output_bytes = 8000;
      const auto r = t2proc::run(s);
      if (!r.ok()) throw GraderError(fmt::format("internal error: gtest/gtest.h does not precompile:\n{}{}", r.error, r.err));
    });
    fs::create_directories(d / "gtest");
    fs::create_symlink(gch, d / "gtest" / "gtest.h.gch");
    return d;
  }();
  return dir;
}

// A trusted object: `src` compiled with `defines` and the include folders `inc`.
fs::path trusted_object(const fs::path& src, const std::vector<std::string>& defines, const std::vector<fs::path>& inc,
                        const fs::path& work) {
  std::string key = read_text(src);
  for (const auto& d : defines) key += " " + d;
  for (const auto& i : inc)
    for (const auto& e : fs::directory_iterator(i))
      if (e.path().extension() == ".hpp") key += read_text(e.path());
  key += fmt::format("{}", fmt::join(trusted_flags(), " "));
  const std::string stem = src.parent_path().filename().string() + "-" + src.stem().string() + (defines.empty() ? "" : "-c");
  return cached(work, stem + ".o", fnv1a(key, toolchain_key()), [&](const fs::path& tmp) {
    t2proc::Spec s;
    s.argv = {"g++"};
    s.argv.insert(s.argv.end(), trusted_flags().begin(), trusted_flags().end());
    s.argv.insert(s.argv.end(), defines.begin(), defines.end());
    if (read_text(src).find("#include <gtest/gtest.h>") != std::string::npos) s.argv.insert(s.argv.end(), {"-I", gtest_pch_dir(work).string()});
    s.argv.insert(s.argv.end(), {"-I", lib_include_dir().string()});
    for (const auto& i : inc) s.argv.insert(s.argv.end(), {"-I", i.string()});
    s.argv.insert(s.argv.end(), {"-c", src.string(), "-o", tmp.string()});
    s.limits.wall_seconds = 600;
    s.limits.output_bytes = 8000;
    const auto r = t2proc::run(s);
    if (!r.ok()) throw GraderError(fmt::format("internal error: {} does not compile:\n{}{}", src.string(), r.error, r.err));
  });
}

// A trusted program linked from trusted objects.
fs::path trusted_program(const std::string& stem, const std::vector<fs::path>& objs, bool gtest, const fs::path& work) {
  static const std::string archive = sha256(library_archive());  // hashed once a run, not once a program
  std::string key = archive;
  for (const auto& o : objs) key += o.filename().string();
  return cached(work, stem, fnv1a(key, toolchain_key()), [&](const fs::path& tmp) {
    t2proc::Spec s;
    s.argv = {linker()};
    if (sanitized_tool()) s.argv.push_back("-fsanitize=address,undefined");
    for (const auto& o : objs) s.argv.push_back(o.string());
    const auto libs = link_libraries(gtest);
    s.argv.insert(s.argv.end(), libs.begin(), libs.end());
    s.argv.insert(s.argv.end(), {"-o", tmp.string()});
    s.limits.wall_seconds = 600;
    s.limits.output_bytes = 8000;
    const auto r = t2proc::run(s);
    if (!r.ok()) throw GraderError(fmt::format("internal error: {} does not link:\n{}{}", stem, r.error, r.err));
  });
}

std::string shorten(const std::string& out) {
  std::string s = out;
  for (const std::string w : {"/src/", "/out/", "/t2/obj/", "/t2/include/"})
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

// Reads a file the sandbox wrote: a regular file only (never through a symlink), at most `cap` bytes.
bool read_untrusted(const fs::path& p, std::string& out, size_t cap) {
  const int fd = ::open(p.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat st{};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || static_cast<size_t>(st.st_size) > cap) {
    ::close(fd);
    return false;
  }
  out.clear();
  char buf[65536];
  for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) > 0 && out.size() <= cap;) out.append(buf, static_cast<size_t>(n));
  ::close(fd);
  return out.size() <= cap;
}

// The compiler's flags, the same for the precompiled header and the submission: GCC takes a
// precompiled header only where the flags that shape it are the ones it was made with.
const std::vector<std::string>& student_flags() {
  static const std::vector<std::string> f = {"-std=c++20", "-O0", "-fno-lto", "-Wall"};
  return f;
}

// The compiler's sandbox: the include view at /t2/include and the system headers it needs.
SandboxRun compiler_sandbox(const IncludeView& view) {
  SandboxRun r;
  r.read_only = {{view.tree, "/t2/include"}};
  r.masked = view.masked;
  for (const auto& p : view.system) r.read_only.push_back({p, p});
  r.limits.memory_bytes = sanitized_tool() ? 0 : 4096ull << 20;
  r.limits.file_bytes = 256ull << 20;
  r.limits.output_bytes = 64 << 10;
  r.tree_memory_bytes = 4096ull << 20;
  r.tmp_bytes = 512ull << 20;
  return r;
}

// A folder the sandbox's user writes (the compiler's output).
void hand_to_sandbox(const fs::path& dir) {
  fs::create_directories(dir);
  if (::geteuid() == 0 && ::chown(dir.c_str(), sandbox_uid(), sandbox_uid()) != 0)
    throw GraderError("cannot hand the build folder to the sandbox's user");
}

// The allowed headers precompiled (kAllowedHeader's .gch; ~55 MB for five kernel headers),
// cached per toolchain, allow-list and flags. Made by the compiler in the sandbox of the
// submission's compile, from the view alone (no line of a submission is in it), so that every
// path it records is the one the submission's compile sees: a diagnostic in a library header
// names /t2/include/t2/..., as without it, never a host folder.
fs::path precompiled_allowed(const Exercise& ex, const IncludeView& view, const fs::path& work) {
  std::string key = fmt::format("{}", fmt::join(student_flags(), " "));
  key += "\n" + read_text(view.tree / kAllowedHeader);  // the allowed headers, in order
  return cached(work, "allowed.gch", fnv1a(key, toolchain_key()), [&](const fs::path& tmp) {
    const fs::path out = work / "pch";
    hand_to_sandbox(out);
    SandboxRun r = compiler_sandbox(view);
    r.writable = {{out, "/out"}};
    r.argv = {"g++"};
    r.argv.insert(r.argv.end(), student_flags().begin(), student_flags().end());
    r.argv.insert(r.argv.end(), {"-I", "/t2/include", "-x", "c++-header", std::string("/t2/include/") + kAllowedHeader,
                                 "-o", "/out/allowed.gch"});
    r.limits.wall_seconds = r.limits.cpu_seconds = r.tree_cpu_seconds = 300;
    const t2proc::Result res = run_sandboxed(r);
    std::string bytes;
    if (!res.ok() || !read_untrusted(out / "allowed.gch", bytes, r.limits.file_bytes))
      throw GraderError(fmt::format("internal error: the allowed headers of {} do not precompile:\n{}{}", ex.id, res.error, res.err));
    std::ofstream(tmp, std::ios::binary) << bytes;
  });
}

// Whether the compile that wrote the dependency list `d` (-MD) took the allowed headers from
// their precompiled header: it lists every file of the view it read as text, and with the
// precompiled header it reads none (all are in it, each #pragma once).
bool took_precompiled(const fs::path& d) {
  std::string deps;
  return read_untrusted(d, deps, 16u << 20) && deps.find(".o:") != std::string::npos &&
         deps.find("/t2/include/") == std::string::npos;
}

}  // namespace

// Exercises are written on the kernel (t2::kernel: points, predicates, constructions, no
// drawing), so student and trusted programs link its archive only.
fs::path library_archive() {
  const fs::path a = fs::path(T2_BINARY_DIR) / "lib" / "libt2_kernel.a";
  if (!fs::exists(a)) throw GraderError(fmt::format("the library {} is not built: run ./build.sh first", a.string()));
  return a;
}

TrustedParts build_trusted(const Exercise& ex, bool hidden, const fs::path& work) {
  TrustedParts t;
  const fs::path h = ex.harness();
  t.probe = trusted_program("probe", {trusted_object(h / "probe.cpp", {}, {}, work)}, false, work);
  const std::vector<fs::path> inc = {h, ex.dir};
  const fs::path checker_main = trusted_object(h / "checker_main.cpp", {}, {h}, work);
  const fs::path remote_checker = trusted_object(ex.remote(), {"-DT2_JUDGE_CHECKER"}, inc, work);
  auto checker = [&](const fs::path& tests, const std::string& tag) {
    const fs::path o = trusted_object(tests, {}, inc, work);
    return trusted_program(ex.id + "-checker-" + tag, {checker_main, remote_checker, o}, true, work);
  };
  t.checker_public = checker(ex.public_tests(), "public");
  if (hidden) t.checker_hidden = checker(ex.hidden_tests(), "hidden");
  t.driver_objects = {trusted_object(h / "driver_main.cpp", {}, {h}, work), trusted_object(ex.remote(), {}, inc, work)};
  t.runtime = driver_runtime(t.checker_public);
  return t;
}

StudentBuild build_student(const Exercise& ex, const TrustedParts& t, const fs::path& src_dir,
                           const fs::path& out_dir, double wall_seconds) {
  StudentBuild b;
  // The compile sees the allow-list only (grader_allow.hpp): no other library header, and of
  // /usr/include what the standard library and the allowed headers include. The view and the
  // precompiled header are the grader's work, not counted in the submission's time.
  const fs::path work = out_dir.parent_path();
  const IncludeView view = include_view(ex, work, toolchain_key());
  SandboxRun r = compiler_sandbox(view);
  const std::string allowed = std::string("/t2/include/") + kAllowedHeader;
  if (!ex.allowed.empty()) {
    const fs::path gch = precompiled_allowed(ex, view, work);
    std::ofstream(view.tree / (std::string(kAllowedHeader) + ".gch"));  // where it is bound
    r.read_only.push_back({gch, allowed + ".gch"});
  }
  const auto start = std::chrono::steady_clock::now();
  hand_to_sandbox(out_dir);
  r.read_only.insert(r.read_only.end(), {{src_dir, "/src"}, {library_archive(), "/t2/lib/libt2_kernel.a"}});
  std::vector<std::string> objs;
  for (size_t i = 0; i < t.driver_objects.size(); ++i) {
    const std::string inside = fmt::format("/t2/obj/part{}.o", i);
    r.read_only.push_back({t.driver_objects[i], inside});
    objs.push_back(inside);
  }
  r.writable = {{out_dir, "/out"}};
  auto step = [&](std::vector<std::string> argv) {
    r.argv = std::move(argv);
    const double left = wall_seconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.limits.wall_seconds = std::max(1.0, left);
    r.limits.cpu_seconds = r.limits.wall_seconds;
    r.tree_cpu_seconds = r.limits.wall_seconds;
    const Prepared p = prepare_sandboxed(r);
    const auto res = t2proc::run(p.spec);
    if (res.timed_out || res.signal == SIGXCPU || *p.out_of_cpu) {
      b.timed_out = true;
      b.messages = fmt::format("the compiler ran out of time (the limit for compiling and linking is {:.0f} s)", wall_seconds);
      return false;
    }
    if (!res.ok()) {
      b.messages = shorten(res.err + res.out + res.error);
      return false;
    }
    return true;
  };
  // The allowed headers are read first, before any line of the submission: no macro of its own
  // can rename what they define (#define antipode x before #include), and its own #include of
  // them is then empty (#pragma once). What they define keeps its name for the symbol check.
  // They are one -include, the first, which GCC takes from its precompiled header (12b's
  // reference: 0.67 s instead of 1.06 s, the same object code): parsed once per allow-list.
  // -MD: the files it read as text, to tell whether it did (took_precompiled).
  std::vector<std::string> compile = {"g++"};
  compile.insert(compile.end(), student_flags().begin(), student_flags().end());
  compile.insert(compile.end(), {"-I", "/t2/include", "-I", "/src"});
  if (!ex.allowed.empty()) compile.insert(compile.end(), {"-include", allowed, "-Winvalid-pch", "-MD", "-MF", "/out/student.d"});
  compile.insert(compile.end(), {"-c", "/src/" + ex.source, "-o", "/out/student.o"});
  if (!step(compile)) {
    if (b.messages.find("No such file or directory") != std::string::npos)
      b.messages += fmt::format("(this exercise's code may include {}, {} and the C++ standard library)\n", ex.header,
                                ex.allowed.empty() ? std::string("no library header") : fmt::format("{}", fmt::join(ex.allowed, ", ")));
    return b;
  }
  // A precompiled header GCC did not take costs time, never a verdict (it reads the text instead).
  if (!ex.allowed.empty() && !took_precompiled(out_dir / "student.d"))
    fmt::print(stderr, "t2: warning: the compiler did not use the precompiled allowed headers of {} (it read their text)\n", ex.id);
  std::string bytes;
  if (!read_untrusted(out_dir / "student.o", bytes, 256u << 20)) {
    b.refused = true;
    b.messages = "the compiled object is missing or is not a regular file";
    return b;
  }
  if (const std::string why = refuse_object(read_object(bytes), ex.forbidden); !why.empty()) {
    b.refused = true;
    b.messages = why;
    return b;
  }
  std::vector<std::string> link = {linker(), "-fno-lto", "-fno-use-linker-plugin", "/out/student.o"};
  link.insert(link.end(), objs.begin(), objs.end());
  for (auto l : driver_libraries()) link.push_back(l == library_archive().string() ? "/t2/lib/libt2_kernel.a" : l);
  link.insert(link.end(), {"-o", "/out/driver"});
  if (!step(link)) {
    b.messages = "the code does not link (a function of " + ex.header + " is missing or defined twice?):\n" + b.messages;
    return b;
  }
  // The driver as the sandbox wrote it, copied to a folder only the grader writes.
  std::string exe;
  if (!read_untrusted(out_dir / "driver", exe, 512u << 20)) {
    b.messages = "the linked program is missing or is not a regular file";
    return b;
  }
  b.driver = out_dir.parent_path() / "driver.bin";
  std::ofstream(b.driver, std::ios::binary) << exe;
  fs::permissions(b.driver, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                fs::perms::others_read | fs::perms::others_exec);
  b.ok = true;
  return b;
}

}  // namespace t2grader
