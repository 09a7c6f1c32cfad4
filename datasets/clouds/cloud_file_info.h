// What a cloud reader found in a file besides the points: the format, how many records were
// dropped and why, whether the file had normals (and which were unusable), the sensor viewpoint
// when the file gives one. Filled by ReadCloudFile and the per-format readers; reports and the
// normal handling (normal_estimation.h) read it.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace implicitfit {

struct CloudFileInfo {
  // "xyz", "ply ascii", "ply binary_little_endian", "pcd binary_compressed", ...
  std::string format;
  // Point records in the file (an organized cloud counts every cell: width x height).
  size_t records = 0;
  // Records dropped because x, y or z is NaN: "no measurement" in PCD and organized clouds.
  size_t dropped_missing = 0;
  // The file has per-point normals (nx ny nz, or PCL's normal_x normal_y normal_z).
  bool normals_in_file = false;
  // Indices (into the returned cloud) whose file normal was NaN, infinite or zero-length.
  // The per-format readers leave a zero vector there; ReadCloudFile replaces each by a
  // re-estimated normal, or drops all normals when every one was invalid.
  std::vector<size_t> invalid_normals;
  // Sensor origin given by the file (PCD VIEWPOINT, PLY camera element), if any.
  std::optional<Eigen::Vector3d> viewpoint;
  // Organized clouds (PCD HEIGHT > 1, PLY range_grid): the grid size; 0 x 0 otherwise.
  size_t grid_width = 0, grid_height = 0;
  // Per-point properties present in the file and deliberately not used (colour, intensity,
  // labels, curvature, ...).
  std::vector<std::string> ignored_properties;
  // Per-point integer labels: of labelled text clouds (.xyzl: "x y z label", e.g. the Fit4CAD
  // primitive number) and of PLY/PCD files with a "label" property (e.g. `detect --ply`);
  // empty otherwise. The fits ignore them (PLY/PCD list them in ignored_properties).
  std::vector<int> labels;
  // Per-point "residual" property of PLY/PCD files (`detect --ply`, `fit --ply`); empty otherwise.
  std::vector<double> residuals;
};

}  // namespace implicitfit
