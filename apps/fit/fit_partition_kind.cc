// implicitfit fit CLOUD --model partition --grid AxBxC [--child plane|quadric|quadric-patch] --out
// M.json: the one sparse least-squares start (fit/tree/partition_start.h), then the tree fitter; the
// report is the shape kinds' (AddTreeFitFigures) plus the grid, the child and the linear start's
// RMS.
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/fit/fit_model_kinds.h"
#include "apps/report_header.h"
#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "datasets/normals/oriented_cloud.h"
#include "fit/tree/partition_start.h"
#include "model/file/model_json.h"

namespace implicitfit {
namespace {

// "AxBxC" with positive integers.
void ParseGrid(const std::string& text, int cells[3]) {
  const std::string usage = "--grid '" + text + "': expected AxBxC, three counts >= 1 (e.g. 3x3x2)";
  size_t start = 0;
  for (int k = 0; k < 3; ++k) {
    const size_t x = text.find('x', start);
    if ((k < 2) != (x != std::string::npos)) throw InputError(usage);
    const std::string item = text.substr(start, k < 2 ? x - start : std::string::npos);
    if (item.empty() || item.size() > 4 || item[0] == '0' ||
        item.find_first_not_of("0123456789") != std::string::npos)
      throw InputError(usage);
    cells[k] = std::stoi(item);
    if (cells[k] < 1) throw InputError(usage);
    start = x + 1;
  }
  // Every cell is a child with its own parameters, fitted jointly (fit/tree/tree_fitter.h:
  // kMaxTreeFitWork); 4x4x4 planes on 2000 points took over a minute.
  if (cells[0] * cells[1] * cells[2] > 64)
    throw InputError("--grid '" + text + "': " + std::to_string(cells[0] * cells[1] * cells[2]) +
                     " cells, more than the limit of 64 (each is a child fitted jointly)");
}

}  // namespace

int RunPartitionFit(const ModelFitRequest& request) {
  if (request.grid.empty()) throw InputError("--model partition needs --grid AxBxC");
  PartitionStartOptions options;
  ParseGrid(request.grid, options.cells);
  if (!IsPartitionChildKind(request.child))
    throw InputError("--child '" + request.child + "': expected plane, quadric or quadric-patch");
  options.child = request.child;
  std::string normals;
  const PointCloud cloud = ReadOrientedCloud(request.cloud, &normals);
  const PartitionStart start = LinearPartitionStart(cloud.points, cloud.normals, options);
  nlohmann::json report = {{"kind", "partition"},
                           {"grid", request.grid},
                           {"child", request.child},
                           {"points", cloud.size()},
                           {"normals", normals}};
  auto fail = [&](const std::string& message) {
    report["success"] = false;
    report["message"] = message;
    if (!request.report.empty()) WriteReportFile(request.report, report);
    std::cerr << "implicitfit fit: " << request.cloud << ": partition fit failed: " << message
              << "\n";
    return 1;
  };
  if (!start.success) return fail(start.message);
  report["linear_start_rms"] = start.linear_rms;
  const TreeFitResult r = FitModelTree(start.model, cloud.points, cloud.normals, CommandLineTreeFitOptions());
  AddTreeFitFigures(r, start.model, cloud.points, normals, &report);
  if (!r.success) return fail(r.message);
  if (!request.report.empty()) WriteReportFile(request.report, report);
  WriteModelFile(r.model, request.out);
  std::printf("%s\n", ModelToJson(r.model)["root"].dump().c_str());
  std::printf(
      "points %zu  inliers %d  rms %.6g  sigma %.6g  normal angle %.3g deg  linear start rms "
      "%.6g  %.3f s\n",
      cloud.size(), r.inliers, r.rms, r.sigma, r.mean_normal_angle_deg, start.linear_rms,
      r.seconds);
  return 0;
}

}  // namespace implicitfit
