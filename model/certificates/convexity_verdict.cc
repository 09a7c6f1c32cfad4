#include "model/certificates/convexity_verdict.h"

#include <cstdio>

#include "model/certificates/bernstein_mesh_certificate.h"
#include "model/certificates/convexity_certificate.h"
#include "model/certificates/tree_certificate.h"

namespace implicitfit {
namespace {

std::string Describe(const Model& model, int index, const std::string& rule) {
  return model.NodeLabel(index) + " (" + NodeTypeName(model.nodes()[index].type) + "): " + rule;
}

// The node that refused certification under `index` (not certified): descend while the node's
// only fault is a child (an intersection or morph of children not all convex functions).
int RefusingNode(const Model& model, const std::vector<NodeCertificate>& c, int index) {
  const ModelNode& node = model.nodes()[index];
  const bool li_phillips = node.type == NodeType::kIntersection && node.order > 0 &&
                           node.smoothing == BlendSmoothing::kLiPhillips;
  const bool child_rule =
      (node.type == NodeType::kIntersection && !li_phillips) || node.type == NodeType::kMorph;
  if (!child_rule) return index;  // the node's own rule refused (union, Li-Phillips blend, ...)
  for (int child : node.children)
    if (c[child].convexity == TreeConvexity::kNotCertified)
      return RefusingNode(model, c, child);
  // Every child is certified, but not strongly enough (a convex-smoothing intersection or a
  // morph needs convex functions): the first convex-solid child is the one to blame.
  for (int child : node.children)
    if (c[child].convexity == TreeConvexity::kConvexSolid) return child;
  return index;
}

void Subtree(const Model& model, int index, std::vector<int>* out) {
  for (int child : model.nodes()[index].children) Subtree(model, child, out);
  out->push_back(index);
}

std::string PatchCertificateText(const Model& model, int index, const std::string& rule) {
  const ModelNode& node = model.nodes()[index];
  if (node.type != NodeType::kBernsteinPatch || node.degree < 2) return rule;
  const ConvexityCertificate c =
      CertifyConvexity(node.degree, model.parameters().data() + node.first_parameter);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "; smallest A^mu eigenvalue %.6g", c.min_eigenvalue);
  return rule + buffer;
}

}  // namespace

ConvexityVerdict JudgeConvexity(const Model& model, bool patches_only) {
  ConvexityVerdict v;
  const std::vector<ModelNode>& nodes = model.nodes();
  const double* p = model.parameters().data();
  // Patches and meshes first (every one of the file, reachable from the root or not).
  for (size_t i = 0; i < nodes.size(); ++i) {
    const ModelNode& node = nodes[i];
    const int index = static_cast<int>(i);
    if (node.type == NodeType::kBernsteinPatch &&
        !CertifyConvexity(node.degree, p + node.first_parameter).convex) {
      v.reason = Describe(model, index, "bernstein_patch: A^mu not all positive definite");
      v.rests_on = {index};
      v.certificates = {"A^mu not all positive definite"};
      return v;
    }
    if (node.type == NodeType::kBernsteinMesh &&
        !CertifyMeshConvexity(node.degree, node.grid, p + node.first_parameter).convex_on_box) {
      v.reason = Describe(model, index, "bernstein_mesh: not certified convex on its box");
      v.rests_on = {index};
      v.certificates = {"not certified convex on its box"};
      return v;
    }
  }
  const std::vector<NodeCertificate> c = CertifyTree(model);
  if (patches_only) {
    v.convex = true;
    for (size_t i = 0; i < nodes.size(); ++i)
      if (nodes[i].type == NodeType::kBernsteinPatch || nodes[i].type == NodeType::kBernsteinMesh) {
        v.rests_on.push_back(static_cast<int>(i));
        v.certificates.push_back(PatchCertificateText(model, static_cast<int>(i), c[i].rule));
        v.domain.push_back(static_cast<int>(i));
      }
    return v;
  }
  if (model.root() < 0) {
    v.reason = "the model has no root";
    return v;
  }
  const NodeCertificate& root = c[model.root()];
  if (root.convexity == TreeConvexity::kNotCertified) {
    const int refusing = RefusingNode(model, c, model.root());
    v.rests_on = {refusing};
    v.certificates = {c[refusing].rule};
    v.reason = "the model tree is not certified convex at " +
               Describe(model, refusing, c[refusing].rule);
    if (refusing != model.root())
      v.reason += " (so " + model.NodeLabel(model.root()) + ": " + root.rule + ")";
    return v;
  }
  v.convex = true;
  Subtree(model, model.root(), &v.rests_on);
  for (int index : v.rests_on)
    v.certificates.push_back(PatchCertificateText(model, index, c[index].rule));
  v.domain = root.domain_nodes;
  return v;
}

nlohmann::ordered_json ConvexityVerdictJson(const Model& model, const ConvexityVerdict& v) {
  using ojson = nlohmann::ordered_json;
  ojson out;
  out["convex"] = v.convex;
  if (!v.convex) out["reason"] = v.reason;
  ojson rests = ojson::array();
  for (size_t i = 0; i < v.rests_on.size(); ++i)
    rests.push_back({{"node", model.NodeLabel(v.rests_on[i])},
                     {"type", NodeTypeName(model.nodes()[v.rests_on[i]].type)},
                     {"certificate", v.certificates[i]}});
  out["rests_on"] = rests;
  if (v.domain.empty()) {
    out["domain"] = "everywhere";
  } else {
    ojson domain = ojson::array();
    for (int index : v.domain) {
      const ModelNode& node = model.nodes()[index];
      ojson d = {{"node", model.NodeLabel(index)}};
      if (node.type == NodeType::kBernsteinPatch) {
        ojson vertices = ojson::array();
        for (int k = 0; k < 4; ++k) {
          const Eigen::Vector3d x = node.tetrahedron.vertex(k);
          vertices.push_back({x.x(), x.y(), x.z()});
        }
        d["tetrahedron"] = vertices;
      } else {
        const Eigen::Vector3d lo = node.grid.BoxMin(), hi = node.grid.BoxMax();
        d["box"] = {{"min", {lo.x(), lo.y(), lo.z()}}, {"max", {hi.x(), hi.y(), hi.z()}}};
      }
      domain.push_back(d);
    }
    out["domain"] = domain;
  }
  return out;
}

}  // namespace implicitfit
