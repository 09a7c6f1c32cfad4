// implicitfit reconstruct CLOUD --out MODEL.json [--scene SCENE.json] [--mesh MESH.ply]
//                         [--report R.json] [--seed s] [--quiet] [--keep-unverified]
// A solid model of the scan (fit/reconstruct/solid_reconstruction.h) from the primitives of a scene
// file (datasets/io/scene_file.h). Without --scene the primitives come from `detect` run on the
// cloud with its defaults and the same seed (implicitfit/reconstruct.h). The solid verifies itself
// (fit/reconstruct/solid_verification.h) before anything but the report is written: a solid that
// fails exits 1 with the reason and writes no model and no mesh;
// --keep-unverified writes them anyway, the model marked {"verification": {"verified": false,
// "reason"}} (exit 1 still). The mesh is `mesh MODEL.json`'s default for the written model (its
// proven bounds), so the two agree. Progress on stderr per stage, one summary line at the end;
// --quiet keeps only the failure's summary.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "apps/command.h"
#include "apps/progress_printer.h"
#include "apps/report_header.h"
#include "apps/view_outputs.h"
#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "datasets/meshing/model_mesher.h"
#include "implicitfit/reconstruct.h"
#include "model/file/model_json.h"

namespace implicitfit {
namespace {

struct ReconstructArgs {
  std::string cloud, out, scene, mesh, report, view;
  unsigned seed = 1;
  bool quiet = false, keep_unverified = false;
};

// Before any work: every output's folder exists and is writable, and no output is the cloud
// (a missing folder used to fail only after the whole reconstruction).
void CheckOutputs(const ReconstructArgs& a) {
  namespace fs = std::filesystem;
  for (const std::string* path : {&a.out, &a.mesh, &a.report, &a.view}) {
    if (path->empty()) continue;
    std::error_code ec;
    if (fs::equivalent(*path, a.cloud, ec)) throw InputError(*path + ": is the input cloud");
    if (fs::is_directory(*path, ec)) throw InputError(*path + ": is a directory");
    fs::path folder = fs::path(*path).parent_path();
    if (folder.empty()) folder = ".";
    if (!fs::is_directory(folder, ec))
      throw InputError(*path + ": no such folder (" + folder.string() + ")");
    if (::access(folder.c_str(), W_OK) != 0)
      throw InputError(*path + ": folder not writable (" + folder.string() + ")");
  }
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
  cmd->add_option("--view", a->view, "A page of the solid and the cloud (docs/view.md)");
  cmd->add_option("--seed", a->seed, "Random seed");
  cmd->add_flag("--quiet", a->quiet, "No progress on stderr (failures are still reported)");
  cmd->add_flag("--keep-unverified", a->keep_unverified,
                "Write the model (marked unverified) and mesh even when verification fails");
  return [a]() {
    if (!a->mesh.empty() && (a->mesh.size() < 4 || a->mesh.substr(a->mesh.size() - 4) != ".ply"))
      throw InputError(a->mesh + ": unsupported mesh format (use .ply)");
    CheckOutputs(*a);
    const auto start = std::chrono::steady_clock::now();
    const ProgressCallback progress = StderrProgress("reconstruct", a->quiet);
    ReconstructJobOptions options;
    options.scene = a->scene;
    options.seed = a->seed;
    options.progress = progress;
    CloudReconstruction job = ReconstructCloudFile(a->cloud, options);
    const PointCloud& cloud = job.cloud;
    const SolidReconstruction& r = job.result;
    nlohmann::json& report = job.report;
    const bool built = r.verification.points > 0;  // a solid was built (verified or not)
    const bool write = r.success || (a->keep_unverified && built);
    report["model_written"] = write;
    TriangleMesh mesh;
    if (write && !a->mesh.empty()) {
      MeshOptions mo;  // verified: `mesh`'s default (the proven bounds); else the cloud's box
      if (!r.model.claims().has_bounds) {
        mo.has_box = true;
        Eigen::Vector3d lo = cloud.points[0], hi = cloud.points[0];
        for (const Eigen::Vector3d& p : cloud.points) {
          lo = lo.cwiseMin(p);
          hi = hi.cwiseMax(p);
        }
        mo.box_min = lo - 0.1 * (hi - lo);
        mo.box_max = hi + 0.1 * (hi - lo);
      }
      ProgressStage stage(progress, "mesh");
      mesh = MeshModel(r.model, mo).mesh;
      stage.End(std::to_string(mesh.triangles.size()) + " triangles");
    }
    // All or nothing: the command's output transaction (apps/output_guard.h) renames these
    // into place only when the command returns.
    if (write) {
      WriteModelFile(r.model, a->out);
      if (!a->mesh.empty()) WriteMeshPlyFile(mesh, a->mesh);
    }
    if (!a->report.empty())  // also when verification failed: the reasons
      WriteReportFile(a->report, job.ToJson(CommandReportHeader()));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!r.success) {
      PrintSummary("reconstruct", a->quiet, false,
                   a->cloud + ": not verified" +
                       std::string(write ? " (written, marked unverified)" : ", nothing written"),
                   seconds, r.message);
      return 1;
    }
    if (!a->view.empty()) WriteReconstructionView(job, a->cloud, a->view);
    std::cout << job.ToJson(CommandReportHeader()).dump(2) << "\n";
    PrintSummary("reconstruct", a->quiet, true, "verified solid", seconds,
                 job.BriefReport() + " -> " + a->out);
    return 0;
  };
}

}  // namespace implicitfit
