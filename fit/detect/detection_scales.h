// The scales of a detection, from the data (fit/detect/primitive_detector.h documents their
// use; `fit --model KIND` checks its result with the same figures, fit/detect/checked_fit.h):
//   s      the sampling spacing (given: the median 6th-neighbour distance);
//   sigma  the noise: fit/detect/surface_noise.h (mid-normal distances of the 8 nearest
//          neighbours, robust median), on an evenly spread subset of at most ~20 000 points;
//   tau    the distance band: max(3 sigma, 0.1 s) unless a threshold is given;
//   theta  the normal band: max(20 deg, 3 x the median angle between neighbouring normals),
//          at most 45 deg, unless given;
//   volume the cloud fills a volume (tangent-plane noise > 0.4 s and median neighbour normal
//          angle > 15 deg: uniform random points read 0.58 s), unless a threshold is given.
// The likelihood scale of the kind selection is sigma clamped to [tau / 10, tau / 3].
#pragma once

#include <Eigen/Core>
#include <vector>

#include "datasets/clouds/neighbour_graph.h"

namespace implicitfit {

// The volume test's limits (above): tangent-plane noise over this x spacing and a median
// neighbour normal angle over this many degrees (also the freeform stage's, per part:
// fit/splines/local_scales.h).
constexpr double kVolumeNoiseToSpacing = 0.4;
constexpr double kVolumeNormalAngleDeg = 15.0;

struct DetectionScales {
  double spacing = 0.0;
  double noise = 0.0;             // sigma
  double threshold = 0.0;         // tau
  double normal_angle_deg = 0.0;  // theta
  double likelihood_sigma = 0.0;  // sigma clamped to [tau / 10, tau / 3]
  bool volume = false;            // no surface at the sampling scale
};

// points: the cloud (recentred for precision far from the origin); threshold, normal_angle_deg:
// <= 0 for "from the data".
DetectionScales EstimateDetectionScales(const std::vector<Eigen::Vector3d>& points,
                                        const std::vector<Eigen::Vector3d>& normals,
                                        const NeighbourGraph& neighbours, double spacing,
                                        double threshold = 0.0, double normal_angle_deg = 0.0);

}  // namespace implicitfit
