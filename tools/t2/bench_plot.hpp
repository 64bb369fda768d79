#pragma once
// The log-log plot of `t2 bench` (cmd_bench.cpp): time against n, one line per implementation,
// drawn with plain Cairo as an SVG document.

#include <string>
#include <vector>

namespace t2bench {

/// The measurements of one implementation.
struct Series {
  std::string name;       ///< its name in the table ("t2", "cgal", ...)
  std::vector<double> n;  ///< the sizes
  std::vector<double> t;  ///< the times (seconds), one per size
};

/// An SVG document (640 × 440 pt): log10 t against log10 n with decade ticks, every series as
/// markers joined by a line, its fitted power law dashed, and a legend naming each series with
/// its growth exponent. Deterministic: the same series give the same bytes.
std::string plot_svg(const std::vector<Series>& series, const std::string& title, const std::string& y_label);

}  // namespace t2bench
