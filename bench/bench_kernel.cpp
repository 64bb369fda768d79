// The kernel's predicates (orient, in_circle, compare_distance, compare_xy, side) against naive
// double arithmetic and CGAL 5.5's Exact_predicates_inexact_constructions_kernel (orientation,
// side_of_oriented_circle, compare_distance_to_point, compare_xy, Line_2::oriented_side), in one
// run, on front (Cartesian) points; then side and compare_distance on homogeneous points (every
// point [w, w·x, w·y] with its own weight, |w| in [0.5, 2], of either sign), where Epick has no
// equivalent (its points are Cartesian): against naive double only.
//   cmake --build --preset default --target bench_kernel && build/default/bin/bench_kernel
// Prints, per predicate and input, the processor time per call of each (best of 5 passes of 10⁶
// calls over 2048 inputs)
// and the ratios t2/naive and t2/CGAL. bench_kernel_stats is the same program built with
// T2_FILTER_STATS: it prints how often t2 needed an exact stage instead of timing.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "t2/kernel/distance.hpp"
#include "t2/kernel/incircle.hpp"
#include "t2/kernel/lexicographic.hpp"
#include "t2/kernel/line.hpp"
#include "t2/kernel/orient.hpp"

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

struct Quad {
  t2::Point p[4];     // Cartesian (w = 1)
  K::Point_2 c[4];    // the same for CGAL
  t2::Line l;         // the line through p[0] and p[1], rounded (W = x₀y₁ − y₀x₁, X = y₀ − y₁, Y = x₁ − x₀)
  K::Line_2 cl;       // the same line for CGAL: X·x + Y·y + W = 0
  t2::Point h[4];     // p[i] as [w, w·x, w·y] with a random weight of either sign (rounded)
};

// The inputs as each implementation reads them: one array per kind of object, as an algorithm
// holds its points. (One array of Quads made every predicate stride over the others' data, and
// the timings then depended on the Quad's size: t2's orient went from 2.4 to 2.7 ns when the
// lines and the weighted points were added.)
struct Input {
  std::vector<std::array<t2::Point, 4>> p;
  std::vector<std::array<K::Point_2, 4>> c;
  std::vector<t2::Line> l;
  std::vector<K::Line_2> cl;
  std::vector<std::array<t2::Point, 4>> h;
  std::size_t size() const { return p.size(); }
  void push_back(const Quad& q) {
    p.push_back({q.p[0], q.p[1], q.p[2], q.p[3]});
    c.push_back({q.c[0], q.c[1], q.c[2], q.c[3]});
    l.push_back(q.l);
    cl.push_back(q.cl);
    h.push_back({q.h[0], q.h[1], q.h[2], q.h[3]});
  }
};

// The kinds of input of the issue.
// kEquidistant is for the distance comparison only: p[0] and p[1] rounded onto one circle around
// p[2], then p[1] moved by a few ulps, so that their distances to p[2] differ by a few ulps.
enum Kind { kUniform, kLine, kCircle, kGrid, kBig, kSmall, kEquidistant };
const char* const kKindNames[] = {"uniform [-1,1]^2", "rounded onto a line", "rounded onto a circle",
                                  "small integer grid", "near 2^60", "near 2^-60", "nearly equidistant"};

Quad make_quad(const double (&xy)[4][2], std::mt19937_64& rng) {
  const t2::Point o(1, 0, 0);
  Quad q{{o, o, o, o}, {}, t2::omega(), {}, {o, o, o, o}};
  std::uniform_real_distribution<double> wt(0.5, 2);
  for (int i = 0; i < 4; ++i) {
    q.p[i] = t2::Point::cartesian(xy[i][0], xy[i][1]);
    q.c[i] = K::Point_2(xy[i][0], xy[i][1]);
    const double w = (rng() & 1 ? 1 : -1) * wt(rng);
    q.h[i] = t2::Point(w, w * xy[i][0], w * xy[i][1]);
  }
  const double W = xy[0][0] * xy[1][1] - xy[0][1] * xy[1][0], X = xy[0][1] - xy[1][1], Y = xy[1][0] - xy[0][0];
  if (W != 0 || X != 0 || Y != 0) {  // else p[0] = p[1]: keep Ω = <1, 0, 0> on both sides
    q.l = t2::Line(W, X, Y);
    q.cl = K::Line_2(X, Y, W);
  } else {
    q.cl = K::Line_2(0, 0, 1);
  }
  return q;
}

