// implicitfit verify MODEL.json CLOUD [--report R.json] [--quiet]
// Is the model a solid the scan supports? The checks of `reconstruct`'s last step
// (fit/reconstruct/solid_verification.h) on any model and cloud: bounded (proven), inside/outside
// agrees with the cloud's oriented normals (estimated and oriented when the file has none,
// datasets/normals/oriented_cloud.h), every piece and cavity supported by scan points. Prints
// the verification (JSON) on stdout; exit 0 when verified, 1 with the reasons on stderr when
// not, 2 for unreadable input.
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/command.h"
#include "apps/report_header.h"
#include "apps/progress_printer.h"
#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "datasets/normals/oriented_cloud.h"
#include "fit/reconstruct/solid_verification.h"

namespace implicitfit {
namespace {

struct VerifyArgs {
  std::string model, cloud, report;
  bool quiet = false;
};

}  // namespace

CommandAction AddVerifyCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "verify", "Check that a model is a bounded solid the scan supports (as reconstruct does)");
  auto a = std::make_shared<VerifyArgs>();
  cmd->add_option("MODEL", a->model, "Model file (JSON)")->required();
  cmd->add_option("CLOUD", a->cloud, "The scan (.xyz/.pwn/.txt/.ply/.pcd)")->required();
  cmd->add_option("--report", a->report, "Also write the verification (JSON) to this file");
  cmd->add_flag("--quiet", a->quiet, "No progress on stderr (failures are still reported)");
  return [a]() {
    const auto start = std::chrono::steady_clock::now();
    const Model model = ReadModelFile(a->model);
    std::string normals;
    const PointCloud cloud = ReadOrientedCloud(a->cloud, &normals);
    if (!cloud.has_normals() || cloud.size() == 0)
      throw InputError(a->cloud + ": no oriented normals (" + normals + ")");
    SolidVerificationOptions options;
    options.progress = StderrProgress("verify", a->quiet);
    const SolidVerification v = VerifySolid(model, cloud.points, cloud.normals, options);
    nlohmann::json report = v.ToJson();
    report["model"] = a->model;
    report["cloud"] = a->cloud;
    report["normals"] = normals;
    if (!a->report.empty()) WriteReportFile(a->report, report);
    std::cout << WithReportHeader(report).dump(2) << "\n";
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    PrintSummary("verify", a->quiet, v.verified, a->model + (v.verified ? ": verified" : ": not verified"),
                 seconds, v.verified ? v.BriefReport() : v.message);
    return v.verified ? 0 : 1;
  };
}

}  // namespace implicitfit
