#include "fit/reconstruct/blend_refit.h"

#include <algorithm>
#include <cmath>

#include "fit/tree/blend_order.h"
#include "fit/tree/tree_covariance.h"
#include "model/median.h"

namespace implicitfit {

using Vec = Eigen::Vector3d;

int CopySubtree(const Model& src, int index, Model* dst, std::vector<int>* map) {
  const ModelNode& node = src.nodes()[index];
  const double* p = src.parameters().data() + node.first_parameter;
  int copied;
  if (IsOperator(node.type)) {
    std::vector<int> children;
    for (int c : node.children) children.push_back(CopySubtree(src, c, dst, map));
    copied = dst->AddOperator(node.type, children, p[0], p[1], node.order, node.name);
    dst->mutable_nodes()[copied].smoothing = node.smoothing;
  } else if (node.type == NodeType::kBernsteinPatch) {
    copied = dst->AddBernsteinPatch(node.degree, node.tetrahedron,
                                    std::vector<double>(p, p + node.num_parameters), node.name);
  } else {
    copied =
        dst->AddPrimitive(node.type, std::vector<double>(p, p + node.num_parameters), node.name);
  }
  dst->mutable_nodes()[copied].fixed = node.fixed;
  if (map) (*map)[index] = copied;
  return copied;
}

bool FixPrimitives(Model* m) {
  bool any_smooth = false;
  for (ModelNode& node : m->mutable_nodes()) {
    if (IsOperator(node.type)) {
      any_smooth = any_smooth || node.order > 0;
      continue;
    }
    node.fixed.clear();
    for (const ParameterField& field : ParameterFieldsOf(node.type))
      node.fixed.push_back(field.name);
  }
  return any_smooth;
}

TreeFitResult TreeFigures(const Model& m, const std::vector<Vec>& points,
                          const std::vector<Vec>& normals, double floor) {
  TreeFitResult r;
  r.model = m;
  r.points = points.size();
  std::vector<double> d(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    double f;
    const Vec g = m.Gradient(points[i], &f);
    d[i] = std::abs(f) / std::sqrt(g.squaredNorm() + 1e-12);
  }
  r.sigma = 1.4826 * Median(d);
  double ss = 0, angles = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!(d[i] < std::max(3 * r.sigma, floor))) continue;
    ++r.inliers;
    ss += d[i] * d[i];
    const Vec g = m.Gradient(points[i]).normalized();
    angles += std::acos(std::min(1.0, std::abs(g.dot(normals[i])))) * 180.0 / M_PI;
  }
  r.rms = r.inliers ? std::sqrt(ss / r.inliers) : 0.0;
  if (r.inliers) r.mean_normal_angle_deg = angles / r.inliers;
  r.success = true;
  r.message = "no blend: the primitives keep their fits";
  return r;
}

namespace {

// The top-level smooth operators: the first smooth node on every path from the root.
std::vector<int> TopSmoothOperators(const Model& m) {
  std::vector<int> tops, stack = {m.root()};
  while (!stack.empty()) {
    const int index = stack.back();
    stack.pop_back();
    const ModelNode& node = m.nodes()[index];
    if (!IsOperator(node.type)) continue;
    if (node.order > 0) {
      tops.push_back(index);
      continue;
    }
    for (int c : node.children) stack.push_back(c);
  }
  return tops;
}

// Indices of the points where |f_solid| = |f_subtree| (relative 1e-9).
std::vector<size_t> PointsOfSubtree(const Model& sub, const std::vector<Vec>& points,
                                    const std::vector<double>& solid_value) {
  std::vector<size_t> mine;
  for (size_t i = 0; i < points.size(); ++i) {
    const double a = std::abs(solid_value[i]), b = std::abs(sub.Value(points[i]));
    if (std::abs(a - b) <= 1e-9 * (1.0 + a)) mine.push_back(i);
  }
  return mine;
}

}  // namespace

