// implicitfit reconstruct CLOUD --out MODEL.json [--scene SCENE.json] [--mesh MESH.ply]
//                         [--report R.json] [--seed s]
// A solid model of the scan (fit/reconstruct/solid_reconstruction.h) from the primitives of a scene file
// (datasets/io/scene_file.h). Without --scene the primitives come from `detect` run on the cloud
// with its defaults and the same seed (apps/reconstruct_job.h).
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/command.h"
#include "apps/reconstruct_job.h"
#include "apps/view_outputs.h"
#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "datasets/meshing/model_mesher.h"
#include "model/file/model_json.h"

namespace implicitfit {
namespace {

struct ReconstructArgs {
  std::string cloud, out, scene, mesh, report, view;
  unsigned seed = 1;
};

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
  cmd->add_option("--view", a->view, "A page of the solid and the cloud (docs/view.md)");
  cmd->add_option("--seed", a->seed, "Random seed");
  return [a]() {
    if (!a->mesh.empty() && (a->mesh.size() < 4 || a->mesh.substr(a->mesh.size() - 4) != ".ply"))
      throw InputError(a->mesh + ": unsupported mesh format (use .ply)");
    const CloudReconstruction job = ReconstructCloudFile(a->cloud, a->scene, a->seed);
    const PointCloud& cloud = job.cloud;
    const SolidReconstruction& r = job.result;
    const nlohmann::json& report = job.report;
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
    if (!a->view.empty()) WriteReconstructionView(job, a->cloud, a->view);
    std::cout << report.dump(2) << "\n";
    return 0;
  };
}

}  // namespace implicitfit
