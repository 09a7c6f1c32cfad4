#include "model/certificates/convexity_fields.h"

#include "model/certificates/patch_certificates.h"
#include "model/bernstein/patch_topology.h"
#include "model/certificates/tree_certificate.h"

namespace implicitfit {

nlohmann::ordered_json TreeNodesJson(const Model& model, nlohmann::ordered_json* tree_verdict,
                                     bool* certified) {
  using ojson = nlohmann::ordered_json;
  const std::vector<NodeCertificate> certificates = CertifyTree(model);
  auto domain = [&](const NodeCertificate& c) {
    if (c.domain_nodes.empty()) return ojson("everywhere");
    ojson d = ojson::array();
    for (int p : c.domain_nodes) d.push_back(model.NodeLabel(p));
    return d;  // the intersection of these nodes' domains
  };
  ojson nodes = ojson::array();
  for (size_t i = 0; i < model.nodes().size(); ++i) {
    const NodeCertificate& c = certificates[i];
    ojson n;
    n["node"] = model.NodeLabel(static_cast<int>(i));
    n["type"] = NodeTypeName(model.nodes()[i].type);
    n["class"] = TreeConvexityName(c.convexity);
    n["rule"] = c.rule;
    n["domain"] = domain(c);
    nodes.push_back(n);
  }
  const NodeCertificate& root = certificates[model.root()];
  *certified = root.convexity != TreeConvexity::kNotCertified;
  (*tree_verdict)["class"] = TreeConvexityName(root.convexity);
  (*tree_verdict)["certified"] = *certified;
  (*tree_verdict)["domain"] = domain(root);
  return nodes;
}

void AppendPatchCertificates(const Model& model, int index, nlohmann::ordered_json* patch) {
  const ModelNode& node = model.nodes()[index];
  const double* b = model.parameters().data() + node.first_parameter;
  const int k = node.degree;
  const CartesianMargin margin = CartesianConvexityMargin(k, node.tetrahedron, b);
  (*patch)["min_eigenvalue_cartesian"] = margin.min_eigenvalue_cartesian;
  (*patch)["hessian_lower_bound"] = margin.hessian_lower_bound;
  // The degree-2k certificate and the subdivision grow like N(k)^2 (N(k) = (k+1)(k+2)(k+3)/6):
  // above kMaxDegreeForSearch they are not attempted and reported as null.
  constexpr int kMaxDegreeForSearch = 8;
  if (k <= kMaxDegreeForSearch) {
    const FinslerCertificate finsler = CertifyFinsler(k, b);
    (*patch)["finsler"] = {{"convex", finsler.convex},
                           {"c", finsler.c},
                           {"margin", finsler.margin},
                           {"degree", finsler.degree}};
    (*patch)["locally_convex"] = CertifyLocalConvexity(k, b).locally_convex;
  } else {
    (*patch)["finsler"] = nullptr;
    (*patch)["locally_convex"] = nullptr;
  }
  nlohmann::ordered_json edges = nlohmann::ordered_json::array();
  for (const EdgeSignChanges& e : EdgeSignChangeCounts(k, b))
    edges.push_back(
        {{"vertices", {e.vertices[0], e.vertices[1]}}, {"sign_changes", e.sign_changes}});
  (*patch)["edges"] = edges;
  nlohmann::ordered_json faces = nlohmann::ordered_json::array();
  for (const auto& f : FacesWithoutCrossing(k, b)) faces.push_back({f[0], f[1], f[2]});
  (*patch)["faces_without_crossing"] = faces;
}

}  // namespace implicitfit
