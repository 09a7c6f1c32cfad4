#include "datasets/meshing/default_mesh_cell.h"

#include <algorithm>

namespace implicitfit {

double DefaultMeshCell(const Model& model, double longest) {
  double finest_crease_leaf = 0.0;  // 0: no Bernstein mesh with creases
  for (const ModelNode& node : model.nodes()) {
    if (node.type != NodeType::kBernsteinMesh || !node.grid.HasSharpFaces()) continue;
    const double u = node.grid.LatticeUnit();
    if (finest_crease_leaf == 0.0 || u < finest_crease_leaf) finest_crease_leaf = u;
  }
  if (finest_crease_leaf > 0.0) return std::min(finest_crease_leaf / 2, longest / 64.0);
  return longest / 100.0;
}

}  // namespace implicitfit
