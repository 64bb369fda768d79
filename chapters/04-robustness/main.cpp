// Chapter 04, robustness: floating point gone wrong, and what the library does about it.
//
// Prints the evidence the chapter quotes and writes its figures (SVG) into --figures DIR.
// Every number below is computed here; nothing is pasted. Deterministic: no clocks, and the
// random inputs come from a fixed-seed std::mt19937_64 turned into doubles by bit arithmetic
// (std::uniform_real_distribution differs between standard libraries).
// This program prints the filter statistics: they count only where T2_FILTER_STATS is defined.
#define T2_FILTER_STATS 1
#include <t2/t2.hpp>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

// ---------------------------------------------------------------------------------------------
// 1. The clipping-order example (seed 002, after Ghali 2008): two ways to one point in float.

//> float-lines
// Cartesian points and lines a·x + b·y + c = 0 in single precision, the way a textbook
// library stores them. line() is the cross product of [x, y, 1] triples; intersect()
// solves the 2×2 system by Cramer's rule and divides, so its result is rounded.
struct PointF { float x, y; };
struct LineF { float a, b, c; };

LineF line(PointF p, PointF q) { return {p.y - q.y, q.x - p.x, p.x * q.y - q.x * p.y}; }

PointF intersect(LineF l, LineF m) {
  const float d = l.a * m.b - m.a * l.b;
  return {(l.b * m.c - m.b * l.c) / d, (m.a * l.c - l.a * m.c) / d};
}
//< float-lines

// The bits of a float as "sign exponent mantissa", the format of the seed's printout.
std::string bits(float f) {
  const auto u = std::bit_cast<std::uint32_t>(f);
  std::string s;
  for (int i = 31; i >= 0; --i) {
    s += ((u >> i) & 1u) ? '1' : '0';
    if (i == 31 || i == 23) s += ' ';
  }
  return s;
}

void clipping_in_float() {
  std::cout << "== 1. Clipping order in float (seed 002, after Ghali 2008)\n";
  //> clipping-float
  const PointF A{2, 2}, B{9, 5}, C{8, 2}, D{6, 5}, E{4, 1}, F{5, 6};
  const PointF Gd = intersect(line(A, B), line(E, F));  // directly: AB meets EF
  const PointF H = intersect(line(A, B), line(C, D));   // first clip AB by CD ...
  const PointF Gi = intersect(line(A, H), line(E, F));  // ... then AH meets EF
  //< clipping-float
  std::printf("Gd = (%.9g, %.9g)   Gi = (%.9g, %.9g)   H = (%.9g, %.9g)\n", Gd.x, Gd.y, Gi.x,
              Gi.y, H.x, H.y);
  std::cout << "Gd.x " << bits(Gd.x) << "\nGi.x " << bits(Gi.x) << "\nGd.y " << bits(Gd.y)
            << "\nGi.y " << bits(Gi.y) << '\n';
  std::cout << "Gd == Gi: " << ((Gd.x == Gi.x && Gd.y == Gi.y) ? "true" : "false")
            << "   Gi.x - Gd.x = 2^" << std::ilogb(Gi.x - Gd.x) << " (one unit in the last place)\n";
  // The seed's printout, copied as data: the program checks that it reproduces it bit for bit.
  const bool same = bits(Gd.x) == "0 10000001 00011010000000000000000" &&
                    bits(Gi.x) == "0 10000001 00011010000000000000001" &&
                    bits(Gd.y) == "0 10000000 10000100000000000000000" &&
                    bits(Gi.y) == "0 10000000 10000100000000000000000";
  std::cout << "matches the four lines printed in seed 002: " << (same ? "yes" : "NO") << "\n";
  // The same computation in double: the error shrinks, it does not go away.
  struct PD { double x, y; };
  auto lineD = [](PD p, PD q) { return std::array<double, 3>{p.y - q.y, q.x - p.x, p.x * q.y - q.x * p.y}; };
  auto interD = [](std::array<double, 3> l, std::array<double, 3> m) {
    const double d = l[0] * m[1] - m[0] * l[1];
    return PD{(l[1] * m[2] - m[1] * l[2]) / d, (m[0] * l[2] - l[0] * m[2]) / d};
  };
  const PD a{2, 2}, b{9, 5}, c{8, 2}, d{6, 5}, e{4, 1}, f{5, 6};
  const PD gd = interD(lineD(a, b), lineD(e, f)), h = interD(lineD(a, b), lineD(c, d));
  const PD gi = interD(lineD(a, h), lineD(e, f));
  std::printf("in double: Gd = (%.17g, %.17g)  Gi = (%.17g, %.17g)  equal: %s\n\n", gd.x, gd.y, gi.x,
              gi.y, (gd.x == gi.x && gd.y == gi.y) ? "true" : "false");
}

