// The starting parameterisation of a surface fit (fit/splines/bspline_surface_fitter.h): the
// points projected onto their least-squares plane (PCA: the smallest eigenvector is the normal
// w, turned toward the mean of the point normals when they are given), and in that plane the
// rectangle of least area that holds the projections (rotating calipers: one side of the least
// rectangle lies on an edge of the 2-D convex hull, Freeman and Shapira 1975), so a square patch
// of data gets a square domain whatever its principal axes. (u, v) are the coordinates along the
// rectangle's sides scaled to [0, 1]; e_u x e_v = w, so S_u x S_v of a start surface points
// along w (the side of the normals).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace implicitfit {

struct ParameterFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // the rectangle's corner (u = v = 0)
  Eigen::Vector3d e_u = Eigen::Vector3d::UnitX(), e_v = Eigen::Vector3d::UnitY();  // unit
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double length_u = 1.0, length_v = 1.0;  // the rectangle's sides (> 0)
  // (u, v) of x in [0, 1]^2 for the points it was made from.
  Eigen::Vector2d Parameters(const Eigen::Vector3d& x) const;
};

// normals may be empty (then w keeps the PCA sign). Needs 3 points that are not collinear
// (throws std::invalid_argument otherwise).
ParameterFrame FitParameterFrame(const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<Eigen::Vector3d>& normals);

}  // namespace implicitfit
