#pragma once
// Chapter 15's example points and its figures (both models).
#include <t2/t2.hpp>

#include <filesystem>
#include <vector>

namespace chapter15 {

/// Five front points with distinct coordinates −2..2 in x and in y.
std::vector<t2::Point> five_points();
/// Points on the front, on the back and on Ω, for the rectangles of T².
std::vector<t2::Point> mixed_points();

/// Writes the chapter's figures into `dir`.
void figures(const std::filesystem::path& dir);

}  // namespace chapter15
