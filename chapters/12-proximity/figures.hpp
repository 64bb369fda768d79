#pragma once
// Chapter 12's example sites and its figures (both models).
#include <t2/t2.hpp>

#include <filesystem>
#include <vector>

namespace chapter12 {

/// Eight sites: four on the front, two on the back, two on Ω.
std::vector<t2::Point> small_sites();

/// Writes the chapter's figures into `dir`.
void figures(const std::filesystem::path& dir);

}  // namespace chapter12
