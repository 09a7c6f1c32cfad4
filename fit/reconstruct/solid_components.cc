#include "fit/reconstruct/solid_components.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "fit/common/thread_count.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

struct Grid {
  Vec origin;
  double h = 0;
  int n[3] = {0, 0, 0};
  std::vector<char> inside;  // f < 0 at the node
  long Index(int i, int j, int k) const { return i + static_cast<long>(n[0]) * (j + static_cast<long>(n[1]) * k); }
  Vec Node(long index) const {
    const int i = static_cast<int>(index % n[0]);
    const int j = static_cast<int>((index / n[0]) % n[1]);
    const int k = static_cast<int>(index / (static_cast<long>(n[0]) * n[1]));
    return origin + h * Vec(i, j, k);
  }
  bool Inside(long index) const { return inside[index] != 0; }
  long Size() const { return static_cast<long>(inside.size()); }
};

// Whether f < 0 at x, exactly as Model::Value's sign, with sharp operators short-circuited: a
// sharp intersection (f = max of its children) is inside when every child is, a sharp union
// (min) when some child is, a sharp difference (max(c0, -c1, ...)) when c0 is inside and every
// subtrahend strictly outside; anything else is evaluated (NaN counts as outside).
bool InsideAt(const Model& m, int index, const double* x) {
  const ModelNode& node = m.nodes()[index];
  if (IsOperator(node.type) && node.order == 0) {
    if (node.type == NodeType::kUnion) {
      for (int c : node.children)
        if (InsideAt(m, c, x)) return true;
      return false;
    }
    if (!InsideAt(m, node.children[0], x)) return false;
    for (size_t c = 1; c < node.children.size(); ++c) {
      if (node.type == NodeType::kIntersection) {
        if (!InsideAt(m, node.children[c], x)) return false;
      } else if (!(m.EvaluateNode(node.children[c], m.parameters().data(), x) > 0)) {
        return false;
      }
    }
    return true;
  }
  return m.EvaluateNode(index, m.parameters().data(), x) < 0;
}

// True when f is 1-Lipschitz: every leaf an exact signed distance (plane, sphere, cylinder,
// cone, torus, box), every operator sharp (a max or min of 1-Lipschitz functions) or a
// complement.
bool OneLipschitz(const Model& m, int index) {
  const ModelNode& node = m.nodes()[index];
  if (IsOperator(node.type) || node.type == NodeType::kComplement) {
    if (IsOperator(node.type) && node.order != 0) return false;
    for (int c : node.children)
      if (!OneLipschitz(m, c)) return false;
    return true;
  }
  switch (node.type) {
    case NodeType::kPlane:
    case NodeType::kSphere:
    case NodeType::kCylinder:
    case NodeType::kCone:
    case NodeType::kTorus:
    case NodeType::kBox:
      return true;
    default:
      return false;
  }
}

constexpr int kStride = 4;  // coarse nodes: every 4th along each axis

// The signs at every node. When f is 1-Lipschitz, f is first evaluated on the coarse nodes; a
// node within r of a coarse node c with |f(c)| > r (+ rounding) has c's sign, so only the nodes
// near the surface are decided one by one (by InsideAt).
void FillSigns(const Model& model, int threads, Grid* g) {
  g->inside.assign(static_cast<size_t>(g->n[0]) * g->n[1] * g->n[2], 0);
  const bool lipschitz = OneLipschitz(model, model.root());
  int nc[3];
  for (int a = 0; a < 3; ++a) nc[a] = (g->n[a] - 1) / kStride + 1;
  std::vector<double> coarse(lipschitz ? static_cast<size_t>(nc[0]) * nc[1] * nc[2] : 0);
  auto coarse_index = [&](int i, int j, int k) { return i + nc[0] * (j + static_cast<long>(nc[1]) * k); };
  auto fill_coarse = [&](int t) {
    for (int k = t; k < nc[2]; k += threads)
      for (int j = 0; j < nc[1]; ++j)
        for (int i = 0; i < nc[0]; ++i)
          coarse[coarse_index(i, j, k)] =
              model.Value(g->origin + g->h * kStride * Vec(i, j, k));
  };
  const double rounding = 1e-9 * (1.0 + g->origin.norm() + g->h * (g->n[0] + g->n[1] + g->n[2]));
  auto work = [&](int t) {
    for (int k = t; k < g->n[2]; k += threads)
      for (int j = 0; j < g->n[1]; ++j)
        for (int i = 0; i < g->n[0]; ++i) {
          const Vec x = g->origin + g->h * Vec(i, j, k);
          if (lipschitz) {
            int c[3];
            const int ijk[3] = {i, j, k};
            double r2 = 0;
            for (int a = 0; a < 3; ++a) {
              c[a] = std::min(nc[a] - 1, (ijk[a] + kStride / 2) / kStride);
              const double d = (ijk[a] - c[a] * kStride) * g->h;
              r2 += d * d;
            }
            const double f = coarse[coarse_index(c[0], c[1], c[2])];
            if (std::abs(f) > std::sqrt(r2) + rounding) {
              g->inside[g->Index(i, j, k)] = f < 0;
              continue;
            }
          }
          g->inside[g->Index(i, j, k)] = InsideAt(model, model.root(), x.data());
        }
  };
  if (lipschitz) {
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(fill_coarse, t);
    fill_coarse(0);
    for (std::thread& t : pool) t.join();
  }
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (std::thread& t : pool) t.join();
}

