#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "datasets/clouds/ply_writer.h"
#include "datasets/clouds/spatial_order.h"
#include "datasets/io/io_error.h"
#include "datasets/normals/neighbourhoods.h"
#include "datasets/normals/oriented_cloud.h"
#include "fit/primitive/primitive_fitter.h"
#include "fit/splines/freeform_detection.h"
#include "implicitfit/detect.h"

namespace implicitfit {
namespace {

// A colour per primitive: hues spread by the golden ratio (neighbouring indices far apart),
// full saturation, value 0.9; unassigned points grey.
std::array<std::uint8_t, 3> PrimitiveColour(int label) {
  if (label < 0) return {128, 128, 128};
  const double h = std::fmod(0.61803398875 * label, 1.0) * 6.0;
  const double v = 0.9, x = v * (1.0 - std::abs(std::fmod(h, 2.0) - 1.0));
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(h)) {
    case 0: r = v, g = x; break;
    case 1: r = x, g = v; break;
    case 2: g = v, b = x; break;
    case 3: g = x, b = v; break;
    case 4: r = x, b = v; break;
    default: r = v, b = x; break;
  }
  auto byte = [](double c) { return static_cast<std::uint8_t>(std::lround(255.0 * c)); };
  return {byte(r), byte(g), byte(b)};
}

// The detection of a cloud put in spatial order, back in the file's order.
void RestoreFileOrder(const std::vector<size_t>& order, CloudDetection* d) {
  d->result.labels = RestoreOrder(order, d->result.labels);
  d->result.residuals = RestoreOrder(order, d->result.residuals);
  if (!d->info.labels.empty()) d->info.labels = RestoreOrder(order, d->info.labels);
  d->cloud.points = RestoreOrder(order, d->cloud.points);
  d->cloud.normals = RestoreOrder(order, d->cloud.normals);
  for (DetectedPrimitive& p : d->result.primitives) {
    for (int& i : p.points) i = static_cast<int>(order[i]);
    std::sort(p.points.begin(), p.points.end());
  }
}

void Tell(const DetectionOptions& options, const std::string& message) {
  if (options.progress) options.progress(message);
}

}  // namespace

std::vector<NodeType> DetectionKindsFromList(const std::string& list) {
  std::vector<NodeType> kinds;
  for (NodeType kind : ParseKindList(list, "--kinds"))
    if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) kinds.push_back(kind);
  if (kinds.empty()) throw InputError("--kinds: no kind given");
  return kinds;
}

