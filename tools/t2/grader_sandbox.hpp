#pragma once
// The grader's sandbox: how untrusted code (the compiler and linker on the student's source, the
// driver running the student's functions) is started. Never as root: as a dedicated unprivileged
// uid (setpriv before bubblewrap when the grader is root), with every capability dropped, no
// nested user namespaces, a seccomp filter, a read-only system, no network, a bounded tmpfs as the
// only writable place (plus, for the compiler, one output folder), rlimits, and a cgroup for the
// whole process tree where the cgroup file system is writable.

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "process.hpp"

namespace t2grader {

namespace fs = std::filesystem;

/// One run inside the sandbox.
struct SandboxRun {
  std::vector<std::string> argv;                          ///< the command, with paths as seen inside
  std::vector<std::pair<fs::path, fs::path>> read_only;   ///< host path → path inside (read-only)
  bool system = true;                                     ///< the host's /usr, /lib ... read-only (false:
                                                          ///< nothing but read_only and copied)
  std::vector<fs::path> masked;                           ///< system folders shown empty (read_only may bind
                                                          ///< parts back: the compile's allow-list)
  std::vector<std::pair<fs::path, fs::path>> writable;    ///< host folder → path inside (compiler output only)
  std::vector<std::pair<fs::path, fs::path>> copied;      ///< host file → executable copy inside, whose
                                                          ///< host path /proc/self/mountinfo does not show
  std::string chdir = "/tmp";                             ///< working folder inside
  t2proc::Limits limits;                                  ///< per-process limits and wall clock
  std::uint64_t tree_memory_bytes = 0;                    ///< cgroup memory of the whole tree (0: none)
  double tree_cpu_seconds = 0;                            ///< CPU time of the whole tree, all processes
                                                          ///< together (0: none; needs the cgroup)
  int tree_processes = 64;                                ///< processes of the whole tree
  std::uint64_t tmp_bytes = 64u << 20;                    ///< size of the tmpfs at /tmp
  t2proc::Stream out = t2proc::Stream::capture;           ///< stdout
  t2proc::Stream err = t2proc::Stream::capture;           ///< stderr
  std::vector<int> handover_fds;  ///< fds handed to the command: kept in it, closed in the caller
};

/// A sandboxed run ready to start (with t2proc::run or run_all); `hold` keeps its cgroup alive
/// until the run has ended and is destroyed.
struct Prepared {
  t2proc::Spec spec;           ///< the command line of setpriv / bwrap / the command
  std::shared_ptr<void> hold;  ///< the run's cgroup and its CPU watcher (removed when the last copy goes)
  std::string tree_limits;     ///< the cgroup limits in force ("" when there is no cgroup)
  std::shared_ptr<const std::atomic<bool>> out_of_cpu;  ///< set when the tree used its CPU time and was
                                                        ///< killed (never set without a cgroup)
  std::function<void()> kill;  ///< kills the run's whole tree now (empty without a cgroup)
};

/// What protects the machine while student code runs, as probed.
struct Sandbox {
  bool works = false;         ///< student code can be run in the sandbox
  std::string mode;           ///< how: "bubblewrap as uid N" or why it cannot
  std::string description;    ///< one line for every report, made of the probe's findings
  std::string probe_output;   ///< the probe's own lines (name=value)
  bool tree_bounded = false;  ///< a cgroup bounds the memory of a run's whole process tree (as root)
};

/// An error of the grader itself (a broken exercise, a missing build, no sandbox).
struct GraderError : std::runtime_error {
  using std::runtime_error::runtime_error;  ///< the message says what is wrong
};

/// Prepares `r` to run in the sandbox.
Prepared prepare_sandboxed(const SandboxRun& r);
/// Runs `r` in the sandbox to its end.
t2proc::Result run_sandboxed(const SandboxRun& r);

/// Probes the sandbox (once per process): runs the trusted `probe` program inside it with the
/// host paths `secrets` (which must not be readable there) and reads what held.
const Sandbox& sandbox(const fs::path& probe, const std::vector<fs::path>& secrets);

/// The uid untrusted code runs as (owner of the compiler's output folder).
unsigned sandbox_uid();

}  // namespace t2grader
