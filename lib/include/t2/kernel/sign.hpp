#pragma once
/// @file sign.hpp
/// @brief The three-valued result of every predicate of T².

namespace t2 {

/// The exact sign of a predicate: it converts to `int` as -1, 0 or +1.
enum Sign : int { NEGATIVE = -1, ZERO = 0, POSITIVE = 1 };

/// The sign of the opposite quantity.
constexpr Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }

/// The sign of a product.
constexpr Sign operator*(Sign a, Sign b) {
  return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b));
}

/// The sign of a value of an ordered type.
template <class T>
constexpr Sign sign_of(const T& v) {
  return v > 0 ? POSITIVE : (v < 0 ? NEGATIVE : ZERO);
}

/// `"-"`, `"0"` or `"+"`.
constexpr const char* to_symbol(Sign s) { return s > 0 ? "+" : (s < 0 ? "-" : "0"); }

}  // namespace t2