TreeFitResult RefitBlends(const Model& solid, const std::vector<Vec>& points,
                          const std::vector<Vec>& normals, const std::vector<bool>& assigned,
                          int max_points, double floor, const TreeFitOptions& options,
                          std::mt19937_64* rng) {
  Model m = solid;
  if (!FixPrimitives(&m)) return TreeFigures(m, points, normals, floor);
  const std::vector<int> tops = TopSmoothOperators(m);
  std::vector<double> solid_value(points.size());
  for (size_t i = 0; i < points.size(); ++i) solid_value[i] = m.Value(points[i]);
  // The truncation of the acceptance cost: 3 sigma of the sharp solid.
  Model sharp = m;
  for (ModelNode& node : sharp.mutable_nodes())
    if (IsOperator(node.type)) node.order = 0;
  const double clip = std::max(3.0 * TreeFigures(sharp, points, normals, floor).sigma, floor);
  double seconds = 0;
  int iterations = 0;
  for (int top : tops) {
    Model sub;
    std::vector<int> map(m.nodes().size(), -1);
    sub.SetRoot(CopySubtree(m, top, &sub, &map));
    // Points where the solid's value is the subtree's: on-face points first, then the others.
    std::vector<size_t> on_face, off_face;
    for (size_t i : PointsOfSubtree(sub, points, solid_value))
      (assigned[i] ? on_face : off_face).push_back(i);
    std::shuffle(on_face.begin(), on_face.end(), *rng);
    // Face points only say where the blend ends: three per transition point, at least 1000,
    // within max_points in all.
    const size_t room = std::min<size_t>(
        std::max<size_t>(1000, 3 * off_face.size()),
        static_cast<size_t>(std::max<long>(0, max_points - static_cast<long>(off_face.size()))));
    if (on_face.size() > room) on_face.resize(room);
    std::vector<size_t> chosen = off_face;
    chosen.insert(chosen.end(), on_face.begin(), on_face.end());
    std::sort(chosen.begin(), chosen.end());
    std::vector<Vec> fit_points, fit_normals;
    for (size_t i : chosen) {
      fit_points.push_back(points[i]);
      fit_normals.push_back(normals[i]);
    }
    TreeFitResult fit = FitModelTree(sub, fit_points, fit_normals, options);
    seconds += fit.seconds;
    iterations += fit.iterations;
    if (!fit.success) {
      TreeFitResult failed = fit;
      failed.model = m;
      return failed;
    }
    // The fold order of n-ary blends (fit/tree/blend_order.h), refitted when it changed.
    Model reordered = fit.model;
    if (ChooseChildOrders(&reordered, fit_points, clip)) {
      const TreeFitResult again = FitModelTree(reordered, fit_points, fit_normals, options);
      seconds += again.seconds;
      iterations += again.iterations;
      if (again.success && TruncatedCost(again.model, fit_points, clip) <
                               TruncatedCost(fit.model, fit_points, clip))
        fit = again;
    }
    std::vector<int> unmap(sub.nodes().size(), -1);
    for (size_t s = 0; s < map.size(); ++s)
      if (map[s] >= 0) unmap[map[s]] = static_cast<int>(s);
    Model blended = m, unblended = m;
    for (size_t s = 0; s < map.size(); ++s) {
      if (map[s] < 0) continue;
      const ModelNode& from = fit.model.nodes()[map[s]];
      const ModelNode& to = m.nodes()[s];
      std::copy_n(fit.model.parameters().begin() + from.first_parameter, to.num_parameters,
                  blended.mutable_parameters().begin() + to.first_parameter);
      if (!IsOperator(to.type)) continue;
      unblended.mutable_nodes()[s].order = 0;
      for (size_t c = 0; c < from.children.size(); ++c)  // the chosen fold order
        blended.mutable_nodes()[s].children[c] = unmap[from.children[c]];
    }
    // Kept only when it explains the points better than the sharp edges do.
    m = TruncatedCost(blended, points, clip) < TruncatedCost(unblended, points, clip) ? blended
                                                                                      : unblended;
  }
  TreeFitResult out = TreeFigures(m, points, normals, floor);
  out.seconds = seconds;
  out.iterations = iterations;
  out.message = "converged";
  out.termination = FitTermination::kConverged;
  return out;
}

std::vector<double> BlendStandardDeviations(const Model& solid,
                                            const std::vector<Vec>& points) {
  std::vector<double> sd(solid.parameters().size(), 0.0);
  std::vector<double> solid_value(points.size());
  for (size_t i = 0; i < points.size(); ++i) solid_value[i] = solid.Value(points[i]);
  for (int top : TopSmoothOperators(solid)) {
    Model sub;
    std::vector<int> map(solid.nodes().size(), -1);
    sub.SetRoot(CopySubtree(solid, top, &sub, &map));
    std::vector<Vec> mine;
    for (size_t i : PointsOfSubtree(sub, points, solid_value)) mine.push_back(points[i]);
    const std::vector<double> sub_sd =
        TreeStandardDeviations(sub, mine, FreeParameterColumns(sub));
    for (size_t s = 0; s < map.size(); ++s) {
      if (map[s] < 0) continue;
      const ModelNode& from = sub.nodes()[map[s]];
      const ModelNode& to = solid.nodes()[s];
      std::copy_n(sub_sd.begin() + from.first_parameter, to.num_parameters,
                  sd.begin() + to.first_parameter);
    }
  }
  return sd;
}

}  // namespace implicitfit
