#include "datasets/generators/model_sampler.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "datasets/meshing/model_mesher.h"
#include "model/primitives/primitive_kinds.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
// Grid cells along the longest side of the box for the mesh the candidates are drawn from.
constexpr double kSamplingMeshCells = 80.0;

void NodeBox(const Model& model, int index, Vec* lo, Vec* hi);

// The exact box of an ellipse c + A cos + B sin (c_k +- hypot(A_k, B_k)) or of a helix (the
// same, swept by C t over [0, turns]).
void CurveBox(const SplineStructure& s, const double* p, Vec* lo, Vec* hi) {
  for (int k = 0; k < 3; ++k) {
    const double half = std::hypot(p[3 + k], p[6 + k]);
    const double rise = s.curve == CurveKind::kHelix ? p[9 + k] * s.turns : 0.0;
    (*lo)[k] = p[k] + std::min(0.0, rise) - half;
    (*hi)[k] = p[k] + std::max(0.0, rise) + half;
  }
}

// The union of the children's boxes.
void ChildrenBox(const Model& model, const ModelNode& node, Vec* lo, Vec* hi) {
  NodeBox(model, node.children[0], lo, hi);
  for (size_t c = 1; c < node.children.size(); ++c) {
    Vec l, h;
    NodeBox(model, node.children[c], &l, &h);
    *lo = lo->cwiseMin(l);
    *hi = hi->cwiseMax(h);
  }
}

