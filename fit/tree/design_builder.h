// Design from oriented points (Li & Phillips §4.1; docs/maths.md LP-3): `implicitfit design CLOUD
// --primitive plane|paraboloid --count m`.
//   1. m oriented representatives: k-means (Lloyd, 50 rounds) on the features (x / L, 2 n),
//      L the cloud's bounding-box diagonal, seeded by farthest-point sampling from the point
//      nearest the centroid (deterministic). Per cluster: P = its member nearest the cluster's
//      mean position, n = the normalised mean normal; for a paraboloid also
//      kappa = -2 sum h |w|^2 / sum |w|^4 over the members (least squares of the cap
//      h = -(kappa / 2) |w|^2, h = n . (x - P), w = x - P - h n).
//   2. The model: intersection(base, shape(P_1, n_1), ..., shape(P_m, n_m)) folded left to right
//      with Li & Phillips' smooth max (delta, epsilon, order), the base the ellipsoid of the
//      cloud's covariance (centre the mean, axes its eigenvectors, radii sqrt(eigenvalue) times
//      1.25 the largest Mahalanobis radius of the points), so it encloses every point and the
//      shapes decide the surface. shape = plane through P with normal n, or the paraboloid of
//      vertex P, axis n and curvature kappa.
//   Smoothing "convex" (`design --smoothing convex`, docs/maths.md LP-4 b): the children are
//      folded with the convexity-preserving S^c_max of width w = delta instead, the base is the
//      BOX of the covariance axes (exact signed distance, a convex function; half sizes 1.25
//      the largest extent of the points along each axis around their mean, so it too encloses
//      every point) and a paraboloid's curvature is clamped to kappa >= 0 (a concave cap is not
//      convex). Every leaf is then a convex function and S^c_max of convex functions is convex,
//      so the whole tree is certified convex (model/certificates/tree_certificate.h): Li &
//      Phillips' convex shape from lines, with a certificate. Their own S_max is neither convex
//      nor monotone, and the ellipsoid's first-order distance is not a convex function, so the
//      default design can never be certified.
//   3. `fit --init` refines it (fit/tree/tree_fitter.h).
// At a representative P_j farther than delta + epsilon (in function value) from every other
// child, the smooth max is exact: f(P_j) = 0 and grad f is parallel to n_j.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

struct OrientedRepresentative {
  Eigen::Vector3d point, normal;
  double curvature = 0.0;  // paraboloid kappa
};

struct DesignOptions {
  std::string primitive = "plane";  // plane | paraboloid
  int count = 6;                    // m >= 1
  double delta = 0.0;               // 0: 2% of the bounding-box diagonal
  double epsilon = 0.0;             // 0: delta / 2
  int order = 3;
  std::string smoothing = "li-phillips";  // li-phillips | convex (see above)
};

bool IsDesignSmoothing(const std::string& smoothing);

bool IsDesignPrimitive(const std::string& primitive);

// Step 1. Throws std::invalid_argument when count < 1 or there are fewer points than count.
std::vector<OrientedRepresentative> PickRepresentatives(const std::vector<Eigen::Vector3d>& points,
                                                        const std::vector<Eigen::Vector3d>& normals,
                                                        int count, bool with_curvature);

// The enclosing ellipsoid (12 parameters of model/primitives/ellipsoid.h) of step 2.
std::vector<double> EnclosingEllipsoid(const std::vector<Eigen::Vector3d>& points);
// The enclosing box of the covariance axes (10 parameters of model/primitives/box.h), the base
// of a convex-smoothing design.
std::vector<double> EnclosingBox(const std::vector<Eigen::Vector3d>& points);

// Step 2 from given representatives and base parameters (an ellipsoid's 12, or with smoothing
// "convex" a box's 10).
Model DesignModel(const std::vector<OrientedRepresentative>& representatives,
                  const std::vector<double>& base, const DesignOptions& options);

// Steps 1-2 (delta / epsilon defaults resolved from the cloud). Throws std::invalid_argument
// for invalid options.
Model DesignFromOrientedPoints(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<Eigen::Vector3d>& normals, DesignOptions options);

}  // namespace implicitfit
