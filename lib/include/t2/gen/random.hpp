#pragma once
/// @file random.hpp
/// @brief The random source of the input generators: the same numbers on every machine.
///
/// `std::uniform_real_distribution`, `std::normal_distribution`, `std::uniform_int_distribution`
/// and `std::shuffle` are implementation-defined: two standard libraries give two different
/// streams from the same engine. The generators therefore draw raw 64-bit words from
/// `std::mt19937_64` (whose output the standard fixes) and turn them into numbers with the
/// transforms below, which use only integer arithmetic and exact scalings by powers of two.

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace t2::gen {

/// A seeded source of reproducible random numbers.
class Random {
 public:
  /// The stream of seed `seed` (std::mt19937_64 seeded with it).
  explicit Random(std::uint64_t seed) : engine_(seed) {}

  /// A raw 64-bit word.
  std::uint64_t bits() { return engine_(); }

  /// A uniform double in [0, 1): k·2⁻⁵³ for a uniform 53-bit integer k (exact).
  double unit() { return static_cast<double>(bits() >> 11) * 0x1p-53; }

  /// A uniform double in [-1, 1): (k − 2⁵²)·2⁻⁵² for a uniform 53-bit integer k (exact).
  double symmetric() { return static_cast<double>(static_cast<std::int64_t>(bits() >> 11) - (std::int64_t{1} << 52)) * 0x1p-52; }

  /// A uniform integer in [0, n), n > 0, without bias (rejection of the top remainder).
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
    for (;;) {
      const std::uint64_t r = bits();
      if (r < limit) return r % n;
    }
  }

  /// An approximately standard normal double: the sum of 12 uniform 40-bit fractions minus 6
  /// (Irwin–Hall; mean 0, variance 1, tails cut at ±6). Exact integer arithmetic, no
  /// logarithm or cosine, so that every machine gives the same bits.
  double normal() {
    std::int64_t s = 0;
    for (int i = 0; i < 12; ++i) s += static_cast<std::int64_t>(bits() >> 24);
    return static_cast<double>(s - 6 * (std::int64_t{1} << 40)) * 0x1p-40;
  }

  /// Fisher–Yates shuffle with `below` (std::shuffle's order differs between libraries).
  template <class T>
  void shuffle(std::vector<T>& v) {
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[below(i)]);
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace t2::gen