struct Component {
  bool inside = false;
  bool on_face = false;
  int nodes = 0;
  long deepest = -1;
  int lo[3] = {1 << 30, 1 << 30, 1 << 30}, hi[3] = {-1, -1, -1};
  int support_points = 0, boundary_edges = 0, covered_edges = 0;
};

// Labels the components (26-connected inside, 6-connected outside) by breadth-first search.
std::vector<Component> Label(const Model& model, const Grid& g, std::vector<int>* label) {
  const long total = g.Size();
  label->assign(total, -1);
  std::vector<Component> comps;
  std::vector<long> queue;
  for (long seed = 0; seed < total; ++seed) {
    if ((*label)[seed] >= 0) continue;
    const int id = static_cast<int>(comps.size());
    Component c;
    c.inside = g.Inside(seed);
    queue.assign(1, seed);
    (*label)[seed] = id;
    for (size_t q = 0; q < queue.size(); ++q) {
      const long at = queue[q];
      const int i = static_cast<int>(at % g.n[0]), j = static_cast<int>((at / g.n[0]) % g.n[1]);
      const int k = static_cast<int>(at / (static_cast<long>(g.n[0]) * g.n[1]));
      ++c.nodes;
      const int ijk[3] = {i, j, k};
      for (int a = 0; a < 3; ++a) {
        c.lo[a] = std::min(c.lo[a], ijk[a]);
        c.hi[a] = std::max(c.hi[a], ijk[a]);
        c.on_face = c.on_face || ijk[a] == 0 || ijk[a] == g.n[a] - 1;
      }
      for (int dk = -1; dk <= 1; ++dk)
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) {
            const int steps = std::abs(di) + std::abs(dj) + std::abs(dk);
            if (steps == 0 || (!c.inside && steps > 1)) continue;
            const int ii = i + di, jj = j + dj, kk = k + dk;
            if (ii < 0 || jj < 0 || kk < 0 || ii >= g.n[0] || jj >= g.n[1] || kk >= g.n[2])
              continue;
            const long next = g.Index(ii, jj, kk);
            if ((*label)[next] >= 0 || g.Inside(next) != c.inside) continue;
            (*label)[next] = id;
            queue.push_back(next);
          }
    }
    // The witness: of up to 64 of its nodes spread over the search order, the one with the
    // largest |f| (deep inside the piece).
    double deepest = -1;
    const size_t step = std::max<size_t>(1, queue.size() / 64);
    for (size_t q = 0; q < queue.size(); q += step) {
      const double f = std::abs(model.Value(g.Node(queue[q])));
      if (f > deepest) {
        deepest = f;
        c.deepest = queue[q];
      }
    }
    comps.push_back(c);
  }
  return comps;
}

// Grid nodes of the 4 x 4 x 4 block around the cell holding p (clamped to the grid).
template <typename Visit>
void ForBlock(const Grid& g, const int cell[3], int reach, Visit visit) {
  int from[3], to[3];
  for (int a = 0; a < 3; ++a) {
    from[a] = std::max(0, cell[a] - reach + 1);
    to[a] = std::min(g.n[a] - 1, cell[a] + reach);
  }
  for (int k = from[2]; k <= to[2]; ++k)
    for (int j = from[1]; j <= to[1]; ++j)
      for (int i = from[0]; i <= to[0]; ++i) visit(g.Index(i, j, k));
}

}  // namespace