// The same construction in T²: join and meet are cross products, nothing is divided.
void clipping_in_t2() {
  std::cout << "== 4a. The same clipping in T2, without division\n";
  //> clipping-t2
  using P = t2::ExactPoint;
  const P A = P::cartesian(2, 2), B = P::cartesian(9, 5), C = P::cartesian(8, 2),
          D = P::cartesian(6, 5), E = P::cartesian(4, 1), F = P::cartesian(5, 6);
  const P Gd = t2::meet(t2::join(A, B), t2::join(E, F));
  const P H = t2::meet(t2::join(A, B), t2::join(C, D));
  const P Gi = t2::meet(t2::join(A, H), t2::join(E, F));
  const bool same = (Gd == Gi);  // equal up to a positive factor: exact
  //< clipping-t2
  std::cout << "Gd = " << t2::to_string(Gd) << "\nH  = " << t2::to_string(H)
            << "\nGi = " << t2::to_string(Gi) << "\nGd == Gi: " << (same ? "true" : "false")
            << "   Gd == antipode(Gi): " << (Gd == t2::antipode(Gi) ? "true" : "false") << '\n';
  std::cout << "Gd as a fraction: (" << t2::to_string(Gd.x()) << "/" << t2::to_string(Gd.w()) << ", "
            << t2::to_string(Gd.y()) << "/" << t2::to_string(Gd.w()) << ") = (" << mpq_class(Gd.x(), Gd.w()).get_d()
            << ", " << mpq_class(Gd.y(), Gd.w()).get_d() << ")\n";
  // With double coordinates the same steps give the same answer here, because every
  // intermediate value is a small integer and therefore exact; deeper chains of
  // constructions are where ExactPoint earns its cost.
  using Q = t2::Point;
  const Q a = Q::cartesian(2, 2), b = Q::cartesian(9, 5), c = Q::cartesian(8, 2), d = Q::cartesian(6, 5),
          e = Q::cartesian(4, 1), f = Q::cartesian(5, 6);
  const Q gd = t2::meet(t2::join(a, b), t2::join(e, f));
  const Q gi = t2::meet(t2::join(a, t2::meet(t2::join(a, b), t2::join(c, d))), t2::join(e, f));
  std::cout << "with t2::Point (double): Gd = " << t2::to_string(gd) << "  Gi = " << t2::to_string(gi)
            << "  Gd == Gi: " << (gd == gi ? "true" : "false") << "\n";
  // Bit growth: each join or meet roughly doubles the size of the coordinates.
  {
    const auto nbits = [](const t2::Integer& v) { return v == 0 ? std::size_t{0} : mpz_sizeinbase(v.get_mpz_t(), 2); };
    std::cout << "largest coordinate, bits: inputs " << nbits(t2::Integer(9)) << ", Gd " << std::max({nbits(Gd.w()), nbits(Gd.x()), nbits(Gd.y())})
              << ", H " << std::max({nbits(H.w()), nbits(H.x()), nbits(H.y())}) << ", Gi "
              << std::max({nbits(Gi.w()), nbits(Gi.x()), nbits(Gi.y())}) << "\n\n";
  }
}

// ---------------------------------------------------------------------------------------------
// 2. The sign map of naive orientation (Kettner, Mehlhorn, Pion, Schirra, Yap 2004/2008).

//> naive-orient
// The textbook orientation test, evaluated in double arithmetic: the sign of
// (qx - px)(ry - py) - (qy - py)(rx - px). Each operation rounds.
int naive_orient(double px, double py, double qx, double qy, double rx, double ry) {
  const double d = (qx - px) * (ry - py) - (qy - py) * (rx - px);
  return (d > 0) - (d < 0);
}
//< naive-orient

