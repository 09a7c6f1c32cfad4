#include "apps/fit/fit_model_kinds.h"
#include "apps/report_header.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/option_validators.h"
#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "datasets/normals/oriented_cloud.h"
#include "fit/common/fit_report.h"
#include "fit/bernstein/patch_fitter.h"
#include "fit/tree/shape_starts.h"
#include "fit/tree/tree_covariance.h"
#include "fit/tree/tree_fitter.h"
#include "model/file/model_json.h"

namespace implicitfit {
namespace {

void Finish(const ModelFitRequest& request, const Model& model, const nlohmann::json& report) {
  if (!request.report.empty()) WriteReportFile(request.report, report);
  WriteModelFile(model, request.out);
  std::printf("%s\n", ModelToJson(model)["root"].dump().c_str());
}

// --through-vertex I, --vertex-normal I=nx,ny,nz, --through-edge I,J (vertices 1..4).
PatchShapeConstraints ShapeConstraintsFromArguments(const ModelFitRequest& request) {
  PatchShapeConstraints c;
  for (int v : request.through_vertices) c.through_vertices.push_back(v - 1);
  auto numbers = [](const std::string& text, const std::string& option) {
    std::vector<double> out;
    size_t start = 0;
    while (start <= text.size()) {
      const size_t comma = text.find(',', start);
      const std::string item =
          text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      out.push_back(ParseDecimal(item, option + " '" + text + "'"));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    return out;
  };
  auto vertex = [](double v, const std::string& option, const std::string& text) {
    if (v != std::floor(v) || v < 1 || v > 4)
      throw InputError(option + " '" + text + "': vertices are numbered 1..4");
    return static_cast<int>(v) - 1;
  };
  for (const std::string& text : request.vertex_normals) {
    const size_t eq = text.find('=');
    if (eq == std::string::npos)
      throw InputError("--vertex-normal '" + text + "': expected I=nx,ny,nz");
    const std::vector<double> i = numbers(text.substr(0, eq), "--vertex-normal");
    const std::vector<double> n = numbers(text.substr(eq + 1), "--vertex-normal");
    if (i.size() != 1 || n.size() != 3)
      throw InputError("--vertex-normal '" + text + "': expected I=nx,ny,nz");
    PatchShapeConstraints::VertexNormal vn;
    vn.vertex = vertex(i[0], "--vertex-normal", text);
    vn.normal = Eigen::Vector3d(n[0], n[1], n[2]);
    if (!(vn.normal.norm() > 0.0))
      throw InputError("--vertex-normal '" + text + "': the normal must be non-zero");
    c.vertex_normals.push_back(vn);
  }
  for (const std::string& text : request.through_edges) {
    const std::vector<double> e = numbers(text, "--through-edge");
    if (e.size() != 2) throw InputError("--through-edge '" + text + "': expected I,J");
    c.through_edges.push_back(
        {vertex(e[0], "--through-edge", text), vertex(e[1], "--through-edge", text)});
    if (c.through_edges.back()[0] == c.through_edges.back()[1])
      throw InputError("--through-edge '" + text + "': two different vertices needed");
  }
  return c;
}

}  // namespace

void ParseCounts(const std::string& text, int n, const std::string& example, int* counts) {
  const std::string usage = "--grid '" + text + "': expected " + std::to_string(n) +
                            " counts >= 1 joined by x (e.g. " + example + ")";
  size_t start = 0;
  for (int k = 0; k < n; ++k) {
    const size_t x = text.find('x', start);
    if ((k < n - 1) != (x != std::string::npos)) throw InputError(usage);
    const std::string item = text.substr(start, k < n - 1 ? x - start : std::string::npos);
    if (item.empty() || item.size() > 4 ||
        item.find_first_not_of("0123456789") != std::string::npos)
      throw InputError(usage);
    counts[k] = std::stoi(item);
    if (counts[k] < 1) throw InputError(usage);
    start = x + 1;
  }
}

bool IsPatchKind(const std::string& kind) {
  return kind == "quadric-patch" || kind == "cubic-patch";
}

const std::vector<std::string>& FitCommandKinds() {
  static const std::vector<std::string> kinds = {
      "plane",           "sphere",        "cylinder",   "cone",    "torus",      "quadric-patch",
      "cubic-patch",     "box",           "paraboloid", "capsule", "patch-mesh", "partition",
      "bspline-surface", "bspline-volume"};
  return kinds;
}

std::string FitCommandKindList() {
  std::string list;
  for (const std::string& kind : FitCommandKinds()) list += (list.empty() ? "" : ", ") + kind;
  return list;
}

int RunTreeFit(const ModelFitRequest& request) {
  const Model init = ReadModelFile(request.init);
  std::string normals;
  const PointCloud cloud = ReadOrientedCloud(request.cloud, &normals);
  const TreeFitResult r = FitModelTree(init, cloud.points, cloud.normals, CommandLineTreeFitOptions());
  const nlohmann::json report = r.ToJson(normals);
  if (!r.success) {
    if (!request.report.empty()) WriteReportFile(request.report, report);
    std::cerr << "implicitfit fit: " << request.cloud << ": model tree fit failed: " << r.message
              << "\n";
    return 1;
  }
  Finish(request, r.model, report);
  std::printf("%s\n", r.BriefReport().c_str());
  return 0;
}

void AddTreeFitFigures(const TreeFitResult& r, const Model& start,
                       const std::vector<Eigen::Vector3d>& points, const std::string& normals,
                       nlohmann::json* report) {
  report->update(r.ToJson(normals));
  // Standard deviations at the optimum from the inliers (|f / |grad f|| < 3 sigma), as the
  // primitives' (fit/tree/tree_covariance.h).
  std::vector<Eigen::Vector3d> inliers;
  for (const Eigen::Vector3d& x : points) {
    double f;
    const double g = r.model.Gradient(x, &f).norm();
    if (g > 0 && std::abs(f / g) < 3.0 * r.sigma) inliers.push_back(x);
  }
  const std::vector<double> sd = TreeStandardDeviations(r.model, inliers);
  const std::vector<std::string> names = r.model.ParameterNames();
  for (size_t i = 0; i < names.size(); ++i) {
    (*report)["parameters"][names[i]] = r.model.parameters()[i];
    (*report)["standard_deviations"][names[i]] = sd[i];
    (*report)["start"][names[i]] = start.parameters()[i];
  }
}

bool IsShapeKind(const std::string& kind) { return IsShapeStartKind(kind); }

int RunShapeFit(const ModelFitRequest& request, unsigned seed) {
  std::string normals;
  const PointCloud cloud = ReadOrientedCloud(request.cloud, &normals);
  const ShapeStart start = RobustShapeStart(request.kind, cloud.points, cloud.normals, seed);
  nlohmann::json report = {{"kind", request.kind}, {"points", cloud.size()}, {"normals", normals}};
  if (!start.success) {
    report["success"] = false;
    report["message"] = start.message;
    if (!request.report.empty()) WriteReportFile(request.report, report);
    std::cerr << "implicitfit fit: " << request.cloud << ": " << request.kind
              << " fit failed: " << start.message << "\n";
    return 1;
  }
  const TreeFitResult r = FitModelTree(start.model, cloud.points, cloud.normals, CommandLineTreeFitOptions());
  AddTreeFitFigures(r, start.model, cloud.points, normals, &report);
  if (!r.success) {
    if (!request.report.empty()) WriteReportFile(request.report, report);
    std::cerr << "implicitfit fit: " << request.cloud << ": " << request.kind
              << " fit failed: " << r.message << "\n";
    return 1;
  }
  Finish(request, r.model, report);
  std::printf("%s\n", r.BriefReport().c_str());
  return 0;
}

ModelKindFit FitPatchCloud(const ModelFitRequest& request) {
  PatchFitOptions options;
  options.degree = request.degree > 0 ? request.degree : (request.kind == "cubic-patch" ? 3 : 2);
  options.convex = request.convex;
  if (!request.tetrahedron.empty()) {
    if (request.tetrahedron.size() != 12)
      throw InputError("--tetrahedron takes 12 numbers (4 vertices x y z)");
    try {
      options.tetrahedron = Tetrahedron::FromArray(request.tetrahedron.data());
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string("--tetrahedron: ") + e.what());
    }
    options.has_tetrahedron = true;
  }
  options.constraints = ShapeConstraintsFromArguments(request);
  std::string error;
  if (!options.IsValid(&error)) throw InputError(error);
  std::string normals;
  const PointCloud cloud = ReadOrientedCloud(request.cloud, &normals);
  const PatchFitResult r = FitBernsteinPatch(cloud.points, cloud.normals, options);
  ModelKindFit fit = MakeModelKindFit(r, r.ToJson(normals), cloud.size());
  fit.brief = r.BriefReport();
  return fit;
}

int RunPatchFit(const ModelFitRequest& request) {
  const ModelKindFit fit = FitPatchCloud(request);
  const nlohmann::json& report = fit.report;
  if (!fit.success) {
    if (!request.report.empty()) WriteReportFile(request.report, report);
    std::cerr << "implicitfit fit: " << request.cloud << ": patch fit failed: " << fit.message
              << "\n";
    return 1;
  }
  Finish(request, fit.model, report);
  std::printf("%s\n", fit.brief.c_str());
  return 0;
}

}  // namespace implicitfit
