#include "model/certificates/convexity_report.h"

#include "model/certificates/convexity_fields.h"
#include "model/certificates/convexity_verdict.h"

namespace implicitfit {

std::vector<PatchConvexity> CertifyModelPatches(const Model& model) {
  std::vector<PatchConvexity> patches;
  for (size_t n = 0; n < model.nodes().size(); ++n) {
    const ModelNode& node = model.nodes()[n];
    if (node.type != NodeType::kBernsteinPatch) continue;
    PatchConvexity p;
    p.node = static_cast<int>(n);
    p.label = model.NodeLabel(p.node);
    p.degree = node.degree;
    p.certificate = CertifyConvexity(node.degree, model.parameters().data() + node.first_parameter);
    patches.push_back(p);
  }
  return patches;
}

nlohmann::ordered_json PatchConvexityJson(int degree, const ConvexityCertificate& certificate) {
  nlohmann::ordered_json p;
  p["degree"] = degree;
  p["convex"] = certificate.convex;
  p["min_eigenvalue"] = certificate.min_eigenvalue;
  return p;
}

nlohmann::ordered_json ModelConvexityJson(const Model& model) {
  nlohmann::ordered_json out;
  nlohmann::ordered_json patches = nlohmann::ordered_json::array();
  const std::vector<PatchConvexity> certified = CertifyModelPatches(model);
  for (const PatchConvexity& p : certified) {
    nlohmann::ordered_json entry = PatchConvexityJson(p.degree, p.certificate);
    AppendPatchCertificates(model, p.node, &entry);
    patches.push_back(entry);
  }
  nlohmann::ordered_json tree;
  bool tree_certified = false;
  const nlohmann::ordered_json nodes = TreeNodesJson(model, &tree, &tree_certified);
  // The file verdict: the tree's certificate AND every patch's and mesh's
  // (model/certificates/convexity_verdict.h).
  const ConvexityVerdict verdict = JudgeConvexity(model);
  out["convex"] = verdict.convex;
  out["patches"] = patches;
  out["tree"] = tree;
  out["nodes"] = nodes;
  out["verdict"] = ConvexityVerdictJson(model, verdict);
  return out;
}

}  // namespace implicitfit
