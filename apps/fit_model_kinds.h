// The fits of `implicitfit fit` beyond single primitives:
//   --init MODEL.json      every free parameter of a model tree (fit/tree_fitter.h)
//   --model quadric-patch | cubic-patch [--degree k] [--convex] [--tetrahedron 12 numbers]
//                          a Bernstein patch (fit/patch_fitter.h)
//   --model box | paraboloid | capsule
//                          a robust start (fit/shape_starts.h), then the tree fitter
// Each reads the cloud, fits, writes the report (when asked) and, on success, the model file;
// returns the exit code (0 success, 1 the fit failed or the constraint cannot be met).
#pragma once

#include <string>
#include <vector>

namespace implicitfit {

struct ModelFitRequest {
  std::string cloud, out, report;
  std::string init;                   // --init
  std::string kind;                   // quadric-patch / cubic-patch
  int degree = 0;                     // 0: from the kind
  bool convex = false;
  std::vector<double> tetrahedron;    // empty or 12 numbers
  // Guo §3 shape control (patch kinds): vertices 1..4; "I=nx,ny,nz"; "I,J".
  std::vector<int> through_vertices;
  std::vector<std::string> vertex_normals, through_edges;
  bool HasShapeConstraints() const {
    return !through_vertices.empty() || !vertex_normals.empty() || !through_edges.empty();
  }
};

bool IsPatchKind(const std::string& kind);
// box, paraboloid, capsule: a robust start (fit/shape_starts.h), then the tree fitter; the
// report is the --init one plus "kind" and the start's parameters ("start").
bool IsShapeKind(const std::string& kind);
int RunShapeFit(const ModelFitRequest& request, unsigned seed);
int RunTreeFit(const ModelFitRequest& request);
int RunPatchFit(const ModelFitRequest& request);

}  // namespace implicitfit
