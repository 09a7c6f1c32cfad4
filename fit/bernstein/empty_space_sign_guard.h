// Watches the sign of a patch-mesh f (model/bernstein/bernstein_mesh.h) away from the data, to reject a fit
// step that grows a new spurious component (a closed blob or a sheet in empty space) which the
// far-field rows' coarser lattice (spacing half a leaf's edge, fit/bernstein/far_field_rows.h)
// does not see.
//
// Samples: the points of a lattice of spacing s = h / samples_per_cube over the grid box that lie
// farther than `band` from every input point (found with a bucket grid of cube edge h: only the
// cubes within ceil(band / h) of a sample's cube can hold a point that near). Every point of
// space lies within rho = s sqrt(3)/2 of a sample, so a new component of the zero set anywhere
// (farther than band from the data) comes within rho of some sample x. Record(b) stores, per
// sample, the sign of f and whether the zero set is clear of it, i.e. its first-order distance
// e(x) = |f(x)| / |grad f(x)| exceeds 2 rho; Changes(b) counts the clear samples where f's sign
// now differs from the recorded one (0 counts as its own sign) or the zero set came within rho
// (e(x) <= rho). Samples within 2 rho of the recorded zero set are not watched: there the
// surface may move (oni's cap over its unscanned base moves across samples as the fit improves).
// A new blob or sheet, even one smaller than s, comes within rho of some sample and trips it (to
// first order in e), unless it grows within 2 rho of the recorded zero set; a surface that moves
// by less than rho trips nothing.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/bernstein/bernstein_mesh.h"

namespace implicitfit {

class EmptySpaceSignGuard {
 public:
  EmptySpaceSignGuard(const BernsteinGrid& grid, const std::vector<Eigen::Vector3d>& points,
                      double band, int samples_per_cube);

  void Record(int degree, const std::vector<double>& control_points);
  long long Changes(int degree, const std::vector<double>& control_points) const;
  // The samples Changes() counts, each with whether its sign changed (else the zero set only
  // came within rho).
  struct Trip {
    Eigen::Vector3d x;
    bool sign_changed;
  };
  std::vector<Trip> Tripped(int degree, const std::vector<double>& control_points) const;
  long long size() const { return static_cast<long long>(samples_.size()); }
  // The watched samples (clear of the recorded zero set) within `radius` (max-norm) of any of
  // `centres`.
  std::vector<Eigen::Vector3d> WatchedNear(const std::vector<Eigen::Vector3d>& centres,
                                           double radius) const;

 private:
  BernsteinGrid grid_;
  std::vector<Eigen::Vector3d> samples_;
  int degree_ = 0;
  double rho_ = 0.0;
  std::vector<signed char> signs_;
  std::vector<bool> clear_;
};

}  // namespace implicitfit
