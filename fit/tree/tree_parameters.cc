#include "fit/tree/tree_parameters.h"

#include "fit/bernstein/patch_shape_constraints.h"

#include <ceres/manifold.h>
#include <ceres/sphere_manifold.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace implicitfit {

namespace {

// The block kind of a field from its role (model/model.h FieldRole).
TreeParameters::Kind KindOfRole(FieldRole role) {
  using Kind = TreeParameters::Kind;
  switch (role) {
    case FieldRole::kDirection:
      return Kind::kDirection;
    case FieldRole::kPositiveLength:
      return Kind::kPositive;
    case FieldRole::kAngle:
      return Kind::kAngle;
    case FieldRole::kRotation:
      return Kind::kQuaternion;
    case FieldRole::kPlain:
    case FieldRole::kPosition:
    case FieldRole::kAxisPoint:
    case FieldRole::kPlaneOffset:
      return Kind::kPlain;
  }
  return Kind::kPlain;
}

// The features block's subspace (see the header): per feature the point moves in the plane
// orthogonal to u_f, width, depth, radius and flare freely. u_f: for coleman_features the
// normalised gradient of the core child at f (central differences, as the evaluator's closest
// core point), for skeleton features the direction from the nearest skeleton point to f.
Eigen::MatrixXd FeatureTangentBasis(const Model& model, const ModelNode& node, int first) {
  const std::vector<double>& p = model.parameters();
  const int m = (node.type == NodeType::kColemanFeatures) ? node.count : SkeletonFeatureCount(node);
  const int n = ColemanFeatures::kPerFeature * m;
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(n, n - m);
  int column = 0;
  for (int q = 0; q < m; ++q) {
    const double* f = p.data() + first + ColemanFeatures::kPerFeature * q;
    Eigen::Vector3d u = Eigen::Vector3d::Zero();
    if (node.type == NodeType::kColemanFeatures) {
      const double h = 1e-6 * std::max({1.0, std::abs(f[0]), std::abs(f[1]), std::abs(f[2])});
      for (int k = 0; k < 3; ++k) {
        double a[3] = {f[0], f[1], f[2]}, b[3] = {f[0], f[1], f[2]};
        a[k] += h;
        b[k] -= h;
        u[k] = model.EvaluateNode(node.children[0], p.data(), a) -
               model.EvaluateNode(node.children[0], p.data(), b);
      }
    } else {
      double nearest[3];
      SkeletonOffsetEvaluator::Closest(static_cast<SkeletonKind>(node.variant), node.count,
                              p.data() + node.first_parameter, f, nearest);
      u = Eigen::Vector3d(f[0] - nearest[0], f[1] - nearest[1], f[2] - nearest[2]);
    }
    const int row = ColemanFeatures::kPerFeature * q;
    if (u.norm() > 0) {  // the point in the plane orthogonal to u
      u.normalize();
      const Eigen::Vector3d a = u.unitOrthogonal(), b = u.cross(a);
      basis.block<3, 1>(row, column) = a;
      basis.block<3, 1>(row, column + 1) = b;
      column += 2;
    } else {  // no direction (f on the core's ridge): the point moves freely
      basis.conservativeResize(n, basis.cols() + 1);
      basis.col(basis.cols() - 1).setZero();
      for (int k = 0; k < 3; ++k) basis(row + k, column + k) = 1.0;
      column += 3;
    }
    for (int k = 3; k < ColemanFeatures::kPerFeature; ++k) basis(row + k, column++) = 1.0;
  }
  basis.conservativeResize(n, column);
  return basis;
}

}  // namespace