Input make_input(Kind kind, std::size_t n) {
  std::mt19937_64 rng(2026), weights(2027);  // the weights have their own generator
  std::uniform_real_distribution<double> u(-1, 1), t(0, 1), ang(0, 6.283185307179586);
  std::uniform_int_distribution<int> g(0, 15), ulps(-3, 3);
  Input v;
  while (v.size() < n) {
    double xy[4][2];
    if (kind == kLine) {  // four rounded points of the segment pq
      const double px = u(rng), py = u(rng), qx = u(rng), qy = u(rng);
      for (auto& p : xy) {
        const double s = t(rng);
        p[0] = px + s * (qx - px);
        p[1] = py + s * (qy - py);
      }
    } else if (kind == kCircle) {  // four rounded points of a circle
      const double cx = u(rng), cy = u(rng), r = 0.1 + t(rng);
      for (auto& p : xy) {
        const double a = ang(rng);
        p[0] = cx + r * std::cos(a);
        p[1] = cy + r * std::sin(a);
      }
    } else if (kind == kEquidistant) {  // p[0], p[1] at one distance from p[2], then a few ulps off
      const double cx = u(rng), cy = u(rng), r = 0.1 + t(rng);
      for (int i = 0; i < 4; ++i) {
        const double a = ang(rng);
        xy[i][0] = i == 2 ? cx : cx + r * std::cos(a);
        xy[i][1] = i == 2 ? cy : cy + r * std::sin(a);
      }
      for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) xy[1][0] = std::nextafter(xy[1][0], k > 0 ? 9.0 : -9.0);
    } else {
      const double scale = kind == kBig ? 0x1p60 : (kind == kSmall ? 0x1p-60 : 1.0);
      for (auto& p : xy) {
        p[0] = kind == kGrid ? g(rng) : scale * u(rng);
        p[1] = kind == kGrid ? g(rng) : scale * u(rng);
      }
    }
    const Quad q = make_quad(xy, weights);
    // in_circle needs a, b, c not collinear (it throws otherwise); CGAL's answer is then unspecified.
    if (t2::orient(q.p[0], q.p[1], q.p[2]) == t2::ZERO) continue;
    v.push_back(q);
  }
  return v;
}

// Every implementation timed is a lambda, so that the timing loop inlines each one alike (a
// function pointer would add an indirect call to one side only).
constexpr auto naive_orient = [](const Input& q, std::size_t i) {
  const t2::Point &p = q.p[i][0], &a = q.p[i][1], &b = q.p[i][2];
  const double d = (a.x() - p.x()) * (b.y() - p.y()) - (a.y() - p.y()) * (b.x() - p.x());
  return (d > 0) - (d < 0);
};

