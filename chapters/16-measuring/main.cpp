// Chapter 16: measuring. Growth exponents read from counts of predicate calls, not
// times: a count depends on neither the machine nor its load, so every run gives the
// same numbers and the same figures. The hulls of chapter 06 on a circle (every point a
// vertex), in a disk and in a square, fitted by least squares on the log-log scale.
#include <t2/draw.hpp>
#include <t2/gen/generate.hpp>
#include <t2/hull.hpp>
#include <t2/t2.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using t2::Point;

void require(bool ok, const std::string& what) {
  if (!ok) throw std::logic_error("chapter 16: check failed: " + what);
}

//> counting-traits
// The hull traits with every orientation test counted: the algorithms take their
// predicates from the traits (chapter 06), so counting needs no change to them.
struct CountingOrient : t2::HullTraits {
  static inline std::size_t calls = 0;
  static t2::Sign orient(const Point& p, const Point& q, const Point& r) {
    ++calls;
    return t2::HullTraits::orient(p, q, r);
  }
};

// The orientation tests `algorithm` makes on n points of `kind` (the seed is fixed: the
// same points, hence the same count, on every machine).
double orient_calls(t2::HullAlgorithm algorithm, t2::gen::Kind kind, std::size_t n) {
  t2::gen::Options o;
  o.n = n;
  o.seed = 16;
  const std::vector<Point> P = t2::gen::points(kind, o);
  CountingOrient::calls = 0;
  t2::convex_hull<CountingOrient>(P, algorithm);
  return double(CountingOrient::calls);
}
//< counting-traits

const std::vector<double> kSizes = {250, 500, 1000, 2000, 4000, 8000};

t2::draw::Series series(const std::string& name, t2::HullAlgorithm a, t2::gen::Kind kind) {
  t2::draw::Series s{name, {}, {}};
  for (double n : kSizes) {
    s.n.push_back(n);
    s.t.push_back(orient_calls(a, kind, static_cast<std::size_t>(n)));
  }
  return s;
}

void table(const std::vector<t2::draw::Series>& all) {
  std::printf("%-22s", "n");
  for (double n : kSizes) std::printf("%10.0f", n);
  std::printf("   exponent\n");
  for (const auto& s : all) {
    std::printf("%-22s", s.name.c_str());
    for (double c : s.t) std::printf("%10.0f", c);
    std::printf("   %.2f\n", t2::draw::fit_power_law(s.n, s.t).exponent);
  }
}

double exponent(const t2::draw::Series& s) { return t2::draw::fit_power_law(s.n, s.t).exponent; }

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = t2::draw::figures_dir(argc, argv, T2_FIGURES_DIR);
  using A = t2::HullAlgorithm;
  using K = t2::gen::Kind;
  std::cout << "== orientation tests on a circle: every point is a hull vertex\n";
  //> circle-growth
  const std::vector<t2::draw::Series> circle = {
      series("Graham", A::graham, K::circle),
      series("monotone chain", A::monotone, K::circle),
      series("Quickhull", A::quickhull, K::circle),
      series("merge (T²)", A::merge, K::circle),
      series("Jarvis", A::jarvis, K::circle)};
  //< circle-growth
  table(circle);
  // n log n shows as an exponent a little above 1 over this range; nh = n² as 2.
  for (int i = 0; i < 4; ++i) require(exponent(circle[i]) < 1.25, circle[i].name + " grows as n log n");
  require(exponent(circle[4]) > 1.95 && exponent(circle[4]) < 2.05, "Jarvis grows as n² on a circle");
  std::cout << "\n== Jarvis's march: the output decides (nh)\n";
  const std::vector<t2::draw::Series> jarvis = {
      series("Jarvis, circle (h = n)", A::jarvis, K::circle),
      series("Jarvis, disk", A::jarvis, K::disk),
      series("Jarvis, square", A::jarvis, K::uniform)};
  table(jarvis);
  // In a disk the expected number of hull vertices grows as n^(1/3), in a square as log n.
  require(exponent(jarvis[1]) > 1.2 && exponent(jarvis[1]) < 1.5, "Jarvis in a disk: n^(4/3)");
  require(exponent(jarvis[2]) > 1.0 && exponent(jarvis[2]) < exponent(jarvis[1]), "Jarvis in a square: n log n");
  t2::write_file_atomically(dir / "growth-circle.svg",
                            t2::draw::loglog_svg(circle, "hulls of n points on a circle", "orientation tests"));
  t2::write_file_atomically(dir / "growth-jarvis.svg",
                            t2::draw::loglog_svg(jarvis, "Jarvis's march: n points, h on the hull", "orientation tests"));
}