void NodeBox(const Model& model, int index, Vec* lo, Vec* hi) {
  const ModelNode& node = model.nodes()[index];
  const double* p = model.parameters().data() + node.first_parameter;
  switch (node.type) {
    case NodeType::kPlane:  // primitives: their table entry's box (model/primitives/primitive_kinds.h)
    case NodeType::kSphere:
    case NodeType::kCylinder:
    case NodeType::kCone:
    case NodeType::kTorus:
    case NodeType::kEllipsoid:
    case NodeType::kQuadric:
    case NodeType::kBox:
    case NodeType::kParaboloid:
      FindPrimitiveKind(node.type)->sampling_box(p, lo, hi);
      return;
    case NodeType::kBernsteinPatch: {
      // The patch is meant inside its tetrahedron (the fitters place the cloud there): its
      // bounding box, 5% larger on every side so a zero set touching a face is kept.
      *lo = *hi = node.tetrahedron.vertex(0);
      for (int i = 1; i < 4; ++i) {
        *lo = lo->cwiseMin(node.tetrahedron.vertex(i));
        *hi = hi->cwiseMax(node.tetrahedron.vertex(i));
      }
      const Vec margin = 0.05 * (*hi - *lo);
      *lo -= margin;
      *hi += margin;
      return;
    }
    case NodeType::kBernsteinMesh:
      *lo = node.grid.BoxMin();
      *hi = node.grid.BoxMax();
      return;
    case NodeType::kBlobs: {  // every blob's centre +- its reach (gaussian: where a e^(-b R^2) =
                              // T/4)
      const int m = node.count;
      const double t = std::max(std::abs(p[5 * m]), 1e-12);
      for (int i = 0; i < m; ++i) {
        const double a = std::abs(p[3 * m + i]), w = p[4 * m + i];
        const double reach = node.variant == static_cast<int>(BlobKernel::kGaussian)
                                 ? std::sqrt(std::max(std::log(4.0 * a / t), 0.0) / w)
                                 : w;
        const Vec c(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
        const Vec l = c - Vec::Constant(reach), h = c + Vec::Constant(reach);
        *lo = i == 0 ? l : Vec(lo->cwiseMin(l));
        *hi = i == 0 ? h : Vec(hi->cwiseMax(h));
      }
      return;
    }
    case NodeType::kSkeletonOffset: {  // the skeleton's extent +- 1.05 r (or the features' reach)
      const int m = node.count;
      double reach = p[3 * m];
      for (int q = 0; q < SkeletonFeatureCount(node); ++q) {  // R_C + D + W + R
        const double* e = p + 3 * m + 1 + ColemanFeatures::kPerFeature * q;
        reach = std::max(reach, p[3 * m] + e[4] + e[3] + e[5]);
      }
      const double r = 1.05 * reach;
      if (node.variant == static_cast<int>(SkeletonKind::kCurve) &&
          node.spline.curve != CurveKind::kBSpline) {
        CurveBox(node.spline, p, lo, hi);
        *lo -= Vec::Constant(r);
        *hi += Vec::Constant(r);
        return;
      }
      *lo = Vec(p[0], p[1], p[2]);
      *hi = *lo;
      for (int i = 1; i < m; ++i) {
        *lo = lo->cwiseMin(Vec(p[3 * i], p[3 * i + 1], p[3 * i + 2]));
        *hi = hi->cwiseMax(Vec(p[3 * i], p[3 * i + 1], p[3 * i + 2]));
      }
      *lo -= Vec::Constant(r);
      *hi += Vec::Constant(r);
      return;
    }
    case NodeType::kPartitionSequence: {  // the cell children's boxes (not the separators')
      NodeBox(model, node.children[node.count], lo, hi);
      for (size_t c = node.count + 1; c < node.children.size(); ++c) {
        Vec l, h;
        NodeBox(model, node.children[c], &l, &h);
        *lo = lo->cwiseMin(l);
        *hi = hi->cwiseMax(h);
      }
      return;
    }
    case NodeType::kColemanFeatures: {  // the core's box grown by the farthest raised core
      NodeBox(model, node.children[0], lo, hi);
      double reach = p[0];
      for (int q = 0; q < node.count; ++q) {
        const double* e = p + 1 + ColemanFeatures::kPerFeature * q;
        reach = std::max(reach, p[0] + e[4] + e[3] + e[5]);
      }
      const double* c = p + 1 + ColemanFeatures::kPerFeature * node.count;
      for (int n : node.curve_vertices) {  // curve features: [3 n vertices, W, D, R, flare]
        reach = std::max(reach, p[0] + c[3 * n + 1] + c[3 * n] + c[3 * n + 2]);
        c += 3 * n + 4;
      }
      *lo -= Vec::Constant(1.05 * reach);
      *hi += Vec::Constant(1.05 * reach);
      return;
    }
    case NodeType::kBSplineSurface: {  // the control net's box (convex hull), grown by 5%
      *lo = *hi = Vec(p[0], p[1], p[2]);
      for (int i = 1; i < node.count; ++i) {
        *lo = lo->cwiseMin(Vec(p[3 * i], p[3 * i + 1], p[3 * i + 2]));
        *hi = hi->cwiseMax(Vec(p[3 * i], p[3 * i + 1], p[3 * i + 2]));
      }
      const Vec margin = Vec::Constant(0.05 * (*hi - *lo).maxCoeff());
      *lo -= margin;
      *hi += margin;
      return;
    }
    case NodeType::kBSplineVolume:
      *lo = Vec(node.spline.box[0], node.spline.box[1], node.spline.box[2]);
      *hi = Vec(node.spline.box[3], node.spline.box[4], node.spline.box[5]);
      return;
    case NodeType::kPartition:
    case NodeType::kComplement:
    case NodeType::kMorph:
    case NodeType::kUnion:
    case NodeType::kIntersection:
    case NodeType::kDifference:
      ChildrenBox(model, node, lo, hi);
      return;
  }
}

bool Inside(const Vec& x, const Vec& lo, const Vec& hi) {
  return (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all();
}

}  // namespace

void SamplingBox(const Model& model, Vec* box_min, Vec* box_max) {
  NodeBox(model, model.root(), box_min, box_max);
}

SampledCloud SampleModel(const Model& model, const SampleOptions& options) {
  SampledCloud out;
  if (options.has_box) {
    out.box_min = options.box_min;
    out.box_max = options.box_max;
  } else {
    SamplingBox(model, &out.box_min, &out.box_max);
  }
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  auto uniform_in_box = [&]() {
    Vec x;
    for (int k = 0; k < 3; ++k)
      x[k] = out.box_min[k] + u01(rng) * (out.box_max[k] - out.box_min[k]);
    return x;
  };
  const int outliers = static_cast<int>(std::lround(options.outlier_fraction * options.count));
  const int inliers = options.count - outliers;
  const double diagonal = (out.box_max - out.box_min).norm();
  const bool partial = options.view_dir.norm() > 0 && options.view_angle_deg < 180.0;
  const Vec view = partial ? options.view_dir.normalized() : Vec::Zero();
  const double view_cos = std::cos(options.view_angle_deg * M_PI / 180.0);

  // Candidates uniform by area: a mesh of the zero set in the box (datasets/meshing/model_mesher.h),
  // a triangle drawn with probability proportional to its area, a uniform point in it.
  MeshOptions mesh_options;
  mesh_options.has_box = true;
  mesh_options.box_min = out.box_min;
  mesh_options.box_max = out.box_max;
  mesh_options.cell = (out.box_max - out.box_min).maxCoeff() / kSamplingMeshCells;
  const TriangleMesh mesh = MeshModel(model, mesh_options).mesh;
  std::vector<double> cumulative_area;
  cumulative_area.reserve(mesh.triangles.size());
  double area = 0.0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Vec& p0 = mesh.vertices[t[0]];
    area += 0.5 * (mesh.vertices[t[1]] - p0).cross(mesh.vertices[t[2]] - p0).norm();
    cumulative_area.push_back(area);
  }
  if (!(area > 0.0))
    throw std::runtime_error("could not sample the zero set: it does not cross the box");
  auto uniform_on_mesh = [&]() {
    const double r = u01(rng) * area;
    const size_t i = std::min(
        cumulative_area.size() - 1,
        static_cast<size_t>(std::upper_bound(cumulative_area.begin(), cumulative_area.end(), r) -
                            cumulative_area.begin()));
    const Eigen::Vector3i& t = mesh.triangles[i];
    const double s = std::sqrt(u01(rng)), w = u01(rng);
    return Vec((1 - s) * mesh.vertices[t[0]] + s * (1 - w) * mesh.vertices[t[1]] +
               s * w * mesh.vertices[t[2]]);
  };

  // The leaves (every node without children), for the truth labels.
  for (size_t k = 0; k < model.nodes().size(); ++k)
    if (model.nodes()[k].children.empty()) out.leaf_nodes.push_back(static_cast<int>(k));
  auto leaf_of = [&](const Vec& x) {
    int best = -1;
    double best_f = 1e-8 * diagonal;
    for (size_t l = 0; l < out.leaf_nodes.size(); ++l) {
      const double f =
          std::abs(model.EvaluateNode(out.leaf_nodes[l], model.parameters().data(), x.data()));
      if (f <= best_f) best_f = f, best = static_cast<int>(l);
    }
    return best;
  };
  std::vector<Vec> pts, nrm;
  std::vector<int> leaf;
  long attempts = 0;
  const long max_attempts = 200L * options.count + 10000;
  while (static_cast<int>(pts.size()) < inliers) {
    if (++attempts > max_attempts)
      throw std::runtime_error(
          "could not sample the zero set: too few projections landed inside the box" +
          std::string(partial ? " and the view cone" : ""));
    Vec x = uniform_on_mesh();
    bool converged = false;
    for (int it = 0; it < 50; ++it) {
      double f;
      const Vec g = model.Gradient(x, &f);
      if (std::abs(f) < 1e-12 * (1.0 + x.cwiseAbs().maxCoeff())) {
        converged = true;
        break;
      }
      const double g2 = g.squaredNorm();
      if (!(g2 > 1e-20) || !std::isfinite(g2)) break;
      x -= f * g / g2;
    }
    if (!converged || !Inside(x, out.box_min, out.box_max)) continue;
    const Vec g = model.Gradient(x);
    const Vec n = g.normalized();
    if (!n.allFinite()) continue;
    // Newton steps can end on a point where f is not smooth (a cone's apex, a crease): there
    // the gradient is no normal. Keep x only if f grows linearly along n on both sides.
    const double h = 1e-4 * diagonal, gn = g.norm();
    if (std::abs(model.Value(x + h * n) - h * gn) > 0.1 * h * gn ||
        std::abs(model.Value(x - h * n) + h * gn) > 0.1 * h * gn)
      continue;
    if (partial && n.dot(view) < view_cos) continue;
    pts.push_back(x + options.noise * gauss(rng) * n);
    nrm.push_back(n);
    leaf.push_back(leaf_of(x));
  }
  out.is_outlier.assign(pts.size(), false);
  for (int i = 0; i < outliers; ++i) {
    pts.push_back(uniform_in_box());
    nrm.push_back(Vec(gauss(rng), gauss(rng), gauss(rng)).normalized());
    out.is_outlier.push_back(true);
    leaf.push_back(-1);
  }
  // Interleave outliers with inliers (deterministic shuffle) so file order tells nothing.
  std::vector<size_t> order(pts.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<bool> outlier_flags(pts.size());
  for (size_t i = 0; i < order.size(); ++i) {
    out.cloud.points.push_back(pts[order[i]]);
    out.cloud.normals.push_back(nrm[order[i]]);
    outlier_flags[i] = out.is_outlier[order[i]];
    out.primitive.push_back(leaf[order[i]]);
  }
  out.is_outlier = outlier_flags;
  return out;
}

}  // namespace implicitfit
