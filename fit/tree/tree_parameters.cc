#include "fit/tree/tree_parameters.h"

#include <ceres/manifold.h>
#include <ceres/sphere_manifold.h>

#include <algorithm>
#include <string>

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

}  // namespace implicitfit
