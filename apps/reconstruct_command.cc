// implicitfit reconstruct CLOUD --out MODEL.json [--scene SCENE.json] [--mesh MESH.ply]
//                         [--report R.json] [--seed s]
// A solid model of the scan (fit/solid_reconstruction.h) from the primitives of a scene file
// (datasets/scene_file.h). Without --scene the primitives come from `detect` run on the cloud
// with its defaults and the same seed (DetectPrimitives below).
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/command.h"
#include "apps/detect_job.h"
#include "datasets/atomic_file.h"
#include "datasets/io_error.h"
#include "datasets/model_file.h"
#include "datasets/model_mesher.h"
#include "datasets/oriented_cloud.h"
#include "datasets/scene_file.h"
#include "fit/solid_reconstruction.h"
#include "model/model_json.h"

namespace implicitfit {
namespace {

struct ReconstructArgs {
  std::string cloud, out, scene, mesh, report;
  unsigned seed = 1;
};

std::vector<SolidPrimitive> PrimitivesOfScene(const Scene& scene) {
  std::vector<SolidPrimitive> primitives;
  for (const ScenePrimitive& p : scene.primitives)
    primitives.push_back({p.name, p.model, p.rms_distance});
  return primitives;
}

// The primitives of the cloud when no scene is given: `detect` on the same file with its
// defaults and the given seed (apps/detect_job.h). Replaces *cloud by the cloud the detection
// read (same points, the normals it used). Empty when nothing was detected.
std::vector<SolidPrimitive> DetectPrimitives(const ReconstructArgs& args, PointCloud* cloud) {
  DetectionOptions options;
  options.seed = args.seed;
  CloudDetection detection = DetectCloudFile(args.cloud, options);
  *cloud = std::move(detection.cloud);
  return PrimitivesOfScene(detection.scene);
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
  j["seconds"] = r.seconds;
  j["primitives"] = nlohmann::json::array();
  for (size_t k = 0; k < primitives.size(); ++k)
    j["primitives"].push_back(
        {{"name", primitives[k].name}, {"side", r.sides[k]}, {"points", r.assigned[k]}});
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

}  // namespace

CommandAction AddReconstructCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "reconstruct", "Solid model of a scan: oriented primitives, smooth CSG, fitted fillets");
  auto a = std::make_shared<ReconstructArgs>();
  cmd->add_option("CLOUD", a->cloud, "Oriented cloud (.xyz/.pwn/.txt/.ply/.pcd)")->required();
  cmd->add_option("--out", a->out, "Output model (JSON)")->required();
  cmd->add_option("--scene", a->scene, "Scene file of the cloud's primitives (from detect)");
  cmd->add_option("--mesh", a->mesh, "Also write a mesh of the solid (.ply)");
  cmd->add_option("--report", a->report,
                  "Report (JSON): RMS, normal agreement, blends with deviations");
  cmd->add_option("--seed", a->seed, "Random seed");
  return [a]() {
    if (!a->mesh.empty() && (a->mesh.size() < 4 || a->mesh.substr(a->mesh.size() - 4) != ".ply"))
      throw InputError(a->mesh + ": unsupported mesh format (use .ply)");
    std::string normals;
    PointCloud cloud = ReadOrientedCloud(a->cloud, &normals);
    std::vector<SolidPrimitive> primitives;
    if (a->scene.empty()) {
      primitives = DetectPrimitives(*a, &cloud);
      if (primitives.empty()) {
        std::cerr << "implicitfit reconstruct: " << a->cloud << ": detect found no primitive\n";
        return 1;
      }
    } else {
      const Scene scene = ReadSceneFile(a->scene);
      if (scene.points > 0 && static_cast<size_t>(scene.points) != cloud.size())
        throw InputError(a->scene + ": scene is of a cloud of " + std::to_string(scene.points) +
                         " points, " + a->cloud + " has " + std::to_string(cloud.size()));
      if (scene.primitives.empty()) throw InputError(a->scene + ": no primitives");
      if (scene.primitives.size() > 64) throw InputError(a->scene + ": more than 64 primitives");
      primitives = PrimitivesOfScene(scene);
    }
    if (!cloud.has_normals()) {
      std::cerr << "implicitfit reconstruct: " << a->cloud << ": no normals (" << normals << ")\n";
      return 1;
    }
    SolidReconstructionOptions options;
    options.seed = a->seed;
    const SolidReconstruction r =
        ReconstructSolid(cloud.points, cloud.normals, primitives, options);
    const nlohmann::json report = Report(r, cloud, normals, primitives);
    if (!a->report.empty()) WriteFileAtomically(a->report, report.dump(2) + "\n");
    if (!r.success) {
      std::cerr << "implicitfit reconstruct: " << a->cloud << ": " << r.message << "\n";
      return 1;
    }
    WriteModelFile(r.model, a->out);
    if (!a->mesh.empty()) {
      MeshOptions mo;
      mo.has_box = true;
      Eigen::Vector3d lo = cloud.points[0], hi = cloud.points[0];
      for (const Eigen::Vector3d& p : cloud.points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
      mo.box_min = lo - 0.1 * (hi - lo);
      mo.box_max = hi + 0.1 * (hi - lo);
      WriteMeshPlyFile(MeshModel(r.model, mo).mesh, a->mesh);
    }
    std::cout << report.dump(2) << "\n";
    return 0;
  };
}

}  // namespace implicitfit
