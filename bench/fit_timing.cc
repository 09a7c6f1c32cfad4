// The C++ baseline of bench/python_comparison.py: times FitPrimitive (the call implicitfit.fit
// makes) on a cloud file, in process, excluding reading the file.
//   fit_timing CLOUD KIND SEED REPEATS
// prints {"seconds": [wall time of each call], "untimed": [wall time minus the result's own
// `seconds`, i.e. the part of the call the fitter does not time: validation, teardown of the
// Ceres problem], "model": the fitted model's JSON text}.
#include <glog/logging.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "datasets/normals/oriented_cloud.h"
#include "fit/primitive/primitive_fitter.h"
#include "model/file/model_json.h"

int main(int argc, char** argv) {
  using namespace implicitfit;
  FLAGS_minloglevel = google::GLOG_ERROR;  // as the command line and the Python module
  if (argc != 5) {
    std::cerr << "usage: fit_timing CLOUD KIND SEED REPEATS\n";
    return 2;
  }
  PrimitiveFitOptions options;
  if (!FittableKindFromName(argv[2], &options.kind)) {
    std::cerr << "fit_timing: unknown kind " << argv[2] << "\n";
    return 2;
  }
  options.seed = static_cast<unsigned>(std::strtoul(argv[3], nullptr, 10));
  const int repeats = std::atoi(argv[4]);
  try {
    const PointCloud cloud = ReadOrientedCloud(argv[1], nullptr);
    nlohmann::json out;
    out["seconds"] = nlohmann::json::array();
    out["untimed"] = nlohmann::json::array();
    PrimitiveFitResult result;
    for (int r = 0; r < repeats; ++r) {
      const auto start = std::chrono::steady_clock::now();
      result = FitPrimitive(cloud.points, cloud.normals, options);
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      out["seconds"].push_back(wall);
      out["untimed"].push_back(wall - result.seconds);
    }
    out["model"] = result.success ? ModelToJson(result.ToModel(options.kind)).dump(2) : "";
    std::cout << out.dump() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "fit_timing: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