SolidComponents FindSolidComponents(const Model& model, const Vec& lo, const Vec& hi,
                                    double cell, const std::vector<Vec>& points,
                                    const SolidComponentOptions& options) {
  SolidComponents out;
  Grid g;
  g.origin = lo;
  g.h = cell;
  for (;;) {
    double total = 1;
    for (int a = 0; a < 3; ++a) {
      g.n[a] = std::max(2, static_cast<int>(std::ceil((hi[a] - lo[a]) / g.h - 1e-9)) + 1);
      total *= g.n[a];
    }
    if (total <= static_cast<double>(options.max_grid_points)) break;
    g.h *= std::cbrt(total / options.max_grid_points) * 1.01;
  }
  out.lo = lo;
  out.hi = lo + g.h * Vec(g.n[0] - 1, g.n[1] - 1, g.n[2] - 1);
  out.cell = g.h;
  for (int a = 0; a < 3; ++a) out.grid[a] = g.n[a];
  FillSigns(model, ThreadCountOrDefault(options.num_threads), &g);
  std::vector<int> label;
  std::vector<Component> comps = Label(model, g, &label);

  // Scan points near the surface: the nodes they see, the components they count for.
  const double band = options.band > 0 ? options.band : g.h;
  std::vector<char> seen(g.inside.size(), 0);
  std::vector<int> counted;
  for (const Vec& p : points) {
    double f;
    const Vec grad = model.Gradient(p, &f);
    if (!(std::abs(f) <= band * grad.norm())) continue;
    int c[3];
    bool in_grid = true;
    for (int a = 0; a < 3; ++a) {
      const double u = std::floor((p[a] - lo[a]) / g.h);
      in_grid = in_grid && u >= 0 && u <= g.n[a] - 2;
      c[a] = static_cast<int>(std::clamp(u, 0.0, g.n[a] - 2.0));
    }
    if (!in_grid) continue;
    ForBlock(g, c, 2, [&](long node) { seen[node] = 1; });
    counted.clear();
    bool both_signs = false;
    ForBlock(g, c, 1, [&](long node) {
      both_signs = both_signs || g.Inside(node) != g.Inside(g.Index(c[0], c[1], c[2]));
    });
    ForBlock(g, c, both_signs ? 1 : 2, [&](long node) {
      if (std::find(counted.begin(), counted.end(), label[node]) == counted.end())
        counted.push_back(label[node]);
    });
    for (int id : counted) ++comps[id].support_points;
  }
  // Boundary edges and their coverage.
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const long a = g.Index(i, j, k);
        const int ijk[3] = {i, j, k};
        for (int axis = 0; axis < 3; ++axis) {
          if (ijk[axis] + 1 >= g.n[axis]) continue;
          const long b = a + (axis == 0 ? 1 : axis == 1 ? g.n[0] : static_cast<long>(g.n[0]) * g.n[1]);
          if (g.Inside(a) == g.Inside(b)) continue;
          const bool covered = seen[a] || seen[b];
          for (long node : {a, b}) {
            ++comps[label[node]].boundary_edges;
            comps[label[node]].covered_edges += covered;
          }
        }
      }
  for (const Component& c : comps) {
    if (c.inside) out.touches_box = out.touches_box || c.on_face;
    if (!c.inside && c.on_face) continue;  // the space around the solid
    SolidPiece piece;
    piece.cavity = !c.inside;
    piece.nodes = c.nodes;
    piece.volume = c.nodes * g.h * g.h * g.h;
    piece.lo = lo + g.h * Vec(c.lo[0], c.lo[1], c.lo[2]);
    piece.hi = lo + g.h * Vec(c.hi[0], c.hi[1], c.hi[2]);
    piece.witness = g.Node(c.deepest);
    piece.support_points = c.support_points;
    piece.boundary_edges = c.boundary_edges;
    piece.covered_edges = c.covered_edges;
    piece.coverage = c.boundary_edges ? static_cast<double>(c.covered_edges) / c.boundary_edges : 0;
    piece.supported =
        piece.coverage >= options.min_coverage && piece.support_points >= options.min_points;
    out.pieces.push_back(piece);
  }
  std::stable_sort(out.pieces.begin(), out.pieces.end(), [](const SolidPiece& a, const SolidPiece& b) {
    if (a.cavity != b.cavity) return !a.cavity;
    return a.nodes > b.nodes;
  });
  for (const SolidPiece& p : out.pieces) (p.cavity ? out.cavities : out.solids) += 1;
  return out;
}

}  // namespace implicitfit
