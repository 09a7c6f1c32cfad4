// The files of the hostile cases: valid clouds and models to start from, headers to forge.
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

#include "apps/hostile/hostile_case.h"
#include "support/fibonacci_sphere.h"

namespace hostile {
namespace {
struct Triple {
  double x, y, z;
};
}  // namespace

void Write(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string PlaneXyz(int n, bool normals, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> g(0.0, noise);
  std::ostringstream s;
  s.precision(9);
  const double nx = -0.1 / std::sqrt(1.01), nz = 1.0 / std::sqrt(1.01);
  for (int i = 0; i < n; ++i) {
    const double x = u(rng), y = u(rng);
    s << x << ' ' << y << ' ' << 0.1 * x + g(rng);
    if (normals) s << ' ' << nx << " 0 " << nz;
    s << '\n';
  }
  return s.str();
}

std::string SphereXyz(int n, double radius, bool normals) {
  std::ostringstream s;
  s.precision(12);
  for (const Eigen::Vector3d& u : testsupport::FibonacciSphere(n)) {  // even, deterministic
    const double x = u.x(), y = u.y(), z = u.z();
    s << radius * x << ' ' << radius * y << ' ' << radius * z;
    if (normals) s << ' ' << x << ' ' << y << ' ' << z;
    s << '\n';
  }
  return s.str();
}

std::string NoisySphereXyz(int n, double noise) {
  std::mt19937 rng(2);
  std::normal_distribution<double> g(0.0, 1.0);
  std::ostringstream s;
  s.precision(12);
  for (int i = 0; i < n; ++i) {
    Triple v{g(rng), g(rng), g(rng)};
    const double norm = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    const double r = 1.0 + noise * g(rng);
    s << r * v.x / norm << ' ' << r * v.y / norm << ' ' << r * v.z / norm << '\n';
  }
  return s.str();
}

std::string PlyBinaryHeader(long long vertices, const std::string& extra_properties) {
  return "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\n" + extra_properties +
         "end_header\n";
}

std::string PlyAsciiPoints(int n) {
  std::string body = SphereXyz(n, 1.0, false);
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(n) +
         "\nproperty float x\nproperty float y\nproperty float z\nend_header\n" + body;
}

std::string PcdHeader(const std::string& data, long long points, const std::string& fields,
                      const std::string& size, const std::string& type, const std::string& count) {
  return "# .PCD v0.7\nVERSION 0.7\nFIELDS " + fields + "\nSIZE " + size + "\nTYPE " + type +
         "\nCOUNT " + count + "\nWIDTH " + std::to_string(points) +
         "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(points) + "\nDATA " +
         data + "\n";
}

std::string SphereModel(double radius) {
  std::ostringstream s;
  s.precision(17);
  s << "{\"format\": \"implicitfit-model\", \"version\": 1, \"root\": {\"type\": \"sphere\", "
       "\"center\": [0, 0, 0], \"radius\": "
    << radius << "}}\n";
  return s.str();
}

std::string PlaneModel() {
  return "{\"format\": \"implicitfit-model\", \"version\": 1, \"root\": {\"type\": \"plane\", "
         "\"normal\": [0, 0, 1], \"offset\": 0}}\n";
}

std::string PatchModel(int degree) {
  const long long k = degree, count = (k + 1) * (k + 2) * (k + 3) / 6;
  std::string cp;
  cp.reserve(count * 3);
  for (long long i = 0; i < count; ++i) cp += (i ? ",1" : "1");
  return "{\"format\": \"implicitfit-model\", \"version\": 1, \"root\": {\"type\": "
         "\"bernstein_patch\", \"degree\": " +
         std::to_string(degree) +
         ", \"vertices\": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], \"control_points\": [" + cp + "]}}\n";
}

std::string BlobsModel(int count) {
  std::string centers, ones;
  for (int i = 0; i < count; ++i) {
    centers += (i ? "," : "") + std::string("[") + std::to_string(i * 0.01) + ",0,0]";
    ones += i ? ",0.1" : "0.1";
  }
  return "{\"format\": \"implicitfit-model\", \"version\": 1, \"root\": {\"type\": \"blobs\", "
         "\"centers\": [" +
         centers + "], \"weights\": [" + ones + "], \"widths\": [" + ones +
         "], \"threshold\": 0.05, \"kernel\": \"gaussian\"}}\n";
}

std::string WideUnionModel(int children) {
  std::string list;
  for (int i = 0; i < children; ++i)
    list += (i ? "," : "") + std::string("{\"type\": \"sphere\", \"center\": [") +
            std::to_string(i) + ",0,0], \"radius\": 0.4}";
  return "{\"format\": \"implicitfit-model\", \"version\": 1, \"root\": {\"type\": \"union\", "
         "\"delta\": 0.1, \"epsilon\": 0.05, \"order\": 3, \"children\": [" +
         list + "]}}\n";
}

void MakeFifo(const std::string& path) { ::mkfifo(path.c_str(), 0644); }

void MakeSymlink(const std::string& target, const std::string& link) {
  if (::symlink(target.c_str(), link.c_str()) != 0) std::perror(link.c_str());
}

}  // namespace hostile
