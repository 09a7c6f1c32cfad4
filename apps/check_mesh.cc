#include "apps/check_mesh.h"

#include <cstdio>

namespace implicitfit {

std::string MeshCheck::Verdict() const {
  if (certificate.convex_on_box) return "convex on the box";
  if (certificate.certified_tetrahedra == certificate.tetrahedra) return "not convex (C1 defect)";
  if (!certificate.c1) return "not convex (uncertified tetrahedra, C1 defect)";
  return "not convex (uncertified tetrahedra)";
}

std::vector<MeshCheck> CheckBernsteinMeshes(const Model& model, int sample_segments) {
  std::vector<MeshCheck> out;
  for (size_t i = 0; i < model.nodes().size(); ++i) {
    const ModelNode& node = model.nodes()[i];
    if (node.type != NodeType::kBernsteinMesh) continue;
    MeshCheck c;
    c.label = model.NodeLabel(static_cast<int>(i));
    c.degree = node.degree;
    c.continuity = node.continuity;
    const double* b = model.parameters().data() + node.first_parameter;
    c.certificate = CertifyMeshConvexity(node.degree, node.grid, b);
    if (sample_segments > 0) {
      MeshSamplingOptions options;
      options.segments = sample_segments;
      c.sample = MeshTangentPlaneTest(node.degree, node.grid, b, options);
      c.sampled = true;
    }
    out.push_back(std::move(c));
  }
  return out;
}

nlohmann::ordered_json MeshCheckJson(const MeshCheck& c) {
  const MeshConvexityCertificate& m = c.certificate;
  nlohmann::ordered_json j;
  j["label"] = c.label;
  j["degree"] = c.degree;
  j["continuity"] = c.continuity;
  j["tetrahedra"] = m.tetrahedra;
  j["certified_tetrahedra"] = m.certified_tetrahedra;
  j["min_eigenvalue"] = m.min_eigenvalue;
  j["worst_tetrahedron"] = m.worst_tetrahedron;
  j["c1_defect"] = m.c1_defect;
  j["c1"] = m.c1;
  j["domain_convex"] = m.domain_convex;
  j["convex_on_box"] = m.convex_on_box;
  j["verdict"] = c.Verdict();
  nlohmann::ordered_json per = nlohmann::ordered_json::array();
  for (const ConvexityCertificate& t : m.per_tetrahedron)
    per.push_back({{"convex", t.convex}, {"min_eigenvalue", t.min_eigenvalue}});
  j["tetrahedra_certificates"] = per;
  if (c.sampled)
    j["sample"] = {{"zero_points", c.sample.zero_points},
                   {"violations", c.sample.violations},
                   {"worst_excursion", c.sample.worst_excursion}};
  return j;
}

void PrintMeshCheck(const std::string& file, const MeshCheck& c) {
  const MeshConvexityCertificate& m = c.certificate;
  std::printf(
      "%-24s %-28s mesh degree %d C%d: %lld/%lld tetrahedra certified (min eigenvalue %.6g), "
      "C1 defect %.3g: %s",
      file.c_str(), c.label.c_str(), c.degree, c.continuity, m.certified_tetrahedra, m.tetrahedra,
      m.min_eigenvalue, m.c1_defect, c.Verdict().c_str());
  if (c.sampled)
    std::printf("  sampling: %d zero points, %d violations", c.sample.zero_points,
                c.sample.violations);
  std::printf("\n");
}

}  // namespace implicitfit
