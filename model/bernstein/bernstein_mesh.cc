#include "model/bernstein/bernstein_mesh.h"

namespace implicitfit {

std::array<int, 4> BernsteinGrid::Leaf(long long q) const {
  if (refined()) return refinement.leaves[static_cast<size_t>(q)];
  return {0, static_cast<int>(q % cells[0]), static_cast<int>((q / cells[0]) % cells[1]),
          static_cast<int>(q / (1LL * cells[0] * cells[1]))};
}

std::array<std::array<int, 3>, 4> BernsteinGrid::LatticeVertices(long long t) const {
  const std::array<int, 4> leaf = Leaf(t / 6);
  const int* pi = kKuhnPermutations[t % 6];
  const int s = 1 << (MaxLevel() - leaf[0]);  // the leaf's edge in lattice units
  std::array<std::array<int, 3>, 4> v;
  v[0] = {s * leaf[1], s * leaf[2], s * leaf[3]};
  v[1] = v[0];
  v[1][pi[0]] += s;
  v[2] = v[1];
  v[2][pi[1]] += s;
  v[3] = {v[0][0] + s, v[0][1] + s, v[0][2] + s};
  return v;
}

Tetrahedron BernsteinGrid::TetrahedronOf(long long t) const {
  const auto v = LatticeVertices(t);
  Eigen::Vector3d x[4];
  for (int n = 0; n < 4; ++n)
    for (int a = 0; a < 3; ++a) x[n][a] = origin[a] + LatticeUnit() * v[n][a];
  return Tetrahedron(x[0], x[1], x[2], x[3]);
}

}  // namespace implicitfit
