#include <cstdio>

#include "datasets/io/io_error.h"
#include "datasets/io/scene_file.h"
#include "datasets/normals/oriented_cloud.h"
#include "implicitfit/detect.h"
#include "implicitfit/reconstruct.h"

namespace implicitfit {
namespace {

std::vector<SolidPrimitive> PrimitivesOfScene(const Scene& scene) {
  std::vector<SolidPrimitive> primitives;
  for (const ScenePrimitive& p : scene.primitives)
    primitives.push_back({p.name, p.model, p.rms_distance});
  return primitives;
}

nlohmann::json Report(const SolidReconstruction& r, const PointCloud& cloud,
                      const std::string& normals, const std::vector<SolidPrimitive>& primitives) {
  nlohmann::json j;
  j["success"] = r.success;
  j["message"] = r.message;
  j["points"] = cloud.size();
  j["normals"] = normals;
  j["expression"] = r.expression;
  j["bounded"] = r.bounded;
  j["rms_distance"] = r.rms;
  j["sigma"] = r.sigma;
  j["inliers"] = r.inliers;
  j["normal_sign_agreement"] = r.normal_agreement;
  j["unassigned"] = r.unassigned;
  j["resigned_normals"] = r.resigned_normals;  // re-signed to their primitive's majority side
  j["seconds"] = r.seconds;
  if (r.verification.points > 0) j["verification"] = r.verification.ToJson();
  j["filled_cavities"] = r.filled_cavities;  // unsupported pieces repaired before verification
  j["removed_pieces"] = r.removed_pieces;
  j["bridged_separators"] = r.bridged_separators;
  // Primitives modelled as blends of the faces they round (the second attempt,
  // fit/reconstruct/fillet_primitives.h); empty when the first attempt verified.
  j["fillets_as_blends"] = r.fillets_as_blends;
  j["primitives"] = nlohmann::json::array();
  for (size_t k = 0; k < primitives.size() && k < r.sides.size(); ++k)
    j["primitives"].push_back(
        {{"name", primitives[k].name}, {"side", r.sides[k]}, {"points", r.assigned[k]}});
  // Planes no data lie on: closures close an open scan (their faces are not measured surfaces),
  // separators split cells of the arrangement.
  for (const auto& [key, planes] :
       {std::pair<const char*, const std::vector<AddedPlane>*>{"closures", &r.closures},
        {"separators", &r.separators}}) {
    j[key] = nlohmann::json::array();
    for (const AddedPlane& p : *planes)
      j[key].push_back({{"name", p.name},
                        {"normal", {p.normal.x(), p.normal.y(), p.normal.z()}},
                        {"offset", p.offset},
                        {"measured", false}});
  }
  // Coaxial cylinders bounding a concave fillet (fit/reconstruct/fillet_separators.h).
  j["separator_cylinders"] = nlohmann::json::array();
  for (const AddedCylinder& c : r.separator_cylinders)
    j["separator_cylinders"].push_back({{"name", c.name},
                                        {"point", {c.point.x(), c.point.y(), c.point.z()}},
                                        {"axis", {c.axis.x(), c.axis.y(), c.axis.z()}},
                                        {"radius", c.radius},
                                        {"measured", false}});
  j["blends"] = nlohmann::json::array();
  for (const BlendEstimate& b : r.blends)
    j["blends"].push_back(
        {{"node", b.node},
         {"type", b.type},
         {"delta", b.delta},
         {"epsilon", b.epsilon},
         {"standard_deviations", {{"delta", b.sd_delta}, {"epsilon", b.sd_epsilon}}},
         {"crease_angle_deg", b.crease_angle_deg},
         {"fillet_radius", b.fillet_radius},
         {"fillet_radius_standard_deviation", b.sd_fillet_radius},
         {"transition_points", b.transition_points}});
  return j;
}

// The solid of the primitives, and the report.
void Finish(CloudReconstruction* out) {
  if (out->primitives.empty()) {
    out->result.message = "detect found no primitive";
  } else if (!out->cloud.has_normals()) {
    out->result.message = "no normals (" + out->normals + ")";
  } else {
    SolidReconstructionOptions options;
    options.seed = out->options.seed;
    options.progress = out->options.progress;
    out->result =
        ReconstructSolid(out->cloud.points, out->cloud.normals, out->primitives, options);
  }
  out->report = Report(out->result, out->cloud, out->normals, out->primitives);
  out->success = out->result.success;
  out->message = out->result.message;
  out->termination = out->success ? FitTermination::kConverged : FitTermination::kFailure;
  out->points = out->cloud.size();
  out->seconds = out->result.seconds;
}

}  // namespace

bool ReconstructJobOptions::IsValid(std::string* /*error*/) const { return true; }

nlohmann::json ReconstructJobOptions::Settings() const { return {{"seed", seed}}; }

std::string CloudReconstruction::BriefReport() const {
  const SolidReconstruction& r = result;
  std::string d = std::to_string(primitives.size()) + " primitives";
  if (r.verification.points > 0)
    d += ", " + std::to_string(r.verification.components.solids) + " solid piece(s), " +
         std::to_string(r.verification.components.cavities) + " cavities";
  char rms[48];
  std::snprintf(rms, sizeof rms, ", rms %.4g", r.rms);
  return d + rms;
}

nlohmann::json CloudReconstruction::ToJson(const ReportHeader& header) const {
  return WithJobReportHeader(report, header, "reconstruct", options.Settings(), name);
}

CloudReconstruction ReconstructCloudFile(const std::string& cloud_path,
                                         const ReconstructJobOptions& options) {
  std::string normals;
  PointCloud cloud;
  {
    ProgressStage stage(options.progress, "normals", cloud_path);
    cloud = ReadOrientedCloud(cloud_path, &normals);
    stage.End(std::to_string(cloud.size()) + " points, " + normals);
  }
  if (options.scene.empty())
    return ReconstructCloud(std::move(cloud), cloud_path, normals, options);
  const std::string& scene_path = options.scene;
  CloudReconstruction out;
  out.options = options;
  out.name = cloud_path;
  out.cloud = std::move(cloud);
  out.normals = normals;
  const Scene scene = ReadSceneFile(scene_path);
  if (scene.points > 0 && static_cast<size_t>(scene.points) != out.cloud.size())
    throw InputError(scene_path + ": scene is of a cloud of " + std::to_string(scene.points) +
                     " points, " + cloud_path + " has " + std::to_string(out.cloud.size()));
  if (scene.primitives.empty()) throw InputError(scene_path + ": no primitives");
  if (scene.primitives.size() > 64) throw InputError(scene_path + ": more than 64 primitives");
  out.primitives = PrimitivesOfScene(scene);
  Finish(&out);
  return out;
}

CloudReconstruction ReconstructCloud(PointCloud cloud, const std::string& name,
                                     const std::string& normals,
                                     const ReconstructJobOptions& options) {
  CloudReconstruction out;
  out.options = options;
  out.name = name;
  out.normals = normals;
  {
    // detect with its defaults and the same seed, on the cloud as given.
    DetectionOptions detect;
    detect.seed = options.seed;
    ProgressStage stage(options.progress, "detect", std::to_string(cloud.size()) + " points");
    CloudDetection detection = DetectCloud(std::move(cloud), name, normals, detect);
    stage.End(std::to_string(detection.scene.primitives.size()) + " primitives");
    out.cloud = std::move(detection.cloud);
    out.primitives = PrimitivesOfScene(detection.scene);
    out.labels = detection.result.labels;
  }
  out.detected = true;
  Finish(&out);
  return out;
}

}  // namespace implicitfit