TreeParameters::TreeParameters(const Model& model) {
  const std::vector<double>& p = model.parameters();
  entries_.resize(p.size());
  // The separators of a partition_sequence are structure (as a grid's cuts): held fixed.
  std::vector<bool> separator(model.nodes().size(), false);
  for (const ModelNode& node : model.nodes())
    if (node.type == NodeType::kPartitionSequence)
      for (int j = 0; j < node.count; ++j) separator[node.children[j]] = true;
  for (size_t index = 0; index < model.nodes().size(); ++index) {
    const ModelNode& node = model.nodes()[index];
    // A convex-smoothing blend has no epsilon (width w = delta): its slot is held, not fitted.
    const bool no_epsilon = node.smoothing == BlendSmoothing::kConvex;
    auto is_fixed = [&node](const std::string& f) {
      return std::find(node.fixed.begin(), node.fixed.end(), f) != node.fixed.end();
    };
    int k = node.first_parameter;
    const int delta_flat = node.first_parameter;  // operators: [delta, epsilon]
    for (const ParameterField& field : ParameterFieldsOf(node)) {
      const std::string name = field.name;
      Kind kind = KindOfRole(field.role);
      const bool structural = node.type == NodeType::kBlobs && name == "threshold";
      if (node.type == NodeType::kMorph && name == "t") kind = Kind::kUnitLogit;
      if (name == "delta") kind = Kind::kDeltaLog;
      if (name == "epsilon") kind = Kind::kEpsilonLogit;
      double scale = 1.0;
      if (node.type == NodeType::kPartition) {
        scale = SmallestPartitionCell(node.cuts) / 2.0;
        kind = scale < 1e307 ? Kind::kUnitLogit : Kind::kLog;
      }
      if (node.type == NodeType::kPartitionSequence) {
        scale = SmallestPartitionSequenceCell(model.SeparatorsOf(node)) / 2.0;
        kind = scale < 1e307 ? Kind::kUnitLogit : Kind::kLog;
      }
      if (separator[index] || is_fixed(name) || structural ||
          (no_epsilon && kind == Kind::kEpsilonLogit)) {
        for (int j = 0; j < field.size; ++j) entries_[k + j].fixed_value = p[k + j];
        k += field.size;
        continue;
      }
      std::vector<double> init(p.begin() + k, p.begin() + k + field.size);
      if (kind == Kind::kDeltaLog) {
        const bool epsilon_fixed = is_fixed("epsilon") && !no_epsilon;
        init[0] = std::log(epsilon_fixed ? std::max(p[k] - p[k + 1], 1e-12 * p[k]) : p[k]);
        if (epsilon_fixed) {
          entries_[k].delta_flat = k + 1;
          entries_[k + 1].fixed_value = p[k + 1];
        }
      }
      if (kind == Kind::kEpsilonLogit) {
        const double ratio = std::clamp(p[k] / p[delta_flat], 1e-9, 1.0 - 1e-9);
        init[0] = std::log(ratio / (1.0 - ratio));
        entries_[k].delta_flat = delta_flat;
      }
      if (kind == Kind::kLog) init[0] = std::log(p[k]);
      if (kind == Kind::kUnitLogit) {
        const double t = std::clamp(p[k] / scale, 1e-9, 1.0 - 1e-9);
        init[0] = std::log(t / (1.0 - t));
      }
      if (kind == Kind::kDirection || kind == Kind::kQuaternion) {
        double n = 0;
        for (double v : init) n += v * v;
        for (double& v : init) v /= std::sqrt(n);
      }
      if (name == "features" && (node.type == NodeType::kColemanFeatures ||
                                 node.type == NodeType::kSkeletonOffset))
        kind = Kind::kFeatureTangent;
      const int block = static_cast<int>(blocks_.size());
      for (int j = 0; j < field.size; ++j) {
        entries_[k + j].block = block;
        entries_[k + j].offset = j;
        entries_[k + j].kind = kind;
        entries_[k + j].scale = scale;
        if (kind == Kind::kEpsilonLogit) entries_[k + j].delta_flat = delta_flat;
      }
      blocks_.push_back(init);
      block_sizes_.push_back(field.size);
      block_kinds_.push_back(kind);
      block_bases_.push_back(kind == Kind::kFeatureTangent ? FeatureTangentBasis(model, node, k)
                                                           : Eigen::MatrixXd());
      k += field.size;
    }
  }
}

void TreeParameters::Configure(ceres::Problem* problem) {
  for (size_t b = 0; b < blocks_.size(); ++b) {
    double* block = blocks_[b].data();
    if (!problem->HasParameterBlock(block)) continue;
    switch (block_kinds_[b]) {
      case Kind::kDirection:
        problem->SetManifold(block, new ceres::SphereManifold<3>());
        break;
      case Kind::kQuaternion:
        problem->SetManifold(block, new ceres::QuaternionManifold());
        break;
      case Kind::kPositive:
        for (int j = 0; j < block_sizes_[b]; ++j) problem->SetParameterLowerBound(block, j, 1e-12);
        break;
      case Kind::kFeatureTangent:
        problem->SetManifold(block, NewLinearSubspaceManifold(block_bases_[b]));
        break;
      case Kind::kAngle:
        problem->SetParameterLowerBound(block, 0, 1e-6);
        problem->SetParameterUpperBound(block, 0, M_PI / 2 - 1e-6);
        break;
      default:
        break;
    }
  }
}

std::vector<double> TreeParameters::ToFlat() const {
  std::vector<const double*> ptrs;
  for (const auto& b : blocks_) ptrs.push_back(b.data());
  std::vector<double> flat(entries_.size());
  ToFlat(ptrs.data(), flat.data());
  return flat;
}

int TreeParameters::RestartCollapsedEpsilons(double min_ratio) {
  const double b_min = std::log(min_ratio / (1.0 - min_ratio));  // epsilon / delta = 1 / (1 + e^-b)
  int restarted = 0;
  for (const Entry& e : entries_)
    if (e.block >= 0 && e.kind == Kind::kEpsilonLogit && blocks_[e.block][e.offset] < b_min) {
      blocks_[e.block][e.offset] = 0.0;
      ++restarted;
    }
  return restarted;
}

std::vector<char> TreeParameters::ConstantSubtrees(const Model& model) const {
  const std::vector<ModelNode>& nodes = model.nodes();
  std::vector<char> constant(nodes.size(), 0), done(nodes.size(), 0);
  // Children before parents (depth-first from the root; the tree has no cycles).
  std::vector<std::pair<int, bool>> stack{{model.root(), false}};
  while (!stack.empty()) {
    auto [index, children_done] = stack.back();
    stack.pop_back();
    if (done[index]) continue;
    const ModelNode& node = nodes[index];
    if (!children_done) {
      stack.push_back({index, true});
      for (int child : node.children)
        if (!done[child]) stack.push_back({child, false});
      continue;
    }
    bool fixed = true;
    for (int i = 0; i < node.num_parameters && fixed; ++i)
      fixed = entries_[node.first_parameter + i].block < 0;
    for (int child : node.children) fixed = fixed && constant[child];
    constant[index] = fixed;
    done[index] = 1;
  }
  return constant;
}

}  // namespace implicitfit
