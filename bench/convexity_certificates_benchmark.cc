// Issue #12 certificates per second (one thread) on docs/convexity.md's random patches
// (tests/support/random_patches.h over the regular tetrahedron (1,1,1), (1,-1,-1), (-1,1,-1),
// (-1,-1,1)): the label-invariant margin (G-2), the tangent-restricted certificate with its
// search over c (G-4 a), the subdivision verdict locally_convex (G-4 b), and the tree
// certificate of a convex-smoothing intersection (LP-4 c).
//
// With --conservative-share (instead of the timing run) it prints, for degrees 2 and 3 on 10^4
// patches each, how many the plain certificate rejects although sampling (300 segments, >= 2 zero
// points) finds no violation ("conservative"), and how many of those the new certificate
// certifies; also any contradiction (certified, yet a sampling violation), which must be 0.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "model/certificates/convexity_certificate.h"
#include "model/certificates/patch_certificates.h"
#include "model/certificates/tangent_plane_test.h"
#include "model/certificates/tree_certificate.h"
#include "support/random_patches.h"

namespace {

using namespace implicitfit;

const Tetrahedron& RegularTetrahedron() {
  static const Tetrahedron t(Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, -1, -1),
                             Eigen::Vector3d(-1, 1, -1), Eigen::Vector3d(-1, -1, 1));
  return t;
}

std::vector<std::vector<double>> Pool(int k, int count) {
  std::mt19937 rng(7);
  std::vector<std::vector<double>> pool;
  for (int i = 0; i < count; ++i) pool.push_back(testsupport::RandomMixedPatch(rng, k));
  return pool;
}

void BM_CartesianMargin(benchmark::State& state) {
  const int k = static_cast<int>(state.range(0));
  const auto pool = Pool(k, 1024);
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(CartesianConvexityMargin(k, RegularTetrahedron(), pool[i].data()));
    i = (i + 1) % pool.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CartesianMargin)->Arg(2)->Arg(3);

void BM_Finsler(benchmark::State& state) {
  const int k = static_cast<int>(state.range(0));
  const auto pool = Pool(k, 256);
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(CertifyFinsler(k, pool[i].data()).convex);
    i = (i + 1) % pool.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Finsler)->Arg(2)->Arg(3);

void BM_LocallyConvex(benchmark::State& state) {
  const int k = static_cast<int>(state.range(0));
  const auto pool = Pool(k, 256);
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(CertifyLocalConvexity(k, pool[i].data()).locally_convex);
    i = (i + 1) % pool.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LocallyConvex)->Arg(2)->Arg(3);

void BM_TreeCertificate(benchmark::State& state) {
  Model m;
  std::vector<int> children;
  for (int i = 0; i < 4; ++i)
    children.push_back(m.AddPrimitive(
        NodeType::kPlane, {i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i >= 2 ? 1.0 : 0.0, 1.0}));
  children.push_back(m.AddPrimitive(NodeType::kSphere, {0, 0, 0, 1.2}));
  const int op = m.AddOperator(NodeType::kIntersection, children, 0.1, 0.1, 3);
  m.mutable_nodes()[op].smoothing = BlendSmoothing::kConvex;
  for (auto _ : state) benchmark::DoNotOptimize(CertifyTree(m)[m.root()].convexity);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TreeCertificate);

int ConservativeShare() {
  for (int k : {2, 3}) {
    const auto pool = Pool(k, 10000);
    int plain = 0, finsler = 0, conservative = 0, confirmed = 0, undecided = 0, rescued = 0;
    int local_rescued = 0, contradictions = 0;
    for (size_t i = 0; i < pool.size(); ++i) {
      const double* b = pool[i].data();
      const bool p = CertifyConvexity(k, b).convex;
      const bool f = CertifyFinsler(k, b).convex;
      TangentPlaneTestOptions o;
      o.segments = 300;
      o.seed = i + 1;
      const TangentPlaneTestResult s = TangentPlaneTest(k, RegularTetrahedron(), b, o);
      plain += p;
      finsler += f;
      if ((p || f) && s.violations > 0) ++contradictions;
      if (p) continue;
      if (s.violations > 0) {
        ++confirmed;
      } else if (s.zero_points >= 2) {
        ++conservative;
        rescued += f;
        local_rescued += CertifyLocalConvexity(k, b).locally_convex;
      } else {
        ++undecided;
      }
    }
    const int judged = conservative + confirmed;
    std::printf(
        "degree %d, %zu patches: plain certified %d, finsler certified %d; of the %d not plainly "
        "certified: %d confirmed non-convex, %d conservative, %d undecided.\n"
        "  conservative share before %.1f%% (%d/%d), after %.1f%% (%d/%d: finsler certifies %d); "
        "locally_convex (a separate, weaker verdict) on %d of the conservative; contradictions "
        "%d\n",
        k, pool.size(), plain, finsler, static_cast<int>(pool.size()) - plain, confirmed,
        conservative, undecided, 100.0 * conservative / std::max(1, judged), conservative, judged,
        100.0 * (conservative - rescued) / std::max(1, judged), conservative - rescued, judged,
        rescued, local_rescued, contradictions);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--conservative-share") == 0) return ConservativeShare();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
