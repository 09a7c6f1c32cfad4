#include "model/splines/patch_tree.h"

#include <cmath>

namespace implicitfit {
namespace {

double Cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a[0] * b[1] - a[1] * b[0]; }

Eigen::Vector2d Mean(const std::vector<Eigen::Vector2d>& v) {
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& x : v) c += x;
  return c / static_cast<double>(v.size());
}

}  // namespace

std::string StarDomainProblem(const std::vector<Eigen::Vector2d>& vertices) {
  if (vertices.size() < 3) return "a domain needs at least 3 vertices";
  if (vertices.size() > 1024) return "a domain has at most 1024 vertices";
  for (const Eigen::Vector2d& x : vertices)
    if (!x.allFinite()) return "a domain vertex is not finite";
  const Eigen::Vector2d c = Mean(vertices);
  double turn = 0.0;
  for (size_t i = 0; i < vertices.size(); ++i) {
    const Eigen::Vector2d a = vertices[i] - c, b = vertices[(i + 1) % vertices.size()] - c;
    if (!(Cross2(a, b) > 0.0))
      return "the domain must be star-shaped about its vertex centroid, counter-clockwise (edge " +
             std::to_string(i) + ")";
    turn += std::atan2(Cross2(a, b), a.dot(b));
  }
  if (std::abs(turn - 2.0 * M_PI) > 1e-6) return "the domain winds more than once about its centroid";
  return "";
}

StarDomain MakeStarDomain(const std::vector<Eigen::Vector2d>& vertices) {
  StarDomain d;
  d.vertices = vertices;
  d.centroid = Mean(vertices);
  return d;
}

int SectorOf(const StarDomain& d, double u, double v) {
  const Eigen::Vector2d p = Eigen::Vector2d(u, v) - d.centroid;
  const size_t m = d.vertices.size();
  for (size_t i = 0; i < m; ++i) {
    const Eigen::Vector2d a = d.vertices[i] - d.centroid;
    const Eigen::Vector2d b = d.vertices[(i + 1) % m] - d.centroid;
    if (Cross2(a, p) >= 0.0 && Cross2(p, b) > 0.0) return static_cast<int>(i);
  }
  return 0;  // p at the centroid: any sector gives tau = 1
}

std::string PatchTree::Problem() const {
  const int n = static_cast<int>(patches.size());
  if (n < 1 || n > 256) return "a patch tree has 1..256 patches";
  if (root < 0 || root >= n) return "the root is not a patch";
  if (placements.size() != links.size() * kPerLink) return "5 placement numbers per link";
  for (double x : placements)
    if (!std::isfinite(x)) return "a placement number is not finite";
  std::vector<int> parent(n, -1);
  for (size_t l = 0; l < links.size(); ++l) {
    const PatchLink& k = links[l];
    if (k.parent < 0 || k.parent >= n || k.child < 0 || k.child >= n || k.child == root ||
        k.parent == k.child)
      return "link " + std::to_string(l) + " names no valid parent and child";
    if (parent[k.child] >= 0) return "patch " + std::to_string(k.child) + " has two parents";
    parent[k.child] = k.parent;
    if (!(k.band > 0.0 && k.band <= 1.0) || !(k.filter > 0.0) || !std::isfinite(k.filter))
      return "link " + std::to_string(l) + ": band in (0, 1] and filter > 0";
  }
  for (int i = 0; i < n; ++i) {  // every patch reaches the root without a cycle
    int at = i, steps = 0;
    while (at != root && at >= 0 && steps <= n) at = parent[at], ++steps;
    if (at != root) return "patch " + std::to_string(i) + " is not under the root";
    const std::string problem = StarDomainProblem(patches[i].domain.vertices);
    if (!problem.empty()) return "patch " + std::to_string(i) + ": " + problem;
    const size_t need[] = {9, 4, 5, 4, 0};
    const size_t kind = static_cast<size_t>(patches[i].kind);
    if (patches[i].kind == PatchKind::kBSpline) {
      const std::string s = SurfaceStructureProblem(patches[i].spline);
      if (!s.empty()) return "patch " + std::to_string(i) + ": " + s;
      if (patches[i].p.size() != 3u * patches[i].spline.count[0] * patches[i].spline.count[1])
        return "patch " + std::to_string(i) + ": 3 numbers per control point";
    } else if (patches[i].p.size() != need[kind]) {
      return "patch " + std::to_string(i) + ": " + std::to_string(need[kind]) + " parameters";
    }
  }
  return "";
}

}  // namespace implicitfit
