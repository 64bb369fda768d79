#pragma once
// The arithmetic of `t2 bench` (cmd_bench.cpp): the sizes of a range, medians, and the growth
// exponent fitted to the measurements. Pure functions, tested in tests/test_bench.cpp.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace t2bench {

/// A power law t ≈ c · n^exponent fitted to measurements.
struct Fit {
  double exponent = 0;  ///< the growth exponent: the slope of log t against log n
  double constant = 0;  ///< c, the time at n = 1 of the fitted line
  std::size_t points = 0;  ///< how many measurements entered the fit (those with t > 0)
};

/// Least squares on (log n, log t) over the measurements with n > 0 and t > 0. With fewer than
/// two distinct n the exponent is undefined: `points` tells (the caller prints nothing then).
Fit fit_power_law(std::span<const double> n, std::span<const double> t);

/// True when the fit has at least two distinct sizes.
bool fit_defined(std::span<const double> n, std::span<const double> t);

/// The sizes of `--range N1..N2`: N1, then sizes growing by the factor 10^(1/per_decade)
/// (rounded to integers, strictly increasing), ending exactly at N2.
std::vector<std::size_t> log_steps(std::size_t n1, std::size_t n2, int per_decade);

/// Parses "N1..N2" (1 ≤ N1 ≤ N2); throws std::invalid_argument saying what is wrong.
std::pair<std::size_t, std::size_t> parse_range(const std::string& text);

/// The median of the values (the mean of the middle two for an even count); 0 for none.
double median(std::vector<double> v);

}  // namespace t2bench
