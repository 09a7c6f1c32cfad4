#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "implicitfit/mesh.h"
#include "model/file/clip_to_tetrahedron.h"

namespace implicitfit {
namespace {

nlohmann::json VectorJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

bool MeshJobOptions::IsValid(std::string* error) const {
  if (!std::isfinite(mesh.cell) || mesh.cell < 0) {
    *error = "cell: must be positive (or 0: longest box side / 100)";
    return false;
  }
  if (mesh.has_box && (!mesh.box_min.allFinite() || !mesh.box_max.allFinite() ||
                       !((mesh.box_max - mesh.box_min).array() > 0).all())) {
    *error = "box: needs xmin < xmax, ymin < ymax, zmin < zmax (finite)";
    return false;
  }
  return true;
}

nlohmann::json MeshJobOptions::Settings() const {
  nlohmann::json box = nullptr;
  if (mesh.has_box) box = {{"min", VectorJson(mesh.box_min)}, {"max", VectorJson(mesh.box_max)}};
  return {{"box", box}, {"cell", mesh.cell}, {"clip_to_tetrahedron", clip_to_tetrahedron}};
}

std::string MeshJobResult::BriefReport() const {
  char line[160];
  std::snprintf(line, sizeof line, "vertices %zu  triangles %zu  cell %.6g  max_abs_value %.6g",
                result.mesh.vertices.size(), result.mesh.triangles.size(), result.cell,
                result.max_abs_value);
  return line;
}

nlohmann::json MeshJobResult::ToJson(const ReportHeader& header) const {
  nlohmann::json j = {{"success", success},
                      {"message", message},
                      {"vertices", result.mesh.vertices.size()},
                      {"triangles", result.mesh.triangles.size()},
                      {"cell", result.cell},
                      {"max_abs_value", result.max_abs_value},
                      {"clipped_patches", clipped_patches},
                      {"box", {{"min", VectorJson(result.box_min)},
                               {"max", VectorJson(result.box_max)}}},
                      {"seconds", seconds}};
  return WithJobReportHeader(std::move(j), header, "mesh", options.Settings());
}

MeshJobResult MeshModelJob(const Model& model, const MeshJobOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(error);
  MeshJobResult out;
  out.options = options;
  Model meshed = model;
  if (options.clip_to_tetrahedron) {
    meshed = ClipPatchesToTetrahedra(model, &out.clipped_patches);
    if (out.clipped_patches == 0)
      throw std::invalid_argument("clip_to_tetrahedron: the model has no bernstein_patch");
  }
  char detail[96];
  if (options.mesh.cell > 0)
    std::snprintf(detail, sizeof detail, "cell %.6g", options.mesh.cell);
  else
    std::snprintf(detail, sizeof detail, "default cell");
  ProgressStage stage(options.progress, "mesh", detail);
  MeshOptions mesh = options.mesh;
  if (options.progress) mesh.on_step = [&stage](const std::string& what) { stage.Update(what); };
  out.result = MeshModel(meshed, mesh);
  stage.End(std::to_string(out.result.mesh.triangles.size()) + " triangles");
  out.success = !out.result.mesh.triangles.empty();
  out.termination = out.success ? FitTermination::kConverged : FitTermination::kFailure;
  out.message = out.success ? "meshed" : "the zero set does not cross the box";
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace implicitfit
