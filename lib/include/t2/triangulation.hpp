#pragma once
/// @file triangulation.hpp
/// @brief Triangulations of T² (chapters 09 and 10): polygons by ear clipping, point sets by the
/// sweep and by Algorithm 9 on both sides of T², the compact `t2::Triangulation` that can be
/// queried, and the Delaunay triangulation (Lawson's flips, the randomized incremental
/// construction, divide and conquer, and the T² Delaunay with its ring at Ω).

#include "t2/triangulation/antipodal_edge.hpp"
#include "t2/triangulation/delaunay.hpp"
#include "t2/triangulation/delaunay_t2.hpp"
#include "t2/triangulation/divide.hpp"
#include "t2/triangulation/ear_clipping.hpp"
#include "t2/triangulation/face_kind.hpp"
#include "t2/triangulation/lawson.hpp"
#include "t2/triangulation/triangulate.hpp"
#include "t2/triangulation/triangulate_t2.hpp"
#include "t2/triangulation/triangulation.hpp"
