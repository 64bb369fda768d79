#pragma once
// The peers of the problem `range` (`t2 bench kdtree`; the worker's runs): nanoflann's
// kd-tree and Boost.Geometry's rtree, each built on the points (w = 1, so x and y are the
// drawn doubles) and asked every window of range_windows, reporting the indices inside it.
// Comparisons of doubles are exact, so both answer exactly what t2's structures answer.
//
// nanoflann 1.4 has k-nearest and radius searches only. A window query is its radius search
// with radius 1/2 under a metric that is, per coordinate, 0 when the coordinate is inside the
// window and 1 when it is outside (the window lives in the dataset adaptor, which nanoflann
// hands to the metric). The sum over the coordinates is 0 exactly for the points inside. Its
// pruning stays right: nanoflann enters the child on the side of the query's centre always, and
// the other one unless the cut (the nearest coordinate of that child's points) is outside the
// window, when no point of that child is inside.

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <nanoflann.hpp>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "algorithms/range.hpp"
#include "t2/kernel/point.hpp"

namespace t2bench {

// The points for nanoflann, with the window of the current query.
struct WindowCloud {
  std::vector<double> xy;  // x0 y0 x1 y1 ...
  std::array<double, 4> window{};
  std::size_t kdtree_get_point_count() const { return xy.size() / 2; }
  double kdtree_get_pt(std::size_t i, std::size_t d) const { return xy[2 * i + d]; }
  template <class B>
  bool kdtree_get_bbox(B&) const {
    return false;
  }
};

// The 0/1 window metric (file comment).
template <class T, class DataSource, class DistanceType_ = T>
struct WindowMetric {
  using ElementType = T;
  using DistanceType = DistanceType_;
  const DataSource& data;
  explicit WindowMetric(const DataSource& d) : data(d) {}
  DistanceType evalMetric(const T*, std::size_t i, std::size_t) const {
    return accum_dist(T(), data.kdtree_get_pt(i, 0), 0) + accum_dist(T(), data.kdtree_get_pt(i, 1), 1);
  }
  template <class U, class V>
  DistanceType accum_dist(const U, const V c, std::size_t d) const {
    return c < data.window[d] || c > data.window[d + 2] ? 1 : 0;
  }
};

// Counts what a radius search finds, keeping the indices as t2 keeps its report.
struct Collect {
  std::vector<unsigned>& out;
  bool full() const { return false; }
  double worstDist() const { return 0.5; }
  bool addPoint(double, unsigned i) {
    out.push_back(i);
    return true;
  }
};

inline std::function<std::size_t()> range_peer(const std::string& impl, const std::vector<t2::Point>& P) {
  const auto W = std::make_shared<std::vector<std::array<double, 4>>>(t2cli::algorithms::range_windows(P));
  if (impl == "nanoflann") {
    auto cloud = std::make_shared<WindowCloud>();
    for (const auto& p : P) cloud->xy.insert(cloud->xy.end(), {p.x(), p.y()});
    return [cloud, W] {
      using Index = nanoflann::KDTreeSingleIndexAdaptor<WindowMetric<double, WindowCloud>, WindowCloud, 2, unsigned>;
      Index index(2, *cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
      index.buildIndex();
      std::size_t k = 0;
      std::vector<unsigned> out;
      for (const auto& w : *W) {
        cloud->window = w;
        const double centre[2] = {(w[0] + w[2]) / 2, (w[1] + w[3]) / 2};
        out.clear();
        Collect c{out};
        index.findNeighbors(c, centre, nanoflann::SearchParams());
        k += out.size();
      }
      return k;
    };
  }
  if (impl == "rtree") {
    namespace bg = boost::geometry;
    using P2 = bg::model::point<double, 2, bg::cs::cartesian>;
    using Value = std::pair<P2, unsigned>;
    auto V = std::make_shared<std::vector<Value>>();
    for (unsigned i = 0; i < P.size(); ++i) V->emplace_back(P2(P[i].x(), P[i].y()), i);
    return [V, W] {
      const bg::index::rtree<Value, bg::index::rstar<16>> tree(V->begin(), V->end());  // bulk loading
      std::size_t k = 0;
      std::vector<Value> out;
      for (const auto& w : *W) {
        out.clear();
        tree.query(bg::index::covered_by(bg::model::box<P2>(P2(w[0], w[1]), P2(w[2], w[3]))), std::back_inserter(out));
        k += out.size();
      }
      return k;
    };
  }
  return nullptr;
}

}  // namespace t2bench
