// An independent second opinion on the convexity of a Bernstein patch, by sampling (Guo's
// definition, not the A^mu matrices): the patch is convex at a point p of its zero set if the
// surface lies in the half-space bounded by the tangent plane at p that -grad f(p) points to.
//
// Method. Draw `segments` random segments between uniform random points of the tetrahedron
// (barycentric coordinates from Dirichlet(1,1,1,1)); along each, f is evaluated at `steps` + 1
// points and every sign change is bisected to a zero point p (60 halvings). Points with a
// vanishing gradient (|grad f| L <= 1e-6 max|b|, L the longest edge) are skipped. Then every
// zero point p is tested against every other zero point q:
//   (q - p) . grad f(p) / |grad f(p)| <= tolerance * L.
// A certified patch (f convex on the tetrahedron) passes this test exactly: f(q) = 0 >=
// f(p) + grad f(p) . (q - p). A failing point is a witness of non-convexity of the zero set
// inside the tetrahedron. Deterministic for a given seed.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>

#include "model/bernstein/bernstein_patch.h"
#include "model/model.h"

namespace implicitfit {

struct TangentPlaneTestOptions {
  int segments = 1000;      // random segments through the tetrahedron
  int steps = 16;           // sign-change search steps per segment
  double tolerance = 1e-8;  // allowed excursion beyond a tangent plane, relative to L
  std::uint64_t seed = 1;   // random generator seed
};

struct TangentPlaneTestResult {
  int zero_points = 0;           // points of the zero set found inside the tetrahedron
  int violations = 0;            // zero points whose tangent plane some other zero point crosses
  double worst_excursion = 0.0;  // largest (q - p) . n / L seen (> tolerance: a violation)
};

TangentPlaneTestResult TangentPlaneTest(int k, const Tetrahedron& tetrahedron,
                                        const double* control_points,
                                        const TangentPlaneTestOptions& options = {});

// The same test for any model over an axis-aligned box (docs/maths.md LP-4 c): segments between uniform
// random points of the box, L = the box diagonal, gradients by Model::Gradient; zero points with
// |grad f| L <= 1e-9 (|f| scale unknown) are skipped. It tests the solid {f <= 0} inside the box.
TangentPlaneTestResult TangentPlaneTest(const Model& model, const Eigen::Vector3d& box_min,
                                        const Eigen::Vector3d& box_max,
                                        const TangentPlaneTestOptions& options = {});

// The shared core: `random_point` draws segment ends, `value` is f, `gradient` is grad f;
// zero points with |grad f| <= min_gradient are skipped; L = `length`.
TangentPlaneTestResult TangentPlaneTestCore(
    const std::function<Eigen::Vector3d()>& random_point,
    const std::function<double(const Eigen::Vector3d&)>& value,
    const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& gradient, double length,
    double min_gradient, const TangentPlaneTestOptions& options);

}  // namespace implicitfit