struct SignMap {
  int n = 256;
  std::vector<int> naive, exact;
};

SignMap sign_map() {
  SignMap m;
  m.naive.resize(m.n * m.n);
  m.exact.resize(m.n * m.n);
  //> sign-map
  const double u = 0x1p-53;  // the spacing of the doubles in [0.5, 1)
  const t2::Point q = t2::Point::cartesian(12, 12), r = t2::Point::cartesian(24, 24);
  for (int j = 0; j < 256; ++j) {
    for (int i = 0; i < 256; ++i) {
      const double px = 0.5 + i * u, py = 0.5 + j * u;  // exact: 256 neighbouring doubles
      m.naive[j * 256 + i] = naive_orient(px, py, q.x(), q.y(), r.x(), r.y());
      m.exact[j * 256 + i] = t2::orient(t2::Point::cartesian(px, py), q, r);
    }
  }
  //< sign-map
  return m;
}

void print_sign_map(const SignMap& m) {
  std::cout << "== 2. Sign map of orient(p, q, r), q = (12, 12), r = (24, 24), p = (0.5 + i u, 0.5 + j u), "
               "0 <= i, j < 256, u = 2^-53\n";
  long wrong_sign = 0, false_zero = 0, missed_zero = 0, pos = 0, neg = 0, zero = 0, npos = 0, nneg = 0, nzero = 0;
  bool exact_is_diagonal = true;
  for (int j = 0; j < m.n; ++j)
    for (int i = 0; i < m.n; ++i) {
      const int a = m.naive[j * m.n + i], e = m.exact[j * m.n + i];
      (e > 0 ? pos : e < 0 ? neg : zero) += 1;
      (a > 0 ? npos : a < 0 ? nneg : nzero) += 1;
      if (a * e < 0) ++wrong_sign;
      if (a == 0 && e != 0) ++false_zero;
      if (a != 0 && e == 0) ++missed_zero;
      if (e != (j > i) - (j < i)) exact_is_diagonal = false;
    }
  std::printf("exact: %ld left, %ld on the line, %ld right (exact sign = sign(j - i) everywhere: %s)\n", pos, zero,
              neg, exact_is_diagonal ? "yes" : "NO");
  std::printf("naive: %ld left, %ld on the line, %ld right\n", npos, nzero, nneg);
  std::printf("naive vs exact: %ld opposite signs, %ld false 'collinear', %ld collinear points missed, "
              "%ld of %d cells wrong (%.1f%%)\n\n",
              wrong_sign, false_zero, missed_zero, wrong_sign + false_zero + missed_zero, m.n * m.n,
              100.0 * (wrong_sign + false_zero + missed_zero) / (m.n * m.n));
}

// ---------------------------------------------------------------------------------------------
// 3. Tolerances: an epsilon test is not an equivalence, and not a geometry.

void tolerances() {
  std::cout << "== 3. Why tolerances fail\n";
  //> eps-equal
  const double eps = 1e-9;
  auto near = [eps](double a, double b) { return std::fabs(a - b) <= eps; };
  const double a = 0, b = 0.6e-9, c = 1.2e-9;
  //< eps-equal
  std::cout << "near(a, b) = " << near(a, b) << ", near(b, c) = " << near(b, c) << ", near(a, c) = " << near(a, c)
            << "   (a = 0, b = 0.6e-9, c = 1.2e-9, eps = 1e-9)\n";
  //> eps-collinear
  // "Collinear within eps": |orientation determinant| <= eps.
  auto det = [](double px, double py, double qx, double qy, double rx, double ry) {
    return (qx - px) * (ry - py) - (qy - py) * (rx - px);
  };
  auto collinear_eps = [&](auto p, auto q, auto r) {
    return std::fabs(det(p[0], p[1], q[0], q[1], r[0], r[1])) <= eps;
  };
  const std::array<double, 2> p{0, 0}, q{1, 0}, r{1e6, 5e-10}, s{-1e6, 5e-10};
  //< eps-collinear
  std::cout << std::boolalpha << "collinear_eps(p, q, r) = " << collinear_eps(p, q, r)
            << ", collinear_eps(p, q, s) = " << collinear_eps(p, q, s)
            << ", collinear_eps(q, r, s) = " << collinear_eps(q, r, s) << " (its determinant is "
            << det(q[0], q[1], r[0], r[1], s[0], s[1]) << ")\n";
  auto P = [](std::array<double, 2> v) { return t2::Point::cartesian(v[0], v[1]); };
  std::cout << "exact orient: (p, q, r) " << t2::to_symbol(t2::orient(P(p), P(q), P(r))) << ", (p, q, s) "
            << t2::to_symbol(t2::orient(P(p), P(q), P(s))) << ", (q, r, s) "
            << t2::to_symbol(t2::orient(P(q), P(r), P(s))) << "\n";
  // Scale: the same four points in millimetres instead of metres change the verdicts.
  const double k = 1000;
  const std::array<double, 2> qk{q[0] * k, q[1] * k}, rk{r[0] * k, r[1] * k};
  std::cout << "scaled by 1000: collinear_eps(p, q, r) = " << collinear_eps(p, qk, rk) << "\n"
            << std::noboolalpha << '\n';
}

