// The freeform stage's scales where the noise varies over the cloud (fit/splines/
// freeform_detection.h). A stereo or structured-light scan measures depth with an error that
// grows with the square of the range: on the PCL table-top scan the local-plane noise is 1.9e-4
// within 0.8 m of the camera and 1.07e-3 beyond 2 m, so the detector's one sigma (3.4e-4, a
// median over the cloud) puts the far wall's points outside any band tau = 3 sigma and its
// normals (noisier by the same ratio over a coarser spacing) outside the normal band.
// From each point's nearest neighbours:
//   r_i  the distance of p_i to the least-squares plane through it and its first k = 12
//        neighbours (fewer when it has fewer, at least 3); for independent noise sigma along the
//        normal of a plane E[r_i^2] = sigma^2 (k - 2) / (k + 1) (the point's own leverage in a
//        3-parameter fit, averaged), so q_i = r_i^2 (k + 1) / (k - 2) estimates sigma^2;
//   a_i  the median angle between n_i and its first 8 neighbours' normals (as the detector's
//        normal band, fit/detect/detection_scales.h).
// (The detector's mid-normal figure, fit/detect/surface_noise.h, is free of the curvature term
// but also reads the normals' error times the spacing; with it in place of q_i, at an early
// stage of this code, the table-top scan's patches ended at pooled RMS 2.05 sigma_plane against
// 1.86 with q_i. q_i is the benchmark's own noise figure, bench/freeform_scans.cc: the stage
// takes its median over a part, the benchmark reports its mean over the assigned points.)
// A part P of the cloud (a region or a piece of one) then has the detector's scales
// (fit/detect/detection_scales.h) computed over P alone:
//   sigma_P = sqrt(median_{i in P} q_i / 0.4549)  (0.4549: the median of chi^2_1),
//   tau_P = max(3 sigma_P, 0.1 s),  theta_P = clamp(3 median_{i in P} a_i, theta, 45 deg),
//   s_P = clamp(sigma_P, tau_P / 10, tau_P / 3)  (the likelihood scale and the RMS bound 2 s_P)
// and fills a volume rather than sampling a surface when, as the detector's test of a whole cloud,
// 1.4826 median t_i > 0.4 s_6 and median a_i > 15 deg (t_i: the median over the first 8
// neighbours of |n_i . (p_j - p_i)|, s_6: the median over P of the distance to the 6th
// neighbour); with s the sampling spacing and theta the detection's normal band; without a spacing
// (s = 0) sigma_P and tau_P are never below the detection's sigma and tau. Two neighbours join a
// smooth region when their normals differ by less than max(theta_i, theta_j), theta_i = clamp(3
// a_i, theta, 45 deg). The plane figure keeps the surface's sagitta (about kappa rho^2 / 2 for
// curvature kappa over a neighbourhood of radius rho): it can only widen a curved part's band.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "datasets/clouds/neighbour_graph.h"

namespace implicitfit {

struct LocalScaleFigures {
  std::vector<double> noise;     // q_i (-1: under 3 neighbours)
  std::vector<double> angle;     // a_i, radians (0: no neighbour)
  std::vector<double> cos_band;  // cos theta_i
  std::vector<double> spacing;   // distance to the 6th neighbour (-1: fewer neighbours)
  std::vector<double> tangent;   // t_i
};

struct PartScales {
  double noise = 0.0;             // sigma_P
  double threshold = 0.0;         // tau_P
  double cos_normal_angle = 1.0;  // cos theta_P
  double likelihood_sigma = 0.0;  // s_P
  bool volume = false;
};

// The detection's scales: sigma, tau, theta (> 0) and the spacing s (>= 0).
struct DetectionBands {
  double noise = 0.0, threshold = 0.0, normal_angle_deg = 0.0, spacing = 0.0;
};

// normal_angle_deg: theta.
LocalScaleFigures ComputeLocalScaleFigures(const std::vector<Eigen::Vector3d>& points,
                                           const std::vector<Eigen::Vector3d>& normals,
                                           const NeighbourGraph& neighbours,
                                           double normal_angle_deg);

PartScales ScalesOfPart(const LocalScaleFigures& figures, const std::vector<int>& part,
                        const DetectionBands& detection);

}  // namespace implicitfit
