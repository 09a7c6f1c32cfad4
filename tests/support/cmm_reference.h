// Coordinate-measuring-machine test sets and an independent least-squares reference.
//
// Sets: 10 mm parts (plane 10 x 10 mm, sphere and cylinder of radius 5 mm, a cone of half angle
// 25 degrees between 10 and 20 mm from its apex, a torus of radii 5 and 2 mm) placed at a random
// pose far from the origin,
// probed at 6-40 points on partial arcs (sphere: a cap; cylinder and cone: 2-4 circles, each
// an arc of 120-240 degrees; 3-4 circles for the cone; torus: 3-4 parallels at tube angles
// between -60 and 60 degrees, each an arc of 120-240 degrees around the axis), with a lobed
// form error of amplitude 1 um
// (three lobes around the axis, waves of 5 mm on the plane) and Gaussian noise of 0.1 um along the
// normal; no normals.
//
// Reference: orthogonal-distance least squares in long double, by Gauss-Newton from the truth
// with central-difference Jacobians, in the part's own frame and parameterisation (the
// NIST-style ones, different from implicitfit's):
//   plane    (a, b, c):             d = (z - a x - b y - c) / sqrt(1 + a^2 + b^2)
//   sphere   (x0, y0, z0, r):       d = |y - c| - r
//   cylinder (x0, y0, a, b, r):     axis through (x0, y0, 0) along (a, b, 1); d = rho - r
//   cone     (x0, y0, a, b, r0, t): axis through (x0, y0, 15) along (a, b, 1), radius r0 there,
//                                   tan(half angle) = t; d = (rho - r0 - h t) / sqrt(1 + t^2)
//   torus    (x0, y0, z0, a, b, R, r): centre (x0, y0, z0), axis (a, b, 1);
//                                   d = sqrt((rho - R)^2 + h^2) - r
// (y = R^T (x - o) in the part frame.) Iterated until the step is below 1e-17 mm.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace testsupport {

enum class CmmKind { kPlane, kSphere, kCylinder, kCone, kTorus };

struct CmmSet {
  CmmKind kind;
  Eigen::Matrix3d rotation;             // part frame -> world
  Eigen::Vector3d origin;               // part frame origin in the world
  std::vector<Eigen::Vector3d> points;  // world coordinates (mm)
  static constexpr double kSize = 10.0;
  static constexpr double kConeHalfAngle = 25.0 * M_PI / 180.0;
};

inline Eigen::Matrix3d RandomRotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  return q.normalized().toRotationMatrix();
}

inline CmmSet MakeCmmSet(CmmKind kind, int n, unsigned seed, double lobe = 1e-3,
                         double noise = 1e-4) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, noise);
  CmmSet s;
  s.kind = kind;
  s.rotation = RandomRotation(rng);
  s.origin = Eigen::Vector3d(100 + 50 * u01(rng), -200 + 50 * u01(rng), 30 + 50 * u01(rng));
  const double R = 5.0, ta = std::tan(CmmSet::kConeHalfAngle);
  // 2..4 circles; 3..4 for the cone and the torus (on two circles the cone's algebraic
  // hypotheses from points are rank deficient: see fit/metrology/point_hypotheses.h; a torus
  // through two parallels is not determined)
  const bool three = kind == CmmKind::kCone || kind == CmmKind::kTorus;
  const int circles = (three ? 3 : 2) + static_cast<int>(u01(rng) * (three ? 2 : 3));
  const double span = (120 + 120 * u01(rng)) * M_PI / 180, start = 2 * M_PI * u01(rng);
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d y = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::UnitZ();
    const int c = i % circles;
    const double phi =
        start + span * (i / circles + 0.5 * (c % 2)) / std::max(1, (n + circles - 1) / circles);
    const double lobes = lobe * std::cos(3 * phi);
    switch (kind) {
      case CmmKind::kPlane: {
        const double x = 10 * u01(rng) - 5, yy = 10 * u01(rng) - 5;
        y = Eigen::Vector3d(x, yy, 0);
        normal = Eigen::Vector3d::UnitZ();
        y += normal * (lobe * std::cos(2 * M_PI * x / 5) * std::cos(2 * M_PI * yy / 5));
        break;
      }
      case CmmKind::kSphere: {  // cap up to 70 degrees from the pole
        const double theta = 70 * M_PI / 180 * std::sqrt(u01(rng)), az = 2 * M_PI * u01(rng);
        normal = Eigen::Vector3d(std::sin(theta) * std::cos(az), std::sin(theta) * std::sin(az),
                                 std::cos(theta));
        y = normal * (R + lobe * std::cos(3 * az));
        break;
      }
      case CmmKind::kCylinder: {
        const double z = -4 + 8.0 * c / std::max(1, circles - 1);
        normal = Eigen::Vector3d(std::cos(phi), std::sin(phi), 0);
        y = normal * (R + lobes) + Eigen::Vector3d(0, 0, z);
        break;
      }
      case CmmKind::kCone: {  // apex at the part origin, axis +z, h in [10, 20]
        const double h = 10 + 10.0 * c / std::max(1, circles - 1);
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0);
        normal = (radial * std::cos(CmmSet::kConeHalfAngle) -
                  Eigen::Vector3d::UnitZ() * std::sin(CmmSet::kConeHalfAngle));
        y = radial * h * ta + Eigen::Vector3d(0, 0, h) + normal * lobes;
        break;
      }
      case CmmKind::kTorus: {  // R = 5, r = 2, centre at the part origin, axis +z
        const double theta = (-60 + 120.0 * c / std::max(1, circles - 1)) * M_PI / 180;
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0);
        normal = radial * std::cos(theta) + Eigen::Vector3d::UnitZ() * std::sin(theta);
        y = radial * 5.0 + normal * (2.0 + lobes);
        break;
      }
    }
    y += normal * gauss(rng);
    s.points.push_back(s.origin + s.rotation * y);
  }
  return s;
}

