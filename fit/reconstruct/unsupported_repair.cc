#include "fit/reconstruct/unsupported_repair.h"

#include "model/primitives/primitive_kinds.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// Adds the cell of w (over the leaves) to *m as a sharp intersection; returns its node, or -1
// when a leaf is not a primitive. *text gets the cell as an expression.
int AddCell(const std::vector<std::pair<std::string, int>>& leaves, const Vec& w, double placeholder,
            Model* m, std::string* text) {
  std::vector<int> literals;
  text->clear();
  for (const auto& [name, index] : leaves) {
    const ModelNode node = m->nodes()[index];
    if (!FindPrimitiveKind(node.type)) return -1;  // a primitive of the kinds table only
    const double* p = m->parameters().data() + node.first_parameter;
    const std::vector<double> parameters(p, p + node.num_parameters);
    const bool leaf_inside = m->EvaluateNode(index, m->parameters().data(), w.data()) < 0;
    int copy = m->AddPrimitive(node.type, parameters, node.name);
    m->mutable_nodes()[copy].fixed = node.fixed;
    if (!leaf_inside) copy = m->AddComposite(NodeType::kComplement, {copy}, {});
    literals.push_back(copy);
    *text += (text->empty() ? "" : " & ") + std::string(leaf_inside ? "" : "!") + name;
  }
  if (literals.empty()) return -1;
  if (literals.size() == 1) return literals[0];
  return m->AddOperator(NodeType::kIntersection, literals, placeholder, placeholder, 0);
}

}  // namespace

PieceRepair RepairUnsupportedPieces(Model* model, SolidVerification* verification,
                                    const std::vector<Vec>& points, const std::vector<Vec>& normals,
                                    const SolidVerificationOptions& options, int max_rounds) {
  PieceRepair out;
  Model m = *model;
  SolidVerification v = *verification;
  const double placeholder = 1e-3 * (v.bounds_max - v.bounds_min).norm() + 1e-12;
  for (int round = 0; round < max_rounds; ++round) {
    // Only a failure of supported pieces alone is repaired (bounded, agreeing with the data).
    if (!v.bounded || v.pieces_supported || v.failures.size() != 1 || v.components.solids == 0)
      break;
    ++out.rounds;
    const std::vector<std::pair<std::string, int>> leaves = SolidLeaves(m);
    bool changed = false;
    for (const SolidPiece& piece : v.components.pieces) {
      if (piece.supported) continue;
      std::string text;
      const int root = m.root();  // AddOperator makes its node the root
      const int cell = AddCell(leaves, piece.witness, placeholder, &m, &text);
      if (cell < 0) return out;
      const NodeType op = piece.cavity ? NodeType::kUnion : NodeType::kDifference;
      m.SetRoot(m.AddOperator(op, {root, cell}, placeholder, placeholder, 0));
      out.expression += (piece.cavity ? " | (" : " & !(") + text + ")";
      (piece.cavity ? out.filled : out.removed) += 1;
      changed = true;
    }
    if (!changed) break;
    v = VerifySolid(m, points, normals, options);
    out.message = v.message;
    if (v.verified) {
      out.verified = true;
      *model = m;
      *verification = v;
      return out;
    }
  }
  return out;
}

}  // namespace implicitfit
