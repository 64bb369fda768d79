#pragma once
// Measured growth (chapter 16): a power law t ≈ c · n^k fitted by least squares on (log n, log t),
// and the log-log plot of measurements with their fitted lines, as `t2 bench --plot` and chapter
// 16's figures draw it (plain Cairo, an SVG document).

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace t2::draw {

/// A power law t ≈ c · n^exponent fitted to measurements.
struct PowerLaw {
  double exponent = 0;     ///< the growth exponent: the slope of log t against log n
  double constant = 0;     ///< c, the value at n = 1 of the fitted line
  std::size_t points = 0;  ///< how many measurements entered the fit (those with n > 0, t > 0)
};

/// Least squares on (log n, log t) over the measurements with n > 0 and t > 0. With fewer than
/// two distinct n the exponent is undefined: `points` tells (the caller prints nothing then).
PowerLaw fit_power_law(std::span<const double> n, std::span<const double> t);

/// True when the fit has at least two distinct sizes.
bool fit_defined(std::span<const double> n, std::span<const double> t);

/// The measurements of one implementation (or one quantity).
struct Series {
  std::string name;       ///< its name in the table ("t2", "cgal", ...)
  std::vector<double> n;  ///< the sizes
  std::vector<double> t;  ///< the measured values (seconds, counts...), one per size
};

/// An SVG document (640 × 440 pt): log10 t against log10 n with decade ticks, every series as
/// markers joined by a line, its fitted power law dashed, and a legend naming each series with
/// its growth exponent. Deterministic: the same series give the same bytes.
std::string loglog_svg(const std::vector<Series>& series, const std::string& title, const std::string& y_label);

}  // namespace t2::draw
