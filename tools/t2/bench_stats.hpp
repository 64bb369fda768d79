#pragma once
// The arithmetic of `t2 bench` (cmd_bench.cpp): the sizes of a range and medians (the growth
// exponent is fitted by t2::draw::fit_power_law, <t2/draw/loglog.hpp>). Pure functions, tested in
// tests/test_bench.cpp.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace t2bench {

/// The sizes of `--range N1..N2`: N1, then sizes growing by the factor 10^(1/per_decade)
/// (rounded to integers, strictly increasing), ending exactly at N2.
std::vector<std::size_t> log_steps(std::size_t n1, std::size_t n2, int per_decade);

/// Parses "N1..N2" (1 ≤ N1 ≤ N2); throws std::invalid_argument saying what is wrong.
std::pair<std::size_t, std::size_t> parse_range(const std::string& text);

/// The median of the values (the mean of the middle two for an even count); 0 for none.
double median(std::vector<double> v);

}  // namespace t2bench
