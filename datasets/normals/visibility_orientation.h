// Outward signs for smooth patches from visibility: a correction after the MST propagation
// (normal_orientation.h), which decides every sign locally and so can carry a wrong one across a
// crease. Where a face continues inside the solid (a dome standing on a slab whose top face is
// also sampled under the dome, Fit4CAD train_PC155), the crease points' PCA normals blend the
// plane's and the sphere's, and the propagation may reach the sphere from the inner sheet: the
// whole dome then comes out inverted, with no inconsistent edge to show it.
//
// Global evidence instead: a point seen from outside, first along a ray from infinity, has its
// outward normal facing the ray (n . d < 0 for the viewing direction d). For each of
// `directions` directions d (a Fibonacci sphere) an orthographic z-buffer of the points
// (cells of cell_factor * spacing across d) keeps the front-most point of each cell; it votes
// for its sign when |n . d| >= min_cosine (grazing views are unreliable). Votes are summed per
// smooth patch: a connected component of the neighbour graph over points of low surface
// variation (creases removed, where PCA normals blend) through edges whose mirrored agreement
// (normal_orientation.h) is at least smooth_agreement. A patch of at least min_patch_points points
// is flipped only when the votes against its sign are at least min_votes and more than flip_ratio
// times the votes for it, so open sheets (seen from both sides: votes balanced) and hidden internal
// faces (no votes) keep the propagation's sign. After a flip, the crease points take their signs
// again by the same propagation, seeded from every patch point at once.
//
// Neither PCL (sign toward a viewpoint only) nor Open3D (MST or a camera; not a Debian
// package) nor CGAL (mst_orient_normals, scanline orientation) offers a visibility vote over
// patches, hence written here: a z-buffer and a union-find.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "datasets/clouds/neighbour_graph.h"

namespace implicitfit {

struct VisibilityOrientationOptions {
  int directions = 96;            // view directions, evenly spread over the sphere
  double cell_factor = 2.0;       // z-buffer cell side in units of the sampling spacing
  double min_cosine = 0.2;        // votes only where |n . d| is at least this
  double smooth_agreement = 0.9;  // patch edges: mirrored agreement at least this
  double max_variation = 0.02;    // patch points: surface variation at most this
  int min_votes = 5;              // fewer votes against a patch never flip it
  int min_patch_points = 20;      // smaller patches (weak evidence) are never flipped
  double flip_ratio = 2.0;        // flip when votes against > flip_ratio * votes for
};

struct VisibilityOrientationResult {
  size_t patches = 0;          // smooth patches found
  size_t flipped_patches = 0;  // patches whose sign the votes reversed
  size_t flipped = 0;          // normals whose sign changed in all (patches and creases)
};

// neighbours: each point's neighbours, nearest first (the first 8 make the patch graph);
// spacing: the sampling spacing (Neighbourhoods::spacing); variation: SurfaceVariation().
VisibilityOrientationResult OrientPatchesByVisibility(
    const std::vector<Eigen::Vector3d>& points, const NeighbourGraph& neighbours,
    double spacing, const std::vector<double>& variation, std::vector<Eigen::Vector3d>* normals,
    const VisibilityOrientationOptions& options = {});

}  // namespace implicitfit
