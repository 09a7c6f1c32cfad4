// Primitive hypotheses from all the oriented points of a small patch (the detector's local
// samples), better conditioned than minimal samples when the patch is small and its normals
// estimated (two nearby normals barely fix a cylinder's axis). Normals may have either sign.
//   plane    least squares: the normal is the eigenvector of the smallest eigenvalue of the
//            points' covariance; offset n . mean.
//   sphere   every normal line passes through the centre: c minimises sum |(I - n n^T)(c - p)|^2,
//            i.e. (sum (I - n n^T)) c = sum (I - n n^T) p; r = mean |p - c|.
//   cylinder every normal is orthogonal to the axis: a is the eigenvector of the smallest
//            eigenvalue of sum n n^T; in the plane orthogonal to a the points lie on a circle,
//            fitted algebraically (Kasa: u^2 + v^2 + D u + E v + F = 0, linear least squares).
// Each returns false when the patch is degenerate for the kind (e.g. all normals parallel for a
// sphere or a cylinder). Parameters in the flat layout of the model evaluators (model/*.h).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace implicitfit {

bool PlaneFromPatch(const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3d>& n,
                    std::vector<double>* params);
bool SphereFromPatch(const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3d>& n,
                     std::vector<double>* params);
bool CylinderFromPatch(const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3d>& n,
                       std::vector<double>* params);

}  // namespace implicitfit