// Long double Gauss-Newton reference (see the top of this file). Returns the parameters in the
// part frame.
class CmmReference {
 public:
  using LD = long double;
  using VecL = Eigen::Matrix<LD, Eigen::Dynamic, 1>;
  using MatL = Eigen::Matrix<LD, Eigen::Dynamic, Eigen::Dynamic>;

  explicit CmmReference(const CmmSet& set) : kind_(set.kind) {
    for (const auto& x : set.points) {
      Eigen::Matrix<LD, 3, 1> xd = x.cast<LD>() - set.origin.cast<LD>();
      y_.push_back(set.rotation.cast<LD>().transpose() * xd);
    }
  }

  static int Size(CmmKind k) {
    return k == CmmKind::kPlane      ? 3
           : k == CmmKind::kSphere   ? 4
           : k == CmmKind::kCylinder ? 5
           : k == CmmKind::kCone     ? 6
                                     : 7;
  }
  static VecL Truth(CmmKind k) {
    VecL p = VecL::Zero(Size(k));
    if (k == CmmKind::kSphere || k == CmmKind::kCylinder) p[Size(k) - 1] = 5;
    if (k == CmmKind::kCone) {
      p[4] = 15 * std::tan(static_cast<LD>(CmmSet::kConeHalfAngle));
      p[5] = std::tan(static_cast<LD>(CmmSet::kConeHalfAngle));
    }
    if (k == CmmKind::kTorus) {
      p[5] = 5;
      p[6] = 2;
    }
    return p;
  }

  LD Distance(const VecL& p, const Eigen::Matrix<LD, 3, 1>& y) const {
    using std::sqrt;
    switch (kind_) {
      case CmmKind::kPlane:
        return (y.z() - p[0] * y.x() - p[1] * y.y() - p[2]) / sqrt(1 + p[0] * p[0] + p[1] * p[1]);
      case CmmKind::kSphere:
        return sqrt((y.x() - p[0]) * (y.x() - p[0]) + (y.y() - p[1]) * (y.y() - p[1]) +
                    (y.z() - p[2]) * (y.z() - p[2])) -
               p[3];
      case CmmKind::kCylinder: {
        Eigen::Matrix<LD, 3, 1> u(p[2], p[3], 1), q(p[0], p[1], 0);
        u /= u.norm();
        return (y - q).cross(u).norm() - p[4];
      }
      case CmmKind::kCone: {
        Eigen::Matrix<LD, 3, 1> u(p[2], p[3], 1), q(p[0], p[1], 15);
        u /= u.norm();
        const Eigen::Matrix<LD, 3, 1> w = y - q;
        const LD h = w.dot(u), rho = (w - h * u).norm();
        return (rho - p[4] - h * p[5]) / sqrt(1 + p[5] * p[5]);
      }
      case CmmKind::kTorus: {
        Eigen::Matrix<LD, 3, 1> u(p[3], p[4], 1), c(p[0], p[1], p[2]);
        u /= u.norm();
        const Eigen::Matrix<LD, 3, 1> w = y - c;
        const LD h = w.dot(u), rho = (w - h * u).norm();
        return sqrt((rho - p[5]) * (rho - p[5]) + h * h) - p[6];
      }
    }
    return 0;
  }

  // Gauss-Newton from the truth; *last_step receives the final step's length.
  VecL Solve(LD* last_step = nullptr) const {
    VecL p = Truth(kind_);
    const int m = static_cast<int>(p.size()), n = static_cast<int>(y_.size());
    LD step = 1;
    for (int it = 0; it < 60 && step > 1e-17L; ++it) {
      MatL J(n, m);
      VecL r(n);
      for (int i = 0; i < n; ++i) r[i] = Distance(p, y_[i]);
      for (int j = 0; j < m; ++j) {
        const LD h = 1e-6L;
        VecL a = p, b = p;
        a[j] += h;
        b[j] -= h;
        for (int i = 0; i < n; ++i) J(i, j) = (Distance(a, y_[i]) - Distance(b, y_[i])) / (2 * h);
      }
      const VecL delta = -J.colPivHouseholderQr().solve(r);
      p += delta;
      step = delta.norm();
    }
    if (last_step) *last_step = step;
    return p;
  }

