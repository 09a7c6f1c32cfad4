// Primitive hypotheses from minimal samples of oriented points (the RANSAC proposals of the
// primitive fitter). Each returns false on a degenerate sample. Parameters are in the flat
// layout of the model evaluators (model/*.h). Normals may be inward or outward: every
// construction below uses normal *lines*, not their sign, except where stated.
//   plane    1 point:  n, d = n . p
//   sphere   2 points: centre = midpoint of the shortest segment between the normal lines,
//                      r = mean distance of the two points to it
//   cylinder 2 points: axis a = n1 x n2; in the plane orthogonal to a the two normal lines meet
//                      at the axis; r = mean distance of the points to the axis
//   cone     3 points: the apex lies on the three tangent planes (3x3 solve); the axis a makes
//                      the same angle with every normal: a ~ (n1 - n2) x (n1 - n3), oriented so
//                      that the points lie on the side a points to; sin(alpha) = |n . a|
//   torus    k >= 5 points: every normal line of a torus meets its axis; in Pluecker coordinates
//                      (d, m) the axis satisfies d . (p_i x n_i) + m . n_i = 0, a homogeneous
//                      linear system solved by SVD; then in meridian coordinates (rho, h) the tube
//                      centre (R, h0) = (rho_i, h_i) - r (n_rho_i, n_h_i), linear least squares.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace implicitfit {

using Vec3 = Eigen::Vector3d;

bool PlaneFromSample(const Vec3& p, const Vec3& n, std::vector<double>* params);
bool SphereFromSample(const Vec3 p[2], const Vec3 n[2], std::vector<double>* params);
bool CylinderFromSample(const Vec3 p[2], const Vec3 n[2], std::vector<double>* params);
bool ConeFromSample(const Vec3 p[3], const Vec3 n[3], std::vector<double>* params);
bool TorusFromSample(const std::vector<Vec3>& p, const std::vector<Vec3>& n,
                     std::vector<double>* params);

}  // namespace implicitfit
