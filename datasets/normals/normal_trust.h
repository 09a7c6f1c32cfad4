// Whether normals estimated by PCA (datasets/normals/normal_estimation.h) can be trusted, decided from
// the neighbourhood fits themselves. For each point, its neighbourhood (the one the estimation
// used, datasets/normals/neighbourhoods.h) with eigenvalues l0 <= l1 <= l2 of its covariance gives
//   share     = (neighbours + 1) / N       how much of the cloud the "local" fit saw
//   variation = l0 / (l0 + l1 + l2)        surface variation: 0 flat, 1/3 isotropic
// The normals are trusted when, at the median point, share <= 0.1 and variation <= 0.15.
// Why: a neighbourhood holding more than a tenth of the cloud is not local (10 probed points on
// a sphere: each neighbourhood is 9 of them and its "normal" is the direction the whole set is
// thinnest in; 8 points of a measured circle: the circle's plane normal, the cylinder's axis,
// orthogonal to the truth); a variation above 0.15 (l0 >= 0.35 l1 when l1 = l2) is a
// neighbourhood nearly as thick as it is wide, with no tangent plane. Dense scans pass (a
// neighbourhood is at most 30 points, variation about (rho/R)^2/24 + noise share).
// Clouds of more than 20000 points are not checked (every neighbourhood is then local).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "datasets/clouds/point_cloud.h"
#include "datasets/normals/neighbourhoods.h"

namespace implicitfit {

struct NormalTrust {
  bool trusted = true;
  double median_share = 0.0, median_variation = 0.0;
  std::string reason;  // why not, when not trusted
};

NormalTrust AssessEstimatedNormals(const std::vector<Eigen::Vector3d>& points);

// ReadOrientedCloud (datasets/normals/oriented_cloud.h) for the primitive fitter: estimated normals
// that AssessEstimatedNormals does not trust are dropped, so the fit hypothesises from points
// alone; normals_action then says "estimated, not trusted (...): fit from points only".
// neighbourhoods (optional): those the normals were estimated or checked with (empty when the
// cloud was too small for them). untrusted_normals (optional): the estimated normals it dropped
// (empty when it kept them or had none), for the volume check of the fit (fit/detect/checked_fit.h).
PointCloud ReadCloudForPrimitiveFit(const std::string& path, std::string* normals_action,
                                    Neighbourhoods* neighbourhoods = nullptr,
                                    std::vector<Eigen::Vector3d>* untrusted_normals = nullptr);

}  // namespace implicitfit
