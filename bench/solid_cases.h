// The clouds of bench/solid_comparison and their truths (header of solid_comparison.cc).
// A SolidCloud is one set of points with the normals every method of its rows uses, the truth
// surface (distance and outward normal at any point), noise-free points on it, the meshing box,
// and the ways implicitfit starts on it: from primitives fitted to ground-truth labels (the
// label-started diagnostics), or end to end from the points (`detect`, orientation, CSG, fit).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "fit/reconstruct/solid_reconstruction.h"

namespace bench {

using Vec = Eigen::Vector3d;

// Distance of a point to the true surface and its outward unit normal there.
using TruthDistance = std::function<double(const Vec& x, Vec* normal)>;

struct SolidCloud {
  std::string name;
  std::string normals;  // where the normals come from: "exact", "estimated, MST-oriented", ...
  std::vector<Vec> points, normals_of_points;
  TruthDistance truth;
  std::vector<Vec> truth_points;
  // Truth points on an internal face: where two labelled surfaces coincide with their points
  // interleaved (Fit4CAD PC155: the slab's top face under the dome and the dome's own base, two
  // bodies touching). No one-piece solid has a surface there; the rows "internal faces left
  // out" measure every method without them. Empty when the truth has none.
  std::vector<Vec> truth_points_outside_internal_faces;
  size_t internal_face_points = 0;
  Vec box_min = Vec::Zero(), box_max = Vec::Zero();  // the meshing box
  double size = 1.0;                                 // longest side of the cloud's box
  // How implicitfit starts: labelled primitives (non-empty), and/or end to end (detect first).
  std::vector<implicitfit::SolidPrimitive> labelled;
  bool end_to_end = false;
};

// Generated solids (datasets/generators/generated_solids.h) sampled with noise 0.2% of their size:
// with exact normals and labelled primitives (`labelled_rows`), and points only (normals
// stripped, then estimated and oriented as for a raw scan) end to end.
std::vector<SolidCloud> GeneratedClouds(int points, double outliers, unsigned seed,
                                        bool labelled_rows);

// Held out (`--heldout 1`): the CAD-like solids of the patch-mesh benchmark
// (datasets/generators/cad_solids.h: rotated generically, a paraboloid dome, chamfers, a saddle
// face), never used to tune reconstruct; points only, sampled as GeneratedClouds, end to end.
std::vector<SolidCloud> HeldOutClouds(int points, unsigned seed);

// A Fit4CAD part as given (points and labels; normals estimated and oriented as `reconstruct`
// does): labelled primitives (diagnostic) and end to end on the same normals. False (and why)
// when its files are absent or unusable.
bool Fit4CadCloud(const std::string& data, const std::string& part, unsigned seed,
                  bool labelled_rows, SolidCloud* c, std::string* why);

// A real scan without CAD truth (CGAL's box on ground, the Kinect milk carton): truth is each
// point's tangent plane (from the file's normals when it has them, else the estimated ones).
// points_only: the file's normals are dropped and estimated (orientation toward the file's
// viewpoint when it has one), end to end; otherwise detect on the file's normals.
bool ScanCloud(const std::string& path, const std::string& name, bool points_only,
               SolidCloud* c, std::string* why);

}  // namespace bench
