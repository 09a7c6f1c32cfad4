#include "fit/reconstruct/separator_bridging.h"

#include <cctype>

namespace implicitfit {

SeparatorBridging BridgeSeparatedPieces(Model* model, SolidVerification* verification,
                                        const std::vector<Eigen::Vector3d>& points,
                                        const std::vector<Eigen::Vector3d>& normals,
                                        const SolidVerificationOptions& options,
                                        int max_trials) {
  SeparatorBridging out;
  std::vector<int> separators, measured;  // plane leaves
  for (int i = 0; i < static_cast<int>(model->nodes().size()); ++i) {
    const ModelNode& n = model->nodes()[i];
    if (n.type != NodeType::kPlane || !n.children.empty()) continue;
    if (n.name.rfind("separator", 0) == 0)
      separators.push_back(i);
    else if (n.name.rfind("closure", 0) != 0 && !n.name.empty())
      measured.push_back(i);
  }
  auto volume = [](const SolidVerification& v) {
    double sum = 0.0;
    for (const SolidPiece& p : v.components.pieces)
      if (!p.cavity) sum += p.volume;
    return sum;
  };
  for (int s : separators) {
    if (verification->components.solids <= 1) break;
    // Of the replacements that verify with fewer pieces, the one with the least solid volume:
    // the join that adds the least material no scan point asked for.
    int best = -1;
    Model best_model;
    SolidVerification best_v;
    for (int p : measured) {
      if (out.trials >= max_trials) break;
      ++out.trials;
      Model trial = *model;
      const ModelNode& from = model->nodes()[p];
      const ModelNode& to = trial.nodes()[s];
      for (int j = 0; j < to.num_parameters; ++j)
        trial.mutable_parameters()[to.first_parameter + j] =
            model->parameters()[from.first_parameter + j];
      SolidVerification v = VerifySolid(trial, points, normals, options);
      if (!v.verified || v.components.solids >= verification->components.solids) continue;
      if (best >= 0 && (v.components.solids > best_v.components.solids ||
                        (v.components.solids == best_v.components.solids &&
                         volume(v) >= volume(best_v))))
        continue;
      best = p;
      best_model = std::move(trial);
      best_v = std::move(v);
    }
    if (best < 0) continue;
    out.replaced.emplace_back(model->nodes()[s].name, model->nodes()[best].name);
    best_model.mutable_nodes()[s].name = model->nodes()[best].name;  // now that measured plane
    *model = std::move(best_model);
    *verification = std::move(best_v);
  }
  return out;
}

std::string SeparatorBridging::Text() const {
  std::string t;
  for (const auto& [from, to] : replaced) t += (t.empty() ? "" : ", ") + from + " -> " + to;
  return t;
}

std::string RenameInExpression(std::string expression, const std::string& from,
                               const std::string& to) {
  auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (size_t at = 0; (at = expression.find(from, at)) != std::string::npos;) {
    const size_t end = at + from.size();
    if ((at > 0 && word(expression[at - 1])) || (end < expression.size() && word(expression[end]))) {
      at = end;
      continue;
    }
    expression.replace(at, from.size(), to);
    at += to.size();
  }
  return expression;
}

}  // namespace implicitfit