namespace {

// detect --freeform: the smooth remainder as bspline_surface primitives, appended to the scene.
void AddFreeformSurfaces(const Neighbourhoods& nb, const DetectionOptions& options,
                         CloudDetection* d) {
  DetectionResult& r = d->result;
  FreeformOptions fo;
  fo.noise = r.noise > 0 ? r.noise : 0.1 * r.threshold;
  fo.threshold = r.threshold;
  fo.normal_angle_deg = r.normal_angle_deg;
  fo.spacing = r.spacing;
  fo.min_points = std::max(r.min_points, 1);
  fo.num_threads = options.num_threads;
  fo.progress = options.progress;
  const FreeformResult f =
      DetectFreeformSurfaces(d->cloud.points, d->cloud.normals, nb.indices, fo,
                             static_cast<int>(d->scene.primitives.size()), &r.labels, &r.residuals);
  int assigned = 0;
  for (const FreeformSurface& s : f.surfaces) {
    ScenePrimitive p;
    p.name = "p" + std::to_string(d->scene.primitives.size());
    p.model = s.model;
    p.points = static_cast<int>(s.points.size());
    p.rms_distance = s.rms_distance;
    p.normal_side = s.normal_side;
    d->scene.primitives.push_back(std::move(p));
    assigned += static_cast<int>(s.points.size());
  }
  d->scene.unassigned -= assigned;
  d->report["unassigned"] = d->scene.unassigned;
  d->report["primitives"] = d->scene.primitives.size();
  d->report["freeform"] = {{"surfaces", f.surfaces.size()},
                           {"points", assigned},
                           {"regions", f.regions},
                           {"region_points", f.region_points},
                           {"fits", f.fits},
                           {"splits", f.splits},
                           {"grown", f.grown},
                           {"seconds", f.seconds},
                           {"rejected",
                            {{"folded", f.folded},
                             {"no_grid", f.no_grid},
                             {"small_support", f.small_support},
                             {"rms_over_2_sigma", f.rms_over},
                             {"small_parts", f.small_parts},
                             {"small_part_points", f.small_part_points},
                             {"depth_limit", f.depth_limit},
                             {"volume", f.volume}}},
                           {"lost_points", f.lost_points}};
  if (!f.surfaces.empty()) d->report["kinds"]["bspline_surface"] = f.surfaces.size();
}

// The detection of a cloud already read: `nb` its neighbourhoods (computed here when empty),
// `order` its spatial order (empty: the cloud is in the file's order), `start` when reading began.
CloudDetection DetectPrepared(PointCloud cloud, CloudFileInfo info, Neighbourhoods nb,
                              const std::vector<size_t>& order, const std::string& path,
                              const std::string& normals_action,
                              std::chrono::steady_clock::time_point start,
                              const DetectionOptions& options, bool freeform) {
  CloudDetection d;
  d.options = options;
  d.freeform = freeform;
  d.cloud = std::move(cloud);
  d.info = std::move(info);
  const size_t N = d.cloud.size();
  d.points = N;
  d.scene.cloud = path;
  d.scene.points = static_cast<int>(N);
  d.report["cloud"] = path;
  d.report["points"] = N;
  d.report["normals"] = normals_action;
  if (!d.cloud.has_normals() || N < 3) {
    d.degenerate = true;
    d.result.labels.assign(N, -1);
    d.scene.unassigned = static_cast<int>(N);
    d.report["primitives"] = 0;
    d.report["unassigned"] = N;
    d.message = "no primitive found (too few points to estimate normals)";
    return d;
  }
  if (nb.indices.size() != N) nb = FindNeighbourhoods(d.cloud.points);
  char line[160];
  std::snprintf(line, sizeof line, "%zu points read, normals %s, neighbourhoods in %.1f s", N,
                normals_action.c_str(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  Tell(options, line);
  d.result = DetectPrimitives(d.cloud.points, d.cloud.normals, nb.indices, nb.spacing, options);
  if (!freeform) nb = Neighbourhoods();
  if (!order.empty()) RestoreFileOrder(order, &d);
  const DetectionResult& r = d.result;
  std::map<std::string, int> kinds;
  int assigned = 0;
  for (size_t k = 0; k < r.primitives.size(); ++k) {
    const DetectedPrimitive& p = r.primitives[k];
    ScenePrimitive s;
    s.name = "p" + std::to_string(k);
    s.model.AddPrimitive(p.kind, p.parameters);
    s.points = static_cast<int>(p.points.size());
    s.rms_distance = p.rms_distance;
    if (!p.standard_deviations.empty()) {
      const std::vector<std::string> names = s.model.ParameterNames();
      for (size_t i = 0; i < names.size(); ++i)
        s.standard_deviations[names[i].substr(names[i].find('.') + 1)] = p.standard_deviations[i];
    }
    s.normal_side = p.normal_side;
    d.scene.primitives.push_back(std::move(s));
    ++kinds[NodeTypeName(p.kind)];
    assigned += static_cast<int>(p.points.size());
  }
  d.scene.unassigned = static_cast<int>(N) - assigned;
  d.report["primitives"] = r.primitives.size();
  d.report["unassigned"] = d.scene.unassigned;
  d.report["kinds"] = kinds;
  d.report["spacing"] = r.spacing;
  d.report["noise"] = r.noise;
  d.report["threshold"] = r.threshold;
  d.report["normal_angle_deg"] = r.normal_angle_deg;
  d.report["min_points"] = r.min_points;
  d.report["seeds"] = r.seeds;
  d.report["candidates_accepted"] = r.candidates_accepted;
  d.report["merges"] = r.merges;
  d.report["seconds"] = r.seconds;
  if (freeform) {
    if (!order.empty()) nb = FindNeighbourhoods(d.cloud.points);  // in the file's order now
    AddFreeformSurfaces(nb, options, &d);
  }
  d.success = !d.scene.primitives.empty();
  d.termination = d.success ? FitTermination::kConverged : FitTermination::kFailure;
  d.message = d.success ? "detected" : "no primitive found";
  d.seconds = r.seconds;
  return d;
}

}  // namespace

CloudDetection DetectCloudFile(const std::string& path, const DetectionOptions& options,
                               bool freeform) {
  const auto start = std::chrono::steady_clock::now();
  Tell(options, "reading " + path);
  std::string normals_action;
  CloudFileInfo info;
  Neighbourhoods nb;
  std::vector<size_t> order;  // large clouds are detected in Morton order (locality)
  PointCloud cloud = ReadOrientedCloud(path, &normals_action, true, &info, &nb, &order);
  return DetectPrepared(std::move(cloud), std::move(info), std::move(nb), order, path,
                        normals_action, start, options, freeform);
}

CloudDetection DetectCloud(PointCloud cloud, const std::string& path,
                           const std::string& normals_action, const DetectionOptions& options) {
  return DetectPrepared(std::move(cloud), CloudFileInfo(), Neighbourhoods(), {}, path,
                        normals_action, std::chrono::steady_clock::now(), options, false);
}

std::string CloudDetection::BriefReport() const {
  char line[200];
  std::snprintf(line, sizeof line,
                "points %d  primitives %zu  unassigned %d  threshold %.6g  %.3f s", scene.points,
                scene.primitives.size(), scene.unassigned, result.threshold, result.seconds);
  return line;
}

nlohmann::json CloudDetection::ToJson(const ReportHeader& header) const {
  std::string kinds;
  for (NodeType k : options.kinds)
    kinds += (kinds.empty() ? "" : ",") + std::string(NodeTypeName(k));
  const nlohmann::json settings = {{"kinds", kinds},
                                   {"threshold", options.threshold},
                                   {"normal_angle_deg", options.normal_angle_deg},
                                   {"min_points", options.min_points},
                                   {"seed", options.seed},
                                   {"threads", options.num_threads},
                                   {"freeform", freeform}};
  return WithJobReportHeader(report, header, "detect", settings, scene.cloud);
}

void WriteDetection(const CloudDetection& d, const std::string& scene_path,
                    const std::string& labels_path, const std::string& ply_path) {
  WriteSceneFile(d.scene, scene_path);
  if (!labels_path.empty()) WriteLabelsFile(d.result.labels, labels_path);
  if (!ply_path.empty()) {
    PlyWriteOptions o;
    o.labels = d.result.labels;
    o.labels.resize(d.cloud.size(), -1);
    o.cloudcompare_fields = true;
    o.colours.reserve(o.labels.size());
    for (int l : o.labels) o.colours.push_back(PrimitiveColour(l));
    std::vector<double> residuals = d.result.residuals;
    residuals.resize(d.cloud.size(), 0.0);
    WritePlyFile(d.cloud, ply_path, residuals, o);
  }
}

TruthLabels LoadTruth(const CloudDetection& d, const TruthRequest& request) {
  const long N = static_cast<long>(d.cloud.size());
  TruthLabels t;
  if (!request.file.empty()) {
    t = ReadTruthFile(request.file, N, request.none);
  } else {
    if (d.info.labels.empty())
      throw FileError(d.scene.cloud,
                      "--score: the cloud has no labels (an .xyzl label column, or a PLY/PCD "
                      "property label, scalar_label or segment_index); give them with --truth");
    if (static_cast<long>(d.info.labels.size()) != N)
      throw FileError(d.scene.cloud, "--score: " + std::to_string(d.info.labels.size()) +
                                         " labels for " + std::to_string(N) + " points");
    t = TruthFromValues(std::vector<long>(d.info.labels.begin(), d.info.labels.end()),
                        request.none, d.scene.cloud);
  }
  if (!request.kinds.empty()) {
    t.kinds = ParseKindList(request.kinds, "--truth-kinds");
    if (t.kinds.size() != t.ids.size())
      throw InputError("--truth-kinds: " + std::to_string(t.kinds.size()) + " kinds for the " +
                       std::to_string(t.ids.size()) + " labelled primitives of " + t.source);
  }
  if (t.ids.empty()) throw FileError(t.source, "no point carries a primitive label");
  return t;
}

DetectionScore ScoreDetection(const CloudDetection& d, const TruthLabels& truth) {
  DetectionScore s;
  std::vector<NodeType> kinds;
  for (const DetectedPrimitive& p : d.result.primitives) kinds.push_back(p.kind);
  std::vector<int> detected = d.result.labels;
  detected.resize(truth.labels.size(), -1);
  s.kinds_known = !truth.kinds.empty();
  s.truth_primitives = static_cast<int>(truth.ids.size());
  s.metrics = s.kinds_known
                  ? CompareSegmentations(truth.labels, truth.kinds, detected, kinds)
                  : CompareSegmentationsWithoutKinds(truth.labels, s.truth_primitives, detected,
                                                     kinds);
  return s;
}

nlohmann::json DetectionScore::ToJson() const {
  const SegmentationMetrics& m = metrics;
  nlohmann::json j = {{"truth_primitives", truth_primitives},
                      {"truth_counted", m.truth_counted},
                      {"recovered", m.recovered},
                      {"recall", m.recall},
                      {"detected_counted", m.detected_counted},
                      {"precise", m.precise},
                      {"precision", m.precision},
                      {"mean_iou", m.mean_iou},
                      {"coverage", m.coverage},
                      {"kinds_known", kinds_known}};
  j["kind_accuracy"] = kinds_known ? nlohmann::json(m.kind_accuracy) : nlohmann::json(nullptr);
  return j;
}

std::string DetectionScore::Line() const {
  const SegmentationMetrics& m = metrics;
  char line[320];
  char kind[64] = "kind accuracy n/a (no truth kinds)";
  if (kinds_known) std::snprintf(kind, sizeof kind, "kind accuracy %.3f", m.kind_accuracy);
  std::snprintf(line, sizeof line,
                "recall %d/%d (%.1f%%)  precision %d/%d (%.1f%%)  mean IoU %.3f  %s  coverage "
                "%.3f  (truth primitives with >= 1%% of the points: %d of %d)",
                m.recovered, m.truth_counted, 100.0 * m.recall, m.precise, m.detected_counted,
                100.0 * m.precision, m.mean_iou, kind, m.coverage, m.truth_counted,
                truth_primitives);
  return line;
}

}  // namespace implicitfit
