#pragma once
// The progress line of `t2 bench` on stderr: which run of how many, on which n, and how long the
// whole benchmark and the current run have taken. It is for a person watching a terminal, so it
// is shown only when stderr is one (or when asked for, see `Progress::from_environment`), once
// the benchmark has lasted a tick (a second), and kept current *during* a long run by a ticker
// thread that rewrites it in place ("\r", erase the line) every tick. It is erased when the
// benchmark ends, before the table is printed: stdout never sees it, and a log never gets it.

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <string>
#include <thread>

namespace t2bench {

/// The progress line of one benchmark (see the file comment).
class Progress {
 public:
  /// A benchmark of `total` runs; nothing is ever written unless `shown`. `tick` is how long
  /// the benchmark lasts before the line appears, and how often it is rewritten.
  Progress(std::size_t total, std::chrono::duration<double> tick, bool shown);
  /// Erases the line (if it was written) and stops the ticker.
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Whether and how often to show the line: on a terminal (`stderr_is_tty`) every second; with
  /// the environment variable T2_BENCH_PROGRESS=SECONDS (`env`, a positive number) every SECONDS
  /// on any stderr (for tests and for logs that want it). Throws std::invalid_argument when
  /// `env` is not a positive number.
  struct Setting {
    bool shown;                            ///< whether the line is written at all
    std::chrono::duration<double> tick;    ///< its delay and period
  };
  /// The setting for this stderr and this value of T2_BENCH_PROGRESS (null when unset).
  static Setting setting(bool stderr_is_tty, const char* env);

  /// Run `k` (1-based) starts: `name` on n points.
  void start(std::size_t k, const std::string& name, std::size_t n);

  /// The line for run k of total, `name` on n, after `total_s` seconds of the benchmark and
  /// `run_s` of the run (without the control characters that rewrite it in place).
  static std::string line(std::size_t k, std::size_t total, const std::string& name, std::size_t n, double total_s,
                          double run_s);

 private:
  void show(const std::unique_lock<std::mutex>&);
  void tick();

  using Clock = std::chrono::steady_clock;
  std::size_t total_, k_ = 0, n_ = 0;
  std::string name_;
  std::chrono::duration<double> tick_;
  bool shown_, written_ = false, done_ = false;
  Clock::time_point start_ = Clock::now(), run_start_ = start_, last_written_{};
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread ticker_;
};

}  // namespace t2bench
