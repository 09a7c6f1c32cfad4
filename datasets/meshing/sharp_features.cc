#include "datasets/meshing/sharp_features.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>
#include <utility>

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
using Edge = std::pair<int, int>;

Edge Undirected(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

Vec FaceNormal(const TriangleMesh& mesh, int a, int b, int c) {
  return (mesh.vertices[b] - mesh.vertices[a]).cross(mesh.vertices[c] - mesh.vertices[a]);
}

// The tangent planes' least-squares intersection about the mass point (header, step 1).
Vec QuadricErrorPoint(const std::vector<Vec>& points, const std::vector<Vec>& normals) {
  Vec mass = Vec::Zero();
  for (const Vec& p : points) mass += p;
  mass /= static_cast<double>(points.size());
  Eigen::MatrixXd a(points.size(), 3);
  Eigen::VectorXd r(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    a.row(i) = normals[i].transpose();
    r[i] = normals[i].dot(points[i] - mass);
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd s = svd.singularValues();
  Eigen::VectorXd inverse = Eigen::VectorXd::Zero(s.size());
  for (int k = 0; k < s.size(); ++k)
    if (s[k] > 0.1 * s[0]) inverse[k] = 1.0 / s[k];
  return mass + svd.matrixV() * inverse.asDiagonal() * svd.matrixU().transpose() * r;
}

// The boundary of a patch as one closed loop of directed edges (a, b) taken from its triangles,
// or empty when the boundary is not a single simple loop.
std::vector<Edge> BoundaryLoop(const TriangleMesh& mesh, const std::vector<int>& patch) {
  std::set<Edge> directed;
  for (int t : patch)
    for (int k = 0; k < 3; ++k)
      directed.insert({mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]});
  std::map<int, int> next;
  for (const Edge& e : directed) {
    if (directed.count({e.second, e.first})) continue;       // interior edge
    if (!next.emplace(e.first, e.second).second) return {};  // vertex left twice: not simple
  }
  if (next.size() < 3) return {};
  std::vector<Edge> loop;
  int v = next.begin()->first;
  do {
    const auto it = next.find(v);
    if (it == next.end() || loop.size() > next.size()) return {};
    loop.emplace_back(v, it->second);
    v = it->second;
  } while (v != next.begin()->first);
  if (loop.size() != next.size()) return {};  // several loops
  return loop;
}

}  // namespace