// ---------------------------------------------------------------------------------------------
// 4. Exact integers: what a double really is.

void exact_integers() {
  std::cout << "== 4b. Every double is an exact dyadic rational: t2::to_exact\n";
  //> to-exact
  const t2::Point p(1, 0.1, 0.2);
  const t2::ExactPoint e = t2::to_exact(p);  // the same point, integer coordinates
  //< to-exact
  std::cout << "to_exact([1, 0.1, 0.2]) = " << t2::to_string(e) << "\n";
  std::cout << "so 0.1 is really " << t2::to_string(e.x()) << "/" << t2::to_string(e.w()) << "\n";
  //> not-collinear
  // "On the line x + y = 1":
  const t2::Point a(1, 0.1, 0.9), b(1, 0.2, 0.8), c(1, 0.3, 0.7);
  //< not-collinear
  const t2::Rational det = t2::to_rational(0.2) * t2::to_rational(0.7) - t2::to_rational(0.8) * t2::to_rational(0.3) -
                           (t2::to_rational(0.1) * t2::to_rational(0.7) - t2::to_rational(0.9) * t2::to_rational(0.3)) +
                           (t2::to_rational(0.1) * t2::to_rational(0.8) - t2::to_rational(0.9) * t2::to_rational(0.2));
  std::cout << "orient([1,0.1,0.9], [1,0.2,0.8], [1,0.3,0.7]) = " << t2::to_symbol(t2::orient(a, b, c))
            << "; the exact determinant of those doubles is " << det.get_str() << " = " << det.get_d() << "\n\n";
}

// ---------------------------------------------------------------------------------------------
// 5. The filter: how often does it need GMP?

std::uint64_t next_bits(std::mt19937_64& g) { return g(); }
// A double uniform in [-1, 1): 53 random bits, exact arithmetic, same on every platform.
double uniform(std::mt19937_64& g) { return std::ldexp(static_cast<double>(next_bits(g) >> 11), -52) - 1.0; }

struct Count {
  std::uint64_t calls, exact;
};

template <class Body>
Count counted(Body body) {
  auto& st = t2::filter_stats();
  st.reset();
  body();
  return {static_cast<std::uint64_t>(st.calls), static_cast<std::uint64_t>(st.exact)};
}

