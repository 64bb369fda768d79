#pragma once
// Chapter 07's example shapes and its figures (both models).
#include <t2/t2.hpp>

#include <filesystem>
#include <vector>

namespace chapter07 {

/// A simple polygon with two pockets (counter-clockwise).
std::vector<t2::Point> pocket_polygon();
/// A centrally symmetric hexagon: its opposite edges are parallel.
std::vector<t2::Point> hexagon();
/// Front points (0,0), (6,2) and back points drawn at (-2,3), (5,-1).
std::vector<t2::Point> front_and_back();
/// Two reflex vertices facing each other: the kernel is a rhombus.
std::vector<t2::Point> hourglass();
/// A U: the two arms hide each other, the kernel is empty.
std::vector<t2::Point> u_shape();
/// A pinwheel whose inner edges lie on the axes: the kernel is one point.
std::vector<t2::Point> pinwheel();
/// An L-shaped corridor running off to +x and +y (two vertices on Ω): its kernel is bounded.
std::vector<t2::Point> corridor();
/// The upper half-plane with a triangular notch (three vertices on Ω): an unbounded kernel.
std::vector<t2::Point> notched_half_plane();

/// Writes the chapter's figures into `dir`.
void figures(const std::filesystem::path& dir);

}  // namespace chapter07
