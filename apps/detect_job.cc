#include "apps/detect_job.h"

#include <map>
#include <sstream>

#include "datasets/io/io_error.h"
#include "datasets/normals/neighbourhoods.h"
#include "datasets/normals/oriented_cloud.h"
#include "datasets/clouds/ply_writer.h"
#include "fit/primitive/primitive_fitter.h"
#include "fit/splines/freeform_detection.h"

namespace implicitfit {

std::vector<NodeType> DetectionKindsFromList(const std::string& list) {
  std::vector<NodeType> kinds;
  std::stringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) {
    NodeType kind;
    if (!FittableKindFromName(name, &kind))
      throw InputError("--kinds: '" + name +
                       "' is not one of plane, sphere, cylinder, cone, torus");
    if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) kinds.push_back(kind);
  }
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
  fo.min_points = std::max(r.min_points, 1);
  fo.num_threads = options.num_threads;
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
  d->report["freeform"] = {{"surfaces", f.surfaces.size()}, {"points", assigned},
                           {"regions", f.regions},          {"region_points", f.region_points},
                           {"fits", f.fits},                {"splits", f.splits},
                           {"seconds", f.seconds},
                           {"rejected", {{"folded", f.folded}, {"no_grid", f.no_grid},
                                         {"small_support", f.small_support},
                                         {"rms_over_2_sigma", f.rms_over},
                                         {"small_parts", f.small_parts},
                                         {"small_part_points", f.small_part_points},
                                         {"depth_limit", f.depth_limit}}}};
  if (!f.surfaces.empty()) d->report["kinds"]["bspline_surface"] = f.surfaces.size();
}

}  // namespace

CloudDetection DetectCloudFile(const std::string& path, const DetectionOptions& options,
                               bool freeform) {
  CloudDetection d;
  std::string normals_action;
  d.cloud = ReadOrientedCloud(path, &normals_action);
  const size_t N = d.cloud.size();
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
    return d;
  }
  const Neighbourhoods nb = FindNeighbourhoods(d.cloud.points);
  d.result = DetectPrimitives(d.cloud.points, d.cloud.normals, nb.indices, nb.spacing, options);
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
  if (freeform) AddFreeformSurfaces(nb, options, &d);
  return d;
}

void WriteDetection(const CloudDetection& d, const std::string& scene_path,
                    const std::string& labels_path, const std::string& ply_path) {
  WriteSceneFile(d.scene, scene_path);
  if (!labels_path.empty()) WriteLabelsFile(d.result.labels, labels_path);
  if (!ply_path.empty()) {
    PlyWriteOptions o;
    o.labels = d.result.labels;
    o.single = true;
    std::vector<double> residuals = d.result.residuals;
    residuals.resize(d.cloud.size(), 0.0);
    WritePlyFile(d.cloud, ply_path, residuals, o);
  }
}

}  // namespace implicitfit