void filter_costs(const SignMap&) {
  std::cout << "== 5. How often the fast path cannot decide (t2::filter_stats())\n";
  std::mt19937_64 g(2026);
  const int n = 100000;
  //> filter-random
  const Count random = counted([&] {
    for (int i = 0; i < n; ++i)
      (void)t2::orient(t2::Point(uniform(g), uniform(g), uniform(g)),
                       t2::Point(uniform(g), uniform(g), uniform(g)),
                       t2::Point(uniform(g), uniform(g), uniform(g)));
  });
  //< filter-random
  const Count grid = counted([] { (void)sign_map(); });
  //> filter-near
  // Nearly degenerate: r is the rounded point s of the way from p to q, so it is off the
  // line pq by at most a few units in the last place.
  const Count near = counted([&] {
    for (int i = 0; i < n; ++i) {
      const double px = 100 * uniform(g), py = 100 * uniform(g), qx = 100 * uniform(g),
                   qy = 100 * uniform(g);
      const double s = 0.5 * (uniform(g) + 1);
      (void)t2::orient(t2::Point::cartesian(px, py), t2::Point::cartesian(qx, qy),
                       t2::Point::cartesian(px + s * (qx - px), py + s * (qy - py)));
    }
  });
  //< filter-near
  //> filter-degenerate
  // Exactly degenerate: r = a p + b q with small integers, so Δ(p, q, r) = 0 exactly.
  const Count degenerate = counted([&] {
    for (int i = 0; i < n; ++i) {
      auto small = [&] { return std::floor(1000 * uniform(g)); };
      const double a = small(), b = small();
      const t2::Point p(small(), small(), 1000 + small()),
          q(small(), small(), 3000 + small());
      (void)t2::orient(p, q, t2::mix(a, p, b, q));
    }
  });
  //< filter-degenerate
  // The same triples divided by 1024: still exactly collinear, but no longer integers.
  const Count dyadic = counted([&] {
    for (int i = 0; i < n; ++i) {
      auto small = [&] { return std::floor(1000 * uniform(g)) / 1024; };
      const double a = std::floor(1000 * uniform(g)), b = std::floor(1000 * uniform(g));
      const t2::Point p(small(), small(), 1 + small()), q(small(), small(), 3 + small());
      (void)t2::orient(p, q, t2::mix(a, p, b, q));
    }
  });
  // One evaluation of the fast path, opened up: the value and the bound, by the library's code.
  auto show = [](const char* name, const t2::Point& p, const t2::Point& q, const t2::Point& r) {
    //> filter-worked
    const auto [value, bound] =
        t2::detail::orient2_filter(p.x(), p.y(), q.x(), q.y(), r.x(), r.y());
    //< filter-worked
    std::printf("%-20s value = %-24.17g bound = %-10.3g  %s\n", name, value, bound,
                std::fabs(value) > bound ? "certain" : "uncertain: exact stage");
  };
  show("a random triple", t2::Point(1, 0.25, -0.5), t2::Point(1, 0.75, 0.125), t2::Point(1, -0.375, 0.5));
  show("grid cell (3, 200)", t2::Point::cartesian(0.5 + 3 * 0x1p-53, 0.5 + 200 * 0x1p-53), t2::Point::cartesian(12, 12),
       t2::Point::cartesian(24, 24));
  // Expansion arithmetic on two small examples, then the grid cell's determinant exactly.
  {
    using namespace t2::expansion;
    //> expansion-worked
    double x, y;
    two_sum(0.1, 0.2, x, y);  // 0.1 + 0.2 = x + y exactly
    std::printf("two_sum(0.1, 0.2)    x = %.17g  y = %.17g\n", x, y);
    two_prod(0.1, 0.1, x, y);  // 0.1 * 0.1 = x + y exactly
    std::printf("two_prod(0.1, 0.1)   x = %.17g  y = %.17g\n", x, y);
    const double px = 0.5 + 3 * 0x1p-53, py = 0.5 + 200 * 0x1p-53;  // the grid cell (3, 200)
    const auto det = diff(12, px) * diff(24, py) - diff(12, py) * diff(24, px);
    std::printf(
        "grid cell (3, 200)   det = %.17g (rounded sum of %d components), sign %+d\n",
        det.estimate(), det.n, static_cast<int>(det.sign()));
    //< expansion-worked
    for (int i = 0; i < det.n; ++i) std::printf("  component %d: %a\n", i, det.c[i]);
  }
  auto row = [](const char* name, Count c) {
    std::printf("%-22s %7llu calls %7llu exact  (%7.3f%%)\n", name, static_cast<unsigned long long>(c.calls),
                static_cast<unsigned long long>(c.exact), 100.0 * static_cast<double>(c.exact) / static_cast<double>(c.calls));
  };
  row("random in [-1,1)^3", random);
  row("the 256x256 grid", grid);
  row("nearly collinear", near);
  row("collinear, integers", degenerate);
  row("collinear, /1024", dyadic);
  std::cout << '\n';
}

// ---------------------------------------------------------------------------------------------
// Figures.

