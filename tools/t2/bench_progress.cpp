// The progress line of t2 bench (see bench_progress.hpp).
#include "bench_progress.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <stdexcept>
#include <string>

namespace t2bench {

namespace {
constexpr const char* kErase = "\r\033[K";  // back to the start of the line, erase it
}

Progress::Progress(std::size_t total, std::chrono::duration<double> tick, bool shown)
    : total_(total), tick_(tick), shown_(shown) {
  if (shown_) ticker_ = std::thread([this] { this->tick(); });
}

Progress::~Progress() {
  if (!shown_) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  wake_.notify_all();
  ticker_.join();
  if (written_) {
    fmt::print(stderr, "{}", kErase);
    std::fflush(stderr);
  }
}

Progress::Setting Progress::setting(bool stderr_is_tty, const char* env) {
  if (env == nullptr) return {stderr_is_tty, std::chrono::seconds(1)};
  std::size_t used = 0;
  double s = 0;
  try {
    s = std::stod(env, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || env[used] != 0 || !(s > 0) || s > 3600)
    throw std::invalid_argument(fmt::format("T2_BENCH_PROGRESS={}: not a number of seconds in (0, 3600]", env));
  return {true, std::chrono::duration<double>(s)};
}

std::string Progress::line(std::size_t k, std::size_t total, const std::string& name, std::size_t n, double total_s,
                           double run_s) {
  return fmt::format("t2 bench: run {}/{}: {} on n = {} ({:.0f} s so far, this run {:.0f} s)", k, total, name, n,
                     total_s, run_s);
}

void Progress::start(std::size_t k, const std::string& name, std::size_t n) {
  if (!shown_) return;
  std::unique_lock<std::mutex> lock(mutex_);
  k_ = k, name_ = name, n_ = n;
  run_start_ = Clock::now();
  show(lock);
}

// Writes the line once the benchmark has lasted a tick: at every new run, and during a run at
// most once a tick.
void Progress::show(const std::unique_lock<std::mutex>&) {
  const auto now = Clock::now();
  if (k_ == 0 || now - start_ < tick_) return;
  const bool new_run = last_written_ < run_start_;
  if (!new_run && now - last_written_ < tick_) return;
  const std::string text = line(k_, total_, name_, n_, std::chrono::duration<double>(now - start_).count(),
                                std::chrono::duration<double>(now - run_start_).count());
  fmt::print(stderr, "{}{}", kErase, text);
  std::fflush(stderr);
  last_written_ = now;
  written_ = true;
}

void Progress::tick() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!done_) {
    wake_.wait_for(lock, tick_ / 4);
    if (!done_) show(lock);
  }
}

}  // namespace t2bench
