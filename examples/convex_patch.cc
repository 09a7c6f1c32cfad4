// Fits a convex quadric Bernstein patch to noisy points of an ellipsoid cap and certifies it:
// every A^mu matrix of Guo's certificate is positive definite, so the patch is convex.
#include <cmath>
#include <cstdio>
#include <random>

#include "implicitfit/implicitfit.h"

int main() {
  // 1500 points of the cap z > 0.3 of the ellipsoid (x/1)^2 + (y/0.7)^2 + (z/0.5)^2 = 1, with
  // outward normals and noise 0.002 along them.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI), height(0.3 / 0.5, 1.0);
  std::normal_distribution<double> noise(0.0, 0.002);
  const Eigen::Vector3d radii(1.0, 0.7, 0.5);
  std::vector<Eigen::Vector3d> points, normals;
  while (points.size() < 1500) {
    const double c = height(rng), s = std::sqrt(1.0 - c * c), a = angle(rng);
    const Eigen::Vector3d u(s * std::cos(a), s * std::sin(a), c);  // on the unit sphere
    const Eigen::Vector3d n = u.cwiseQuotient(radii).normalized();
    points.push_back(u.cwiseProduct(radii) + noise(rng) * n);
    normals.push_back(n);
  }

  implicitfit::PatchFitOptions options;
  options.degree = 2;
  options.convex = true;
  const implicitfit::PatchFitResult fit = implicitfit::FitBernsteinPatch(points, normals, options);
  if (!fit.success) {
    std::fprintf(stderr, "no convex patch: %s\n", fit.message.c_str());
    return 1;
  }
  // An independent check of the result: the certificate, recomputed from the control points.
  const implicitfit::ConvexityCertificate certificate =
      implicitfit::CertifyConvexity(fit.degree, fit.control_points.data());
  std::printf(
      "degree %d patch, RMS distance %.4g (unconstrained %.4g), mean normal angle %.2f deg\n",
      fit.degree, fit.rms, fit.unconstrained_rms, fit.mean_normal_angle_deg);
  std::printf("certified convex: %s (smallest A^mu eigenvalue %.4g over %d matrices)\n",
              certificate.convex ? "yes" : "no", certificate.min_eigenvalue,
              certificate.num_matrices);
  std::printf("%s\n", implicitfit::ModelToJson(fit.ToModel()).dump().c_str());
  return certificate.convex ? 0 : 1;
}
