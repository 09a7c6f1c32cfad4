// Adaptive patch-mesh fit (fit --model patch-mesh, MeshFitOptions::adaptive; docs/patch-mesh.md,
// "Adaptive refinement and sharp features"): a uniform grid spends its unknowns evenly while the
// error sits at the creases, so the grid is refined where the fit's residuals exceed the noise.
//
// Rounds. Fit on the base grid (fit/bernstein/bernstein_mesh_fitter.h, steps 1-3). Then, while
// some leaf cube's points have an RMS residual r_q = rms f/|grad f| above the threshold
// tau = max(refine_factor sigma, refine_spacing_floor s) (sigma: the noise, s: the spacing,
// fit/bernstein/cloud_scales.h), split those leaves into 8 (octree, model/bernstein/
// grid_refinement.h; 2:1 balanced, leaves no smaller than min_leaf_spacings s, at most
// max_levels below the base, worst leaves first within max_unknowns), re-express the fit on the
// finer grid (exact: the spaces are nested, every finer tetrahedron lies in one coarser one) and
// fit again from there (step 2 only, the far-field relaxation continuing where it stopped).
// Empty space keeps the coarse base cubes.
//
// Sharp features. A leaf whose points' normals spread by more than feature_angle_deg (the
// largest angle between the normal farthest from their mean and another) holds a crease or a
// corner: every face of its tetrahedra is declared C0 (grid.sharp), so the fit may bend there as
// sharply as a tetrahedron's polynomial can instead of rounding the edge over a C1 band of
// cells. Elsewhere the mesh stays C1.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "fit/bernstein/bernstein_mesh_fitter.h"

namespace implicitfit {

MeshFitResult FitAdaptiveBernsteinMesh(const std::vector<Eigen::Vector3d>& points,
                                       const std::vector<Eigen::Vector3d>& normals,
                                       const MeshFitOptions& options,
                                       const BernsteinGrid& base);

// The control points of the mesh (grid, b) re-expressed on `finer`, a refinement of grid's
// leaves: every tetrahedron of finer lies in one of grid's (model/bernstein/grid_refinement.h).
std::vector<double> ReexpressOnFinerGrid(int k, const BernsteinGrid& grid,
                                         const std::vector<double>& b,
                                         const BernsteinGrid& finer);

// Per leaf of grid: the RMS of f/|grad f| over its points (0 without points) and their count.
void LeafResiduals(int k, const BernsteinGrid& grid, const std::vector<double>& b,
                   const std::vector<Eigen::Vector3d>& points, std::vector<double>* rms,
                   std::vector<int>* count);

// Per leaf: whether its points' normals spread by more than feature_angle_deg (at least 4
// points).
std::vector<bool> CreaseLeaves(const BernsteinGrid& grid, const std::vector<Eigen::Vector3d>& points,
                               const std::vector<Eigen::Vector3d>& normals,
                               double feature_angle_deg);

}  // namespace implicitfit