SharpFeatureStats InsertSharpFeatures(const Model& model, const Vec& origin, double h,
                                      const std::vector<Eigen::Vector3i>& triangle_cells,
                                      TriangleMesh* mesh, const SharpFeatureOptions& options) {
  SharpFeatureStats stats;
  const double cos_feature = std::cos(options.feature_angle_deg * M_PI / 180.0);
  // Triangles by cell, then patches of edge-connected triangles within a cell.
  std::map<std::tuple<int, int, int>, std::vector<int>> by_cell;
  for (size_t t = 0; t < mesh->triangles.size(); ++t) {
    const Eigen::Vector3i& c = triangle_cells[t];
    by_cell[{c[0], c[1], c[2]}].push_back(static_cast<int>(t));
  }
  std::vector<char> removed(mesh->triangles.size(), 0);
  struct Fan {
    int a, b, x;  // triangle (a, b, x), (a, b) the patch's boundary edge
  };
  std::vector<Fan> fans;
  for (const auto& [key, tris] : by_cell) {
    // Union-find over the cell's triangles by shared vertices (shared edges in a manifold cell).
    std::vector<int> parent(tris.size());
    for (size_t i = 0; i < tris.size(); ++i) parent[i] = static_cast<int>(i);
    auto find = [&](int i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    for (size_t i = 0; i < tris.size(); ++i)
      for (size_t j = i + 1; j < tris.size(); ++j) {
        int shared = 0;
        for (int p = 0; p < 3; ++p)
          for (int q = 0; q < 3; ++q)
            shared += mesh->triangles[tris[i]][p] == mesh->triangles[tris[j]][q];
        if (shared >= 2) parent[find(static_cast<int>(i))] = find(static_cast<int>(j));
      }
    std::map<int, std::vector<int>> patches;
    for (size_t i = 0; i < tris.size(); ++i) patches[find(static_cast<int>(i))].push_back(tris[i]);
    const Vec cell_lo = origin + h * Vec(std::get<0>(key), std::get<1>(key), std::get<2>(key));
    const Vec cell_hi = cell_lo + Vec::Constant(h);
    for (const auto& [root, patch] : patches) {
      std::set<int> vertex_set;
      for (int t : patch)
        for (int k = 0; k < 3; ++k) vertex_set.insert(mesh->triangles[t][k]);
      std::vector<Vec> points, normals;
      for (int v : vertex_set) {
        points.push_back(mesh->vertices[v]);
        normals.push_back(mesh->normals[v]);
      }
      double min_cos = 1.0;
      for (size_t i = 0; i < normals.size(); ++i)
        for (size_t j = i + 1; j < normals.size(); ++j)
          min_cos = std::min(min_cos, normals[i].dot(normals[j]));
      if (min_cos >= cos_feature) continue;
      const std::vector<Edge> loop = BoundaryLoop(*mesh, patch);
      const Vec x = QuadricErrorPoint(points, normals);
      double f = 0.0;
      const Vec g = model.Gradient(x, &f);
      const double distance = std::abs(f) / g.norm();
      const Vec margin = Vec::Constant(options.cell_margin * h);
      const bool in_cell = ((x - (cell_lo - margin)).array() >= 0).all() &&
                           ((cell_hi + margin - x).array() >= 0).all();
      if (loop.empty() || !x.allFinite() || !in_cell || !(distance <= options.max_distance * h)) {
        ++stats.rejected;
        continue;
      }
      stats.max_distance = std::max(stats.max_distance, distance);
      const int xi = static_cast<int>(mesh->vertices.size());
      mesh->vertices.push_back(x);
      mesh->normals.push_back(Vec::Zero());
      for (int t : patch) removed[t] = 1;
      for (const Edge& e : loop) fans.push_back({e.first, e.second, xi});
      ++stats.feature_points;
    }
  }
  // Flips across the boundary edges two fans share (header, step 3).
  std::unordered_map<long long, std::vector<int>> by_edge;
  auto key_of = [](const Edge& e) { return (static_cast<long long>(e.first) << 32) | e.second; };
  for (size_t i = 0; i < fans.size(); ++i)
    by_edge[key_of(Undirected(fans[i].a, fans[i].b))].push_back(static_cast<int>(i));
  std::vector<Eigen::Vector3i> flipped;
  std::vector<char> done(fans.size(), 0);
  std::set<Edge> feature_edges;
  for (size_t i = 0; i < fans.size(); ++i) {
    if (done[i]) continue;
    const std::vector<int>& pair = by_edge[key_of(Undirected(fans[i].a, fans[i].b))];
    if (pair.size() != 2) continue;
    const Fan& f1 = fans[pair[0]];
    const Fan& f2 = fans[pair[1]];
    if (done[pair[0]] || done[pair[1]] || f1.x == f2.x) continue;
    if (feature_edges.count(Undirected(f1.x, f2.x))) continue;
    // f1 = (a, b, x1), f2 = (b, a, x2) -> (x1, a, x2), (x2, b, x1).
    const Vec before = FaceNormal(*mesh, f1.a, f1.b, f1.x).normalized() +
                       FaceNormal(*mesh, f2.a, f2.b, f2.x).normalized();
    const Vec n1 = FaceNormal(*mesh, f1.x, f1.a, f2.x), n2 = FaceNormal(*mesh, f2.x, f1.b, f1.x);
    if (!(n1.dot(before) > 0) || !(n2.dot(before) > 0)) continue;
    flipped.emplace_back(f1.x, f1.a, f2.x);
    flipped.emplace_back(f2.x, f1.b, f1.x);
    done[pair[0]] = done[pair[1]] = 1;
    feature_edges.insert(Undirected(f1.x, f2.x));
    ++stats.flips;
  }
  std::vector<Eigen::Vector3i> triangles;
  triangles.reserve(mesh->triangles.size() + fans.size());
  for (size_t t = 0; t < mesh->triangles.size(); ++t)
    if (!removed[t]) triangles.push_back(mesh->triangles[t]);
  for (size_t i = 0; i < fans.size(); ++i)
    if (!done[i]) triangles.emplace_back(fans[i].a, fans[i].b, fans[i].x);
  triangles.insert(triangles.end(), flipped.begin(), flipped.end());
  // Feature points' normals, then drop the vertices no triangle uses any more.
  const int first_feature = static_cast<int>(mesh->vertices.size()) - stats.feature_points;
  std::vector<Vec> sums(mesh->vertices.size(), Vec::Zero());
  std::vector<int> remap(mesh->vertices.size(), -1);
  for (const Eigen::Vector3i& t : triangles) {
    const Vec n = FaceNormal(*mesh, t[0], t[1], t[2]);
    for (int k = 0; k < 3; ++k) {
      sums[t[k]] += n;
      remap[t[k]] = 0;
    }
  }
  TriangleMesh out;
  for (size_t v = 0; v < mesh->vertices.size(); ++v) {
    if (remap[v] < 0) continue;
    remap[v] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(mesh->vertices[v]);
    if (static_cast<int>(v) >= first_feature) {
      const double n = sums[v].norm();
      out.normals.push_back(n > 0 ? Vec(sums[v] / n) : Vec(0, 0, 1));
    } else {
      out.normals.push_back(mesh->normals[v]);
    }
  }
  for (Eigen::Vector3i& t : triangles)
    for (int k = 0; k < 3; ++k) t[k] = remap[t[k]];
  out.triangles = std::move(triangles);
  *mesh = std::move(out);
  return stats;
}

}  // namespace implicitfit
