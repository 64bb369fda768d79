#pragma once
// The one way the t2 tools start a process: arguments, environment, working folder, captured or
// discarded output (bounded, never blocking the child), resource limits, and a wall-clock limit
// that kills the child's whole process group. Shared by the grader and the rest of the tools;
// it depends on nothing of the command-line layer. POSIX only.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

/// Running child processes (see tools/common/process.hpp).
namespace t2proc {

/// Limits of one run; 0 means none.
struct Limits {
  double wall_seconds = 0;         ///< on expiry the whole process group gets SIGKILL
  double cpu_seconds = 0;          ///< RLIMIT_CPU
  std::uint64_t memory_bytes = 0;  ///< RLIMIT_AS
  std::uint64_t file_bytes = 0;    ///< RLIMIT_FSIZE
  int processes = 0;               ///< RLIMIT_NPROC
  std::size_t output_bytes = 0;    ///< bytes kept per captured stream; the rest is read and dropped
};

/// What becomes of the child's stdout or stderr.
enum class Stream {
  capture,  ///< read into Result::out / Result::err (bounded by Limits::output_bytes)
  discard,  ///< /dev/null
  inherit   ///< the caller's own stream
};

/// What to run and how.
struct Spec {
  std::vector<std::string> argv;                ///< argv[0] is searched in PATH when it has no '/'
  std::filesystem::path cwd;                    ///< empty: inherit
  std::optional<std::vector<std::string>> env;  ///< nullopt: inherit; else exactly these NAME=VALUE
  std::string stdin_data;                       ///< written to stdin then closed ("": /dev/null)
  bool inherit_stdin = false;                   ///< the child reads the caller's stdin instead, and
                                                ///< stays in the caller's process group (a terminal
                                                ///< would stop a background group that reads it), so
                                                ///< only the child itself is killed at its end
  Stream out = Stream::capture;                 ///< stdout
  Stream err = Stream::capture;                 ///< stderr
  std::filesystem::path err_file;               ///< when set, stderr goes to this file instead
  Limits limits;                                ///< resource and time limits
  std::vector<int> keep_fds;                    ///< fds the child inherits (all others closed)
  std::vector<int> close_in_parent;             ///< fds handed over: closed in the caller once the
                                                ///< child is started (or could not be); lets two
                                                ///< children of run_all talk through pipes and see
                                                ///< EOF when the other ends
};

/// How a run ended.
struct Result {
  bool started = false;       ///< false: could not start (error says why)
  std::string error;          ///< why it could not start
  int exit_code = -1;         ///< -1 when killed by a signal
  int signal = 0;             ///< the signal that ended it, or 0
  bool timed_out = false;     ///< the wall-clock limit fired
  bool out_truncated = false; ///< stdout was longer than Limits::output_bytes
  bool err_truncated = false; ///< stderr was longer than Limits::output_bytes
  std::string out;            ///< captured stdout
  std::string err;            ///< captured stderr
  double wall_seconds = 0;    ///< elapsed time
  double cpu_seconds = 0;     ///< user + system time of the child tree (children it waited for)
  long peak_rss_kb = 0;       ///< peak resident memory of the child (or of its largest waited-for
                              ///< descendant), in KiB: wait4's ru_maxrss
  /// Started, not timed out, no signal, exit status 0.
  bool ok() const { return started && !timed_out && signal == 0 && exit_code == 0; }
};

/// Runs one process (in its own process group) to its end; thread-safe.
Result run(const Spec& spec);
/// Runs every spec, at most `jobs` at once; results in the order of `specs`.
std::vector<Result> run_all(const std::vector<Spec>& specs, int jobs);

/// Removes a folder when the caller ends without removing it itself, however it ends (SIGKILL
/// included): a watcher process in a session of its own (out of reach of signals sent to the
/// caller's process group) waits on a pipe; end of file there means the caller died, and the
/// watcher removes the folder (`rm -rf`, after a second for the caller's children to die with
/// it). The destructor, run once the caller has removed the folder, ends the watcher.
class RemoveWhenGone {
 public:
  explicit RemoveWhenGone(const std::filesystem::path& folder);
  ~RemoveWhenGone();
  RemoveWhenGone(const RemoveWhenGone&) = delete;
  RemoveWhenGone& operator=(const RemoveWhenGone&) = delete;

 private:
  int fd_ = -1;   // the pipe's write end (close-on-exec)
  int pid_ = -1;  // the watcher
};

}  // namespace t2proc
