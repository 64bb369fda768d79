// What exactness costs: t2::orient (filtered) against the naive double determinant, the
// always-exact GMP rational evaluation and integer points, on three kinds of input.
//   build/default/bin/bench_predicates --benchmark_counters_tabular=true
// The counter `exact_rate` is the fraction of calls in which the filter could not decide and
// GMP ran (t2::filter_stats()).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "t2/t2.hpp"

namespace {

using t2::Point;

struct Triple {
  Point p, q, r;
};

enum Kind { kRandom, kGrid, kNearlyCollinear };

std::vector<Triple> make_input(Kind kind, std::size_t n) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1, 1), t(0, 1);
  std::uniform_int_distribution<int> g(0, 15);
  std::vector<Triple> v;
  v.reserve(n);
  while (v.size() < n) {
    if (kind == kRandom) {
      v.push_back({Point(1, u(rng), u(rng)), Point(1, u(rng), u(rng)), Point(1, u(rng), u(rng))});
    } else if (kind == kGrid) {
      // A 16×16 integer grid: about 1 triple in 20 is exactly collinear.
      v.push_back({Point(1, g(rng), g(rng)), Point(1, g(rng), g(rng)), Point(1, g(rng), g(rng))});
    } else {
      // r is the rounded point (1-s)p + sq: collinear up to the last bit.
      const double px = u(rng), py = u(rng), qx = u(rng), qy = u(rng), s = t(rng);
      v.push_back({Point(1, px, py), Point(1, qx, qy), Point(1, px + s * (qx - px), py + s * (qy - py))});
    }
  }
  return v;
}

double naive_det(const Point& p, const Point& q, const Point& r) {
  return t2::det3(p.w(), p.x(), p.y(), q.w(), q.x(), q.y(), r.w(), r.x(), r.y());
}

template <Kind K>
void BM_orient_naive_double(benchmark::State& state) {
  const auto in = make_input(K, 4096);
  std::size_t i = 0;
  for (auto _ : state) {
    const Triple& t = in[i++ & 4095];
    benchmark::DoNotOptimize(naive_det(t.p, t.q, t.r) > 0);
  }
}

template <Kind K>
void BM_orient_filtered(benchmark::State& state) {
  const auto in = make_input(K, 4096);
  auto& stats = t2::filter_stats();
  stats.reset();
  std::size_t i = 0;
  for (auto _ : state) {
    const Triple& t = in[i++ & 4095];
    benchmark::DoNotOptimize(t2::orient(t.p, t.q, t.r));
  }
  state.counters["exact_rate"] = double(stats.exact) / double(std::max<std::uint64_t>(1, stats.calls));
}

// The exact stage alone, on GMP rationals (the test suite's oracle) and on the dyadic numbers
// the filter falls back to.
template <Kind K>
void BM_orient_rational_always(benchmark::State& state) {
  const auto in = make_input(K, 4096);
  std::size_t i = 0;
  for (auto _ : state) {
    const Triple& t = in[i++ & 4095];
    using R = t2::Exact<t2::Rational>;
    auto q = [](double x) { return R(t2::to_rational(x)); };
    benchmark::DoNotOptimize(t2::sign_of(
        t2::det3(q(t.p.w()), q(t.p.x()), q(t.p.y()), q(t.q.w()), q(t.q.x()), q(t.q.y()), q(t.r.w()), q(t.r.x()), q(t.r.y())).v));
  }
}

template <Kind K>
void BM_orient_dyadic_always(benchmark::State& state) {
  const auto in = make_input(K, 4096);
  std::size_t i = 0;
  for (auto _ : state) {
    const Triple& t = in[i++ & 4095];
    using D = t2::Dyadic;
    benchmark::DoNotOptimize(t2::sign_of(
        t2::det3(D(t.p.w()), D(t.p.x()), D(t.p.y()), D(t.q.w()), D(t.q.x()), D(t.q.y()), D(t.r.w()), D(t.r.x()), D(t.r.y()))));
  }
}

template <Kind K>
void BM_orient_integer_points(benchmark::State& state) {
  const auto in = make_input(K, 4096);
  std::vector<std::array<t2::ExactPoint, 3>> ex;
  for (const auto& t : in) ex.push_back({t2::to_exact(t.p), t2::to_exact(t.q), t2::to_exact(t.r)});
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& t = ex[i++ & 4095];
    benchmark::DoNotOptimize(t2::orient(t[0], t[1], t[2]));
  }
}

// How often the naive double sign is wrong on each input (not a timing: a counter).
template <Kind K>
void BM_naive_sign_errors(benchmark::State& state) {
  const auto in = make_input(K, 4096);
  std::size_t wrong = 0;
  for (auto _ : state) {
    wrong = 0;
    for (const auto& t : in) {
      const double d = naive_det(t.p, t.q, t.r);
      const t2::Sign naive = d > 0 ? t2::POSITIVE : (d < 0 ? t2::NEGATIVE : t2::ZERO);
      wrong += naive != t2::orient(t.p, t.q, t.r);
    }
  }
  state.counters["wrong_rate"] = double(wrong) / double(in.size());
}

}  // namespace

BENCHMARK(BM_orient_naive_double<kRandom>)->Name("naive_double/random");
BENCHMARK(BM_orient_naive_double<kGrid>)->Name("naive_double/grid");
BENCHMARK(BM_orient_naive_double<kNearlyCollinear>)->Name("naive_double/nearly_collinear");
BENCHMARK(BM_orient_filtered<kRandom>)->Name("t2_orient/random");
BENCHMARK(BM_orient_filtered<kGrid>)->Name("t2_orient/grid");
BENCHMARK(BM_orient_filtered<kNearlyCollinear>)->Name("t2_orient/nearly_collinear");
BENCHMARK(BM_orient_rational_always<kRandom>)->Name("gmp_rational/random");
BENCHMARK(BM_orient_dyadic_always<kNearlyCollinear>)->Name("gmp_dyadic/nearly_collinear");
BENCHMARK(BM_orient_rational_always<kNearlyCollinear>)->Name("gmp_rational/nearly_collinear");
BENCHMARK(BM_orient_integer_points<kRandom>)->Name("integer_points/random");
BENCHMARK(BM_orient_integer_points<kGrid>)->Name("integer_points/grid");
BENCHMARK(BM_naive_sign_errors<kRandom>)->Name("naive_wrong/random")->Iterations(1);
BENCHMARK(BM_naive_sign_errors<kGrid>)->Name("naive_wrong/grid")->Iterations(1);
BENCHMARK(BM_naive_sign_errors<kNearlyCollinear>)->Name("naive_wrong/nearly_collinear")->Iterations(1);
