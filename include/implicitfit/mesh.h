// Public API: the mesh job (`implicitfit mesh`, Python's implicitfit.mesh) — a triangle mesh of a
// model's zero set with normals from grad f (datasets/meshing/model_mesher.h, which also gives
// WriteMeshPlyFile), optionally with every Bernstein patch clipped to its tetrahedron first
// (model/file/clip_to_tetrahedron.h: Guo's object S(f) ∩ V, a closed surface along V's faces)
// (MeshJobOptions with IsValid, MeshModelJob, MeshJobResult with BriefReport and ToJson). The
// report:
//   {"success", "message", "vertices", "triangles", "cell", "max_abs_value", "clipped_patches",
//    "box": {"min", "max"}, "seconds"} and the header of jobs/report_header.h.
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "datasets/meshing/model_mesher.h"
#include "fit/common/fit_summary.h"
#include "fit/common/progress.h"
#include "jobs/report_header.h"
#include "model/model.h"

namespace implicitfit {

struct MeshJobOptions {
  MeshOptions mesh;                  // box (default: the model's, enlarged), cell, threads
  bool clip_to_tetrahedron = false;  // needs a bernstein_patch in the model
  // Stage "mesh" (fit/common/progress.h): the cell at the start, each step of the mesher
  // (datasets/meshing/model_mesher.h), the triangles at the end. Empty: nothing reported.
  ProgressCallback progress;
  // False (with a reason naming the option) for a negative or non-finite cell or a box that is
  // not finite with min < max on every axis.
  bool IsValid(std::string* error) const;
  // The "settings" of the report: box (null: the default), cell, clip_to_tetrahedron.
  nlohmann::json Settings() const;
};

// success: the zero set crosses the box (a mesh with triangles); termination CONVERGENCE then,
// else FAILURE with the reason in message.
struct MeshJobResult : FitSummary {
  MeshResult result;        // the mesh, the box gridded, the cell used, max |f| at the vertices
  int clipped_patches = 0;  // with clip_to_tetrahedron
  // "vertices V  triangles T  cell h  max_abs_value v" (one line).
  std::string BriefReport() const;
  // The report above, with `header` (its settings: MeshJobOptions::Settings() when empty).
  nlohmann::json ToJson(const ReportHeader& header = {}) const;
  MeshJobOptions options;  // as given
};

// Throws std::invalid_argument for invalid options, a clip without a bernstein_patch or a grid
// the mesher refuses (finer than options.mesh.max_grid_points).
MeshJobResult MeshModelJob(const Model& model, const MeshJobOptions& options = {});

}  // namespace implicitfit
