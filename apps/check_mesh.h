// `check` on bernstein_mesh nodes (model/certificates/bernstein_mesh_certificate.h): per-tetrahedron
// certificates, the largest C1 defect, and the verdict "convex on the box" only when both hold.
// Additive to the check output: JSON files[i].meshes = [{"label", "degree", "continuity",
// "tetrahedra", "certified_tetrahedra", "min_eigenvalue", "worst_tetrahedron", "c1_defect",
// "c1", "domain_convex", "convex_on_box", "verdict", "tetrahedra_certificates":
// [{"convex", "min_eigenvalue"}...], "sample" (with --sample)}].
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model/certificates/bernstein_mesh_certificate.h"
#include "model/model.h"

namespace implicitfit {

struct MeshCheck {
  std::string label;
  int degree = 0;
  int continuity = 0;
  MeshConvexityCertificate certificate;
  bool sampled = false;
  MeshSamplingResult sample;
  // "convex on the box", "not convex (C1 defect)", "not convex (uncertified tetrahedra)"
  std::string Verdict() const;
};

// Every bernstein_mesh node of the model; sample_segments > 0 adds the sampling test.
std::vector<MeshCheck> CheckBernsteinMeshes(const Model& model, int sample_segments);
nlohmann::ordered_json MeshCheckJson(const MeshCheck& check);
void PrintMeshCheck(const std::string& file, const MeshCheck& check);

}  // namespace implicitfit