constexpr auto naive_incircle = [](const Input& q, std::size_t i) {
  const double dx = q.p[i][3].x(), dy = q.p[i][3].y();
  const double adx = q.p[i][0].x() - dx, ady = q.p[i][0].y() - dy, bdx = q.p[i][1].x() - dx, bdy = q.p[i][1].y() - dy,
               cdx = q.p[i][2].x() - dx, cdy = q.p[i][2].y() - dy;
  const double d = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                   (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
  return (d > 0) - (d < 0);
};

// Is p[0] nearer to p[2] than p[1] is? The squared distances compared in doubles.
constexpr auto naive_distance = [](const Input& q, std::size_t i) {
  const double ax = q.p[i][0].x() - q.p[i][2].x(), ay = q.p[i][0].y() - q.p[i][2].y(), bx = q.p[i][1].x() - q.p[i][2].x(),
               by = q.p[i][1].y() - q.p[i][2].y();
  const double d = (ax * ax + ay * ay) - (bx * bx + by * by);
  return (d > 0) - (d < 0);
};

// The same comparison by t2 and by CGAL.
constexpr auto t2_distance = [](const Input& q, std::size_t i) {
  return static_cast<int>(t2::compare_distance(q.p[i][0], q.p[i][1], q.p[i][2]));
};
constexpr auto cgal_distance = [](const Input& q, std::size_t i) {
  return static_cast<int>(CGAL::compare_distance_to_point(q.c[i][2], q.c[i][0], q.c[i][1]));
};

// The lexicographic (x, y) order of p[0] and p[1]: plain comparisons of doubles (exact).
constexpr auto naive_xy = [](const Input& q, std::size_t i) {
  const t2::Point &a = q.p[i][0], &b = q.p[i][1];
  if (a.x() != b.x()) return a.x() < b.x() ? -1 : 1;
  return (a.y() > b.y()) - (a.y() < b.y());
};

// side of p[2] against the line l through p[0] and p[1] (on a line input: p[2] within ulps of l).
constexpr auto naive_side = [](const Input& q, std::size_t i) {
  const double d = q.l[i].W() + q.l[i].X() * q.p[i][2].x() + q.l[i].Y() * q.p[i][2].y();
  return (d > 0) - (d < 0);
};
constexpr auto t2_side = [](const Input& q, std::size_t i) { return static_cast<int>(t2::side(q.l[i], q.p[i][2])); };
constexpr auto cgal_side = [](const Input& q, std::size_t i) { return static_cast<int>(q.cl[i].oriented_side(q.c[i][2])); };

// The same on homogeneous points: side(l, h[2]) and compare_distance(h[0], h[1], h[2]).
constexpr auto naive_side_h = [](const Input& q, std::size_t i) {
  const t2::Point& p = q.h[i][2];
  const double d = q.l[i].W() * p.w() + q.l[i].X() * p.x() + q.l[i].Y() * p.y();
  return (d > 0) - (d < 0);
};
constexpr auto t2_side_h = [](const Input& q, std::size_t i) { return static_cast<int>(t2::side(q.l[i], q.h[i][2])); };
// Naive: the sides of a, b relative to c, then the squared distances scaled by the weights.
constexpr auto naive_distance_h = [](const Input& q, std::size_t i) {
  const t2::Point &a = q.h[i][0], &b = q.h[i][1], &c = q.h[i][2];
  const int ra = (a.w() > 0) == (c.w() > 0), rb = (b.w() > 0) == (c.w() > 0);
  if (ra != rb) return ra ? -1 : 1;
  const double ex = a.x() * c.w() - c.x() * a.w(), ey = a.y() * c.w() - c.y() * a.w();
  const double fx = b.x() * c.w() - c.x() * b.w(), fy = b.y() * c.w() - c.y() * b.w();
  const double d = (ex * ex + ey * ey) * (b.w() * b.w()) - (fx * fx + fy * fy) * (a.w() * a.w());
  const int s = (d > 0) - (d < 0);
  return ra ? s : -s;
};
constexpr auto t2_distance_h = [](const Input& q, std::size_t i) {
  return static_cast<int>(t2::compare_distance(q.h[i][0], q.h[i][1], q.h[i][2]));
};

constexpr std::size_t kInput = 1 << 11;  // distinct inputs, cycled (they stay in the cache)
constexpr std::size_t kCalls = 1000000;  // calls per measurement

// The processor time of this thread (not wall time: the machine is shared, and time spent
// waiting for a core is not the predicate's).
double thread_cpu_ns() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return 1e9 * double(ts.tv_sec) + double(ts.tv_nsec);
}

// Nanoseconds per call: best of 5 passes of kCalls calls (the minimum is the least disturbed
// by the other processes of a shared machine).
template <class F>
[[gnu::noinline]] double time_per_call(const Input& in, F f, long& checksum) {
  double best = 1e30;
  for (int pass = 0; pass < 5; ++pass) {
    long sum = 0;
    const double t0 = thread_cpu_ns();
    for (std::size_t i = 0; i < kCalls; ++i) sum += f(in, i & (kInput - 1));
    best = std::min(best, (thread_cpu_ns() - t0) / kCalls);
    checksum += sum;
  }
  return best;
}

// No CGAL peer: the column stays empty.
struct NoPeer {};

