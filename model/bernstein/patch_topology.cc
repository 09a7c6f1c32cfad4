#include "model/bernstein/patch_topology.h"

#include "model/bernstein/bernstein_patch.h"

namespace implicitfit {
namespace {

double At(const double* b, const std::array<int, 4>& l) {
  return b[BernsteinIndex(l[1], l[2], l[3])];
}

}  // namespace

std::vector<EdgeSignChanges> EdgeSignChangeCounts(int k, const double* b) {
  std::vector<EdgeSignChanges> out;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      EdgeSignChanges e;
      e.vertices = {i, j};
      int last = 0;
      for (int a = k; a >= 0; --a) {
        std::array<int, 4> l = {0, 0, 0, 0};
        l[i] = a;
        l[j] = k - a;
        const double v = At(b, l);
        const int s = v > 0.0 ? 1 : (v < 0.0 ? -1 : 0);
        if (s != 0) {
          if (last != 0 && s != last) ++e.sign_changes;
          last = s;
        }
      }
      out.push_back(e);
    }
  return out;
}

std::vector<std::array<int, 3>> FacesWithoutCrossing(int k, const double* b) {
  std::vector<std::array<int, 3>> out;
  for (int opposite = 3; opposite >= 0; --opposite) {
    bool positive = true, negative = true;
    for (const std::array<int, 4>& l : BernsteinMultiIndices(k)) {
      if (l[opposite] != 0) continue;
      const double v = At(b, l);
      positive &= v > 0.0;
      negative &= v < 0.0;
    }
    if (positive || negative) {
      std::array<int, 3> face;
      int n = 0;
      for (int v = 0; v < 4; ++v)
        if (v != opposite) face[n++] = v;
      out.push_back(face);
    }
  }
  return out;
}

}  // namespace implicitfit
