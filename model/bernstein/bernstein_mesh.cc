#include "model/bernstein/bernstein_mesh.h"

namespace implicitfit {

std::array<std::array<int, 3>, 4> BernsteinGrid::LatticeVertices(long long t) const {
  const long long cube = t / 6;
  const int* pi = kKuhnPermutations[t % 6];
  const int i = static_cast<int>(cube % cells[0]);
  const int j = static_cast<int>((cube / cells[0]) % cells[1]);
  const int l = static_cast<int>(cube / (1LL * cells[0] * cells[1]));
  std::array<std::array<int, 3>, 4> v;
  v[0] = {i, j, l};
  v[1] = v[0];
  ++v[1][pi[0]];
  v[2] = v[1];
  ++v[2][pi[1]];
  v[3] = {i + 1, j + 1, l + 1};
  return v;
}

Tetrahedron BernsteinGrid::TetrahedronOf(long long t) const {
  const auto v = LatticeVertices(t);
  Eigen::Vector3d x[4];
  for (int n = 0; n < 4; ++n)
    for (int a = 0; a < 3; ++a) x[n][a] = origin[a] + cell * v[n][a];
  return Tetrahedron(x[0], x[1], x[2], x[3]);
}

}  // namespace implicitfit
