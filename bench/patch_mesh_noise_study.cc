// How far the patch-mesh fit (fit/bernstein/bernstein_mesh_fitter.h) lies from the truth on the generated
// clouds of bench/surface_comparison (same shapes, same sampling, same noise), without meshing:
// the fitted zero set's signed distance to each of 20 000 noise-free truth points, measured along
// the truth normal by Newton steps on t -> f(x + t n). Prints the fit's RMS of f/|grad f| (against
// the noisy input), the mean |distance| (~ truth->mesh half of the Chamfer distance), the mean
// signed distance (bias: > 0 the fit lies outside the truth) and the RMS distance; with
// --noise-free the same fit on the noise-free cloud (its distance is the approximation error
// alone, so the difference is the part that follows the noise).
//   build/bench/patch_mesh_noise_study [--shape torus|union|ellipsoid] [--points 20000]
//       [--seed 1] [--noise-free 0|1] [--degree k] [--cells n] [--normal-weight w]
//       [--smoothing-weight w] [--far-field-weight w] [--far-field-ramp r]
//       [--far-field-relaxation r (0: the refinement before issue 11's relaxation)]
//       [--max-iterations n]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "datasets/generators/model_sampler.h"
#include "fit/bernstein/bernstein_mesh_fitter.h"
#include "model/bernstein/bernstein_patch.h"

namespace {

using Vec = Eigen::Vector3d;

double Evaluate(const implicitfit::MeshFitResult& r, const Vec& x, Vec* g) {
  const long long n = implicitfit::NumBernsteinControlPoints(r.degree);
  double tau[4];
  const long long t = r.grid.Locate(x.data(), tau);
  return implicitfit::BernsteinPatch::Derivatives(r.degree, r.grid.TetrahedronOf(t),
                                                  r.control_points.data() + t * n, x.data(), g);
}

}  // namespace

int main(int argc, char** argv) {
  std::string shape = "torus";
  int points = 20000;
  unsigned seed = 1;
  bool noise_free = false;
  implicitfit::MeshFitOptions fo;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    const char* v = argv[i + 1];
    if (a == "--shape")
      shape = v;
    else if (a == "--points")
      points = std::atoi(v);
    else if (a == "--seed")
      seed = static_cast<unsigned>(std::atoi(v));
    else if (a == "--noise-free")
      noise_free = std::atoi(v) != 0;
    else if (a == "--degree")
      fo.degree = std::atoi(v);
    else if (a == "--cells")
      fo.cells = std::atoi(v);
    else if (a == "--normal-weight")
      fo.normal_weight = std::atof(v);
    else if (a == "--smoothing-weight")
      fo.smoothing_weight = std::atof(v);
    else if (a == "--far-field-weight")
      fo.far_field_weight = std::atof(v);
    else if (a == "--far-field-ramp")
      fo.far_field_ramp = std::atof(v);
    else if (a == "--far-field-relaxation")
      fo.far_field_relaxation = std::atof(v);
    else if (a == "--max-iterations")
      fo.max_iterations = std::atoi(v);
    else {
      std::fprintf(stderr, "unknown option %s\n", a.c_str());
      return 2;
    }
  }
  implicitfit::Model m;
  if (shape == "torus") {
    m.AddPrimitive(implicitfit::NodeType::kTorus, {0, 0, 0, 0, 0, 1, 1.0, 0.35});
  } else if (shape == "ellipsoid") {
    m.AddPrimitive(implicitfit::NodeType::kEllipsoid, {0, 0, 0, 1.0, 0.7, 0.5, 1, 0, 0, 0, 1, 0});
  } else if (shape == "union") {
    const int a = m.AddPrimitive(implicitfit::NodeType::kSphere, {-0.4, 0, 0, 0.6});
    const int b = m.AddPrimitive(implicitfit::NodeType::kSphere, {0.4, 0, 0, 0.6});
    m.AddOperator(implicitfit::NodeType::kUnion, {a, b}, 0.1, 0.1, 3);
  } else {
    std::fprintf(stderr, "unknown shape %s\n", shape.c_str());
    return 2;
  }
  // The sampling of bench/surface_comparison.cc (AddGenerated).
  implicitfit::SampleOptions so;
  so.count = points;
  so.seed = seed;
  const implicitfit::SampledCloud clean = implicitfit::SampleModel(m, so);
  const double size = (clean.box_max - clean.box_min).maxCoeff() / 1.1;
  so.noise = noise_free ? 0.0 : 0.002 * size;
  so.seed = seed + 1000;
  const implicitfit::SampledCloud noisy = implicitfit::SampleModel(m, so);
  const auto start = std::chrono::steady_clock::now();
  const implicitfit::MeshFitResult r =
      implicitfit::FitBernsteinMesh(noisy.cloud.points, noisy.cloud.normals, fo);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!r.success) {
    std::fprintf(stderr, "fit failed: %s\n", r.message.c_str());
    return 1;
  }
  double sum_abs = 0, sum = 0, sum2 = 0;
  const auto& truth = clean.cloud;
  for (size_t i = 0; i < truth.points.size(); ++i) {
    const Vec& x = truth.points[i];
    const Vec& nrm = truth.normals[i];
    double t = 0;
    for (int it = 0; it < 8; ++it) {
      Vec g;
      const double f = Evaluate(r, x + t * nrm, &g);
      const double slope = g.dot(nrm);
      if (std::abs(slope) < 1e-12) break;
      t -= f / slope;
    }
    // t: the fitted surface lies at x + t n (t > 0: outside the truth).
    sum_abs += std::abs(t);
    sum += t;
    sum2 += t * t;
  }
  const double count = static_cast<double>(truth.points.size());
  std::printf(
      "%s degree %d cells %d noise %.2e (sigma) | fit rms %.3e (start %.3e) | truth distance: mean "
      "|d| %.3e "
      "(%.3f sigma), mean d %+.2e, rms %.3e | %lld patches, %d iterations, %.1f s, box sign "
      "errors %lld\n",
      shape.c_str(), fo.degree, fo.cells, 0.002 * size, r.rms, r.initial_rms, sum_abs / count,
      sum_abs / count / (0.002 * size), sum / count, std::sqrt(sum2 / count), r.tetrahedra,
      r.iterations, seconds, r.box_sign_errors);
  return 0;
}