// One row of the table: the three implementations on one input (two without a CGAL peer).
template <class N, class T, class C>
void run_row(const char* name, int k, const Input& in, long& checksum, N naive, T t2f, C cgal) {
  // The answers must agree with CGAL's everywhere (a free cross-check), and naive's may not.
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    if constexpr (!std::is_same_v<C, NoPeer>) {
      if (t2f(in, i) != cgal(in, i)) {
        std::fprintf(stderr, "t2 and CGAL disagree on %s, %s\n", name, kKindNames[k]);
        std::exit(1);
      }
    }
    wrong += naive(in, i) != t2f(in, i);
  }
#ifdef T2_FILTER_STATS
  (void)checksum;
  auto& st = t2::filter_stats();
  st.reset();
  for (std::size_t i = 0; i < in.size(); ++i) (void)t2f(in, i);
  std::printf("%-10s %-22s exact stage in %7.3f%% of %llu calls\n", name, kKindNames[k],
              100.0 * double(st.exact) / double(st.calls), static_cast<unsigned long long>(st.calls));
#else
  const double tn = time_per_call(in, naive, checksum), tt = time_per_call(in, t2f, checksum);
  if constexpr (std::is_same_v<C, NoPeer>) {
    std::printf("%-10s %-22s %9.2f %9.2f %9s %9.2f %9s %6.2f%%\n", name, kKindNames[k], tn, tt, "-", tt / tn, "-",
                100.0 * double(wrong) / double(in.size()));
  } else {
    const double tc = time_per_call(in, cgal, checksum);
    std::printf("%-10s %-22s %9.2f %9.2f %9.2f %9.2f %9.2f %6.2f%%\n", name, kKindNames[k], tn, tt, tc, tt / tn,
                tt / tc, 100.0 * double(wrong) / double(in.size()));
  }
#endif
}

}  // namespace

int main() {
#ifndef T2_FILTER_STATS
  std::printf("%-10s %-22s %9s %9s %9s %9s %9s %s\n", "predicate", "input", "naive ns", "t2 ns", "CGAL ns",
              "t2/naive", "t2/CGAL", "naive wrong");
#endif
  long checksum = 0;
  for (int k = kUniform; k <= kEquidistant; ++k) {
    const auto in = make_input(static_cast<Kind>(k), kInput);
    if (k == kEquidistant) {
      run_row("distance", k, in, checksum, naive_distance, t2_distance, cgal_distance);
      run_row("dist hom", k, in, checksum, naive_distance_h, t2_distance_h, NoPeer{});
      continue;
    }
    run_row("orient", k, in, checksum, naive_orient,
            [](const Input& q, std::size_t i) { return static_cast<int>(t2::orient(q.p[i][0], q.p[i][1], q.p[i][2])); },
            [](const Input& q, std::size_t i) { return static_cast<int>(CGAL::orientation(q.c[i][0], q.c[i][1], q.c[i][2])); });
    run_row("in_circle", k, in, checksum, naive_incircle,
            [](const Input& q, std::size_t i) { return static_cast<int>(t2::in_circle(q.p[i][0], q.p[i][1], q.p[i][2], q.p[i][3])); },
            [](const Input& q, std::size_t i) {
              return static_cast<int>(CGAL::side_of_oriented_circle(q.c[i][0], q.c[i][1], q.c[i][2], q.c[i][3]));
            });
    run_row("distance", k, in, checksum, naive_distance,
            t2_distance, cgal_distance);
    run_row("side", k, in, checksum, naive_side, t2_side, cgal_side);
    run_row("side hom", k, in, checksum, naive_side_h, t2_side_h, NoPeer{});
    run_row("dist hom", k, in, checksum, naive_distance_h, t2_distance_h, NoPeer{});
    run_row("xy", k, in, checksum, naive_xy,
            [](const Input& q, std::size_t i) { return static_cast<int>(t2::compare_xy(q.p[i][0], q.p[i][1])); },
            [](const Input& q, std::size_t i) { return static_cast<int>(CGAL::compare_xy(q.c[i][0], q.c[i][1])); });
  }
  std::fprintf(stderr, "(checksum %ld)\n", checksum);
}
