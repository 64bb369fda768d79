// The arithmetic of `t2 bench`: see bench_stats.hpp.
#include "bench_stats.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace t2bench {

std::vector<std::size_t> log_steps(std::size_t n1, std::size_t n2, int per_decade) {
  if (n1 < 1 || n2 < n1 || per_decade < 1) throw std::invalid_argument("log_steps: need 1 <= n1 <= n2, per_decade >= 1");
  std::vector<std::size_t> out{n1};
  const double factor = std::pow(10.0, 1.0 / per_decade);
  for (int k = 1;; ++k) {
    const double x = double(n1) * std::pow(factor, k);
    if (x >= double(n2) * (1 - 1e-9)) break;  // N2 itself ends the list
    const auto s = static_cast<std::size_t>(std::llround(x));
    if (s > out.back()) out.push_back(s);
  }
  if (n2 > out.back()) out.push_back(n2);
  return out;
}

std::pair<std::size_t, std::size_t> parse_range(const std::string& text) {
  const auto dots = text.find("..");
  auto number = [&](const std::string& s) {
    if (s.empty() || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
      throw std::invalid_argument("--range " + text + ": expected N1..N2 with positive integers, e.g. 1000..1000000");
    try {
      return static_cast<std::size_t>(std::stoull(s));
    } catch (const std::out_of_range&) {
      throw std::invalid_argument("--range " + text + ": " + s + " is too large");
    }
  };
  if (dots == std::string::npos)
    throw std::invalid_argument("--range " + text + ": expected N1..N2, e.g. 1000..1000000");
  const std::size_t a = number(text.substr(0, dots)), b = number(text.substr(dots + 2));
  if (a < 1 || b < a) throw std::invalid_argument("--range " + text + ": need 1 <= N1 <= N2");
  return {a, b};
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

}  // namespace t2bench
