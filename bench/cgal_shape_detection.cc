#include "bench/cgal_shape_detection.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Shape_detection/Efficient_RANSAC.h>
#include <CGAL/property_map.h>

#include <chrono>

namespace implicitfit_bench {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// Each point carries its input index: detect() reorders the input range (CGAL's documentation of
// set_input), and the shapes' indices refer to the reordered range.
using Pwn = std::tuple<Kernel::Point_3, Kernel::Vector_3, std::size_t>;
using Pwns = std::vector<Pwn>;
using Traits = CGAL::Shape_detection::Efficient_RANSAC_traits<
    Kernel, Pwns, CGAL::Nth_of_tuple_property_map<0, Pwn>, CGAL::Nth_of_tuple_property_map<1, Pwn>>;
using Ransac = CGAL::Shape_detection::Efficient_RANSAC<Traits>;

}  // namespace

CgalDetection CgalEfficientRansac(const std::vector<Eigen::Vector3d>& points,
                                  const std::vector<Eigen::Vector3d>& normals,
                                  const CgalParameters& p) {
  using implicitfit::NodeType;
  Pwns pwn;
  pwn.reserve(points.size());
  Eigen::Vector3d lo = points[0], hi = points[0];
  for (size_t i = 0; i < points.size(); ++i) {
    pwn.emplace_back(Kernel::Point_3(points[i][0], points[i][1], points[i][2]),
                     Kernel::Vector_3(normals[i][0], normals[i][1], normals[i][2]), i);
    lo = lo.cwiseMin(points[i]);
    hi = hi.cwiseMax(points[i]);
  }
  const double diag = (hi - lo).norm();
  const auto start = std::chrono::steady_clock::now();
  Ransac ransac;
  ransac.set_input(pwn);
  ransac.add_shape_factory<CGAL::Shape_detection::Plane<Traits>>();
  ransac.add_shape_factory<CGAL::Shape_detection::Sphere<Traits>>();
  ransac.add_shape_factory<CGAL::Shape_detection::Cylinder<Traits>>();
  ransac.add_shape_factory<CGAL::Shape_detection::Cone<Traits>>();
  ransac.add_shape_factory<CGAL::Shape_detection::Torus<Traits>>();
  CgalDetection d;
  const auto in_time = [&](double) {
    d.stopped = p.max_seconds > 0 &&
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
                    p.max_seconds;
    return !d.stopped;
  };
  if (p.defaults) {
    ransac.detect(Ransac::Parameters(), in_time);
  } else {
    Ransac::Parameters params;
    params.probability = p.probability;
    params.min_points =
        std::max<std::size_t>(10, static_cast<std::size_t>(p.min_points_fraction * points.size()));
    params.epsilon = p.epsilon_fraction * diag;
    params.cluster_epsilon = p.cluster_epsilon_fraction * diag;
    params.normal_threshold = p.normal_threshold;
    ransac.detect(params, in_time);
  }
  d.labels.assign(points.size(), -1);
  for (const auto& shape : ransac.shapes()) {
    NodeType kind = NodeType::kPlane;
    if (dynamic_cast<CGAL::Shape_detection::Sphere<Traits>*>(shape.get())) kind = NodeType::kSphere;
    if (dynamic_cast<CGAL::Shape_detection::Cylinder<Traits>*>(shape.get()))
      kind = NodeType::kCylinder;
    if (dynamic_cast<CGAL::Shape_detection::Cone<Traits>*>(shape.get())) kind = NodeType::kCone;
    if (dynamic_cast<CGAL::Shape_detection::Torus<Traits>*>(shape.get())) kind = NodeType::kTorus;
    const int id = static_cast<int>(d.kinds.size());
    d.kinds.push_back(kind);
    for (std::size_t i : shape->indices_of_assigned_points()) d.labels[std::get<2>(pwn[i])] = id;
  }
  d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return d;
}

}  // namespace implicitfit_bench