// The sign map as a raster of cells, y up; horizontal runs of one colour are merged.
std::string raster_svg(const std::vector<int>& s, int n, const std::string& title) {
  const int cell = 2, margin = 4;
  const int size = n * cell + 2 * margin;
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << size << "\" height=\"" << size + 18
    << "\" viewBox=\"0 0 " << size << ' ' << size + 18 << "\">\n<title>" << title << "</title>\n";
  o << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  namespace pal = t2::draw::palette;
  auto colour = [](int v) { return v > 0 ? pal::positive : v < 0 ? pal::negative : pal::zero; };
  for (int j = 0; j < n; ++j) {
    int i = 0;
    while (i < n) {
      int k = i;
      while (k < n && s[j * n + k] == s[j * n + i]) ++k;
      o << "<rect x=\"" << margin + i * cell << "\" y=\"" << margin + (n - 1 - j) * cell << "\" width=\""
        << (k - i) * cell << "\" height=\"" << cell << "\" fill=\"" << colour(s[j * n + i]) << "\"/>\n";
      i = k;
    }
  }
  o << "<text x=\"" << size / 2 << "\" y=\"" << size + 13
    << "\" font-family=\"sans-serif\" font-size=\"12\" text-anchor=\"middle\">" << title << "</text>\n</svg>\n";
  return o.str();
}

// The clipping example in both models of T² (t2::draw): the same points, lines and segments.
t2::draw::Figure clipping_figure() {
  namespace dr = t2::draw;
  namespace pal = t2::draw::palette;
  using P = t2::Point;
  const P A = P::cartesian(2, 2), B = P::cartesian(9, 5), C = P::cartesian(8, 2), D = P::cartesian(6, 5),
          E = P::cartesian(4, 1), F = P::cartesian(5, 6);
  const P H = t2::meet(t2::join(A, B), t2::join(C, D)), G = t2::meet(t2::join(A, B), t2::join(E, F));
  dr::Figure f;
  f.segment(A, B, dr::Style().width(2));
  f.segment(C, D, dr::Style().color(pal::blue).width(2));
  f.segment(E, F, dr::Style().color(pal::red).width(2));
  f.add(A, dr::Style().label("A").label_angle(-135));
  f.add(B, dr::Style().label("B"));
  f.add(C, dr::Style().color(pal::blue).label("C").label_angle(-45));
  f.add(D, dr::Style().color(pal::blue).label("D"));
  f.add(E, dr::Style().color(pal::red).label("E").label_angle(-45));
  f.add(F, dr::Style().color(pal::red).label("F"));
  f.add(H, dr::Style().marker(dr::Marker::square).label("H").label_angle(-45));
  f.add(G, dr::Style().marker(dr::Marker::square).label("G").label_angle(135));
  return f;
}

void write_figures(const std::filesystem::path& dir, const SignMap& m) {
  int written = 0;
  written += t2::update_file_atomically(dir / "signmap-naive.svg", raster_svg(m.naive, m.n, "naive double orient"));
  written += t2::update_file_atomically(dir / "signmap-exact.svg", raster_svg(m.exact, m.n, "exact t2::orient"));
  t2::draw::PlaneView plane;
  plane.cx = 5.5;
  plane.cy = 3.5;
  plane.half_width = 4.5;
  written += t2::draw::save(clipping_figure(), plane, dir / "clipping-plane.svg");
  t2::draw::SphereView sphere;  // look straight at the cluster: azimuth of (5.5, 3.5), low latitude
  sphere.lat = 10;
  sphere.lon = 32;
  written += t2::draw::save(clipping_figure(), sphere, dir / "clipping-sphere.svg");
  std::cout << "figures: 4 in " << dir.filename().string() << "\n";
  std::cerr << written << " figure file(s) rewritten\n";  // depends on the directory: not stdout
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path figures = T2_FIGURES_DIR;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--figures" && i + 1 < argc) {
      figures = argv[++i];
    } else {
      std::cerr << "usage: chapter_04 [--figures DIR]\n";
      return 2;
    }
  }
  clipping_in_float();
  const SignMap m = sign_map();
  print_sign_map(m);
  tolerances();
  clipping_in_t2();
  exact_integers();
  filter_costs(m);
  write_figures(figures, m);
}
