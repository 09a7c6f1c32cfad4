// Generalised winding number of an oriented point cloud (Barill, Dickson, Schmidt, Levin,
// Jacobson 2018, "Fast winding numbers for soups and clouds"): every point p_i with unit outward
// normal n_i stands for a small disk of area a_i, and
//   w(x) = sum_i a_i (p_i - x) . n_i / (4 pi |p_i - x|^3),
// the solid angle those disks subtend at x over 4 pi: ~1 inside a closed sampled surface, ~0
// outside. Across the hole of an open scan w goes smoothly from ~1 to ~0, and its level 1/2
// spans the rim: for a planar rim, every point of the plane inside it sees the missing part of
// the surface under a solid angle of 2 pi, so w = 1/2 there (the flat cap). This is what makes
// w the inside/outside test for the far-field rows of the patch-mesh fit
// (fit/bernstein/bernstein_mesh_fitter.h), where the nearest point's tangent plane says nothing (beyond
// an open rim) or the wrong thing (across a thin part). Brute force, O(n) per evaluation: the
// fit evaluates it at a few thousand lattice points (Barill's Barnes-Hut tree would be the
// next step for clouds of millions of points).
//
// Areas (Barill et al.'s choice for clouds): a_i = the area of p_i's Voronoi cell in its tangent
// plane among its 16 nearest neighbours facing the same way (n_i . n_j > 0: the far side of a
// thin part is another sheet), projected onto that plane, the cell clipped to the disk of radius
// the 8th neighbour's distance (a point on the rim of an open scan has an unbounded cell).
// Measured on cgal_oni (1 435 points, spacing varying 5x): w at the head's centre 0.97 (a
// smoothing kernel with a bandwidth from the 8th neighbour: 0.83, its areas summing to 1.74
// against ~1.9 for the scanned surface). Neighbours from a hash grid.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace implicitfit {

// The area each point stands for (see above); the sum approximates the sampled surface's area.
std::vector<double> PointAreas(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<Eigen::Vector3d>& normals);

class WindingNumber {
 public:
  // normals: unit, outward (f < 0 inside, docs/design.md); same size as points.
  WindingNumber(const std::vector<Eigen::Vector3d>& points,
                const std::vector<Eigen::Vector3d>& normals);
  double operator()(const Eigen::Vector3d& x) const { return Evaluate(x, nullptr); }
  // w(x) and, when gradient is given, grad w(x) = sum_i a_i / (4 pi) (-n_i / r^3 +
  // 3 (n_i . d) d / r^5) with d = p_i - x, r = |d|.
  double Evaluate(const Eigen::Vector3d& x, Eigen::Vector3d* gradient) const;

 private:
  // Per point: a_i n_i / (4 pi) and p_i, packed for the brute-force sum.
  std::vector<Eigen::Vector3d> points_, weighted_normals_;
};

}  // namespace implicitfit