 private:
  CmmKind kind_;
  std::vector<Eigen::Matrix<LD, 3, 1>> y_;
};

inline Eigen::Vector3d ToPart(const CmmSet& s, const Eigen::Vector3d& x) {
  return s.rotation.transpose() * (x - s.origin);
}

// Differences (mm; angles times the part size) of the geometric parameters of a fit p in
// implicitfit's layout (world frame: plane n, d; sphere c, r; cylinder point, axis, r; cone
// apex, axis, half angle) and the reference q (part frame).
inline std::vector<std::pair<std::string, double>> ParameterDifferences(
    const CmmSet& s, const std::vector<double>& p, const CmmReference::VecL& q) {
  const double L = CmmSet::kSize;
  std::vector<std::pair<std::string, double>> d;
  auto dir = [&](int at) {
    Eigen::Vector3d u =
        s.rotation.transpose() * Eigen::Vector3d(p[at], p[at + 1], p[at + 2]).normalized();
    return u.z() < 0 ? Eigen::Vector3d(-u) : u;
  };
  switch (s.kind) {
    case CmmKind::kPlane: {
      Eigen::Vector3d n = s.rotation.transpose() * Eigen::Vector3d(p[0], p[1], p[2]).normalized();
      double off = p[3] / Eigen::Vector3d(p[0], p[1], p[2]).norm() - (s.rotation * n).dot(s.origin);
      if (n.z() < 0) {
        n = -n;
        off = -off;
      }
      const double nr = std::sqrt(1.0 + static_cast<double>(q[0] * q[0] + q[1] * q[1]));
      const Eigen::Vector3d nref(-static_cast<double>(q[0]) / nr, -static_cast<double>(q[1]) / nr,
                                 1.0 / nr);
      d.push_back({"normal angle x L", std::atan2(n.cross(nref).norm(), n.dot(nref)) * L});
      d.push_back({"offset", std::abs(off - static_cast<double>(q[2]) / nr)});
      break;
    }
    case CmmKind::kSphere: {
      const Eigen::Vector3d c = ToPart(s, Eigen::Vector3d(p[0], p[1], p[2]));
      for (int k = 0; k < 3; ++k)
        d.push_back({"center" + std::to_string(k), std::abs(c[k] - static_cast<double>(q[k]))});
      d.push_back({"radius", std::abs(p[3] - static_cast<double>(q[3]))});
      break;
    }
    case CmmKind::kCylinder:
    case CmmKind::kCone: {
      const Eigen::Vector3d u = dir(3), a = ToPart(s, Eigen::Vector3d(p[0], p[1], p[2]));
      const bool cone = s.kind == CmmKind::kCone;
      const double zref = cone ? 15.0 : 0.0;
      const Eigen::Vector3d at = a + u * ((zref - a.z()) / u.z());  // axis meets z = zref
      Eigen::Vector3d uref(static_cast<double>(q[2]), static_cast<double>(q[3]), 1.0);
      uref.normalize();
      d.push_back({"axis angle x L", std::atan2(u.cross(uref).norm(), u.dot(uref)) * L});
      d.push_back({"axis x", std::abs(at.x() - static_cast<double>(q[0]))});
      d.push_back({"axis y", std::abs(at.y() - static_cast<double>(q[1]))});
      if (!cone) {
        d.push_back({"radius", std::abs(p[6] - static_cast<double>(q[4]))});
      } else {
        const double r_at = (at - a).norm() * std::tan(p[6]);
        d.push_back({"radius at z=15", std::abs(r_at - static_cast<double>(q[4]))});
        d.push_back({"half angle x L", std::abs(p[6] - std::atan(static_cast<double>(q[5]))) * L});
      }
      break;
    }
    case CmmKind::kTorus: {
      const Eigen::Vector3d u = dir(3), c = ToPart(s, Eigen::Vector3d(p[0], p[1], p[2]));
      Eigen::Vector3d uref(static_cast<double>(q[3]), static_cast<double>(q[4]), 1.0);
      uref.normalize();
      d.push_back({"axis angle x L", std::atan2(u.cross(uref).norm(), u.dot(uref)) * L});
      for (int k = 0; k < 3; ++k)
        d.push_back({"center" + std::to_string(k), std::abs(c[k] - static_cast<double>(q[k]))});
      d.push_back({"major radius", std::abs(p[6] - static_cast<double>(q[5]))});
      d.push_back({"minor radius", std::abs(p[7] - static_cast<double>(q[6]))});
      break;
    }
  }
  return d;
}

}  // namespace testsupport
