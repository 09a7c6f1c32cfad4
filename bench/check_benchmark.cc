// Convexity certificates per second (model/certificates/convexity_certificate.h) for degree 2 (one A^mu)
// and degree 3 (four A^mu), on a pool of random patches, a mix of convex and not (the
// certificate's cost does not depend on the verdict). One thread: the figure is per core.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "model/bernstein/bernstein_patch.h"
#include "model/certificates/convexity_certificate.h"

namespace {

std::vector<double> RandomPatches(int k, int count) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> b(static_cast<size_t>(count * implicitfit::NumBernsteinControlPoints(k)));
  for (double& x : b) x = u(rng);
  return b;
}

void BM_Certificate(benchmark::State& state) {
  const int k = static_cast<int>(state.range(0));
  const int count = 4096;
  const size_t stride = static_cast<size_t>(implicitfit::NumBernsteinControlPoints(k));
  const std::vector<double> b = RandomPatches(k, count);
  int convex = 0;
  size_t i = 0;
  for (auto _ : state) {
    const implicitfit::ConvexityCertificate c =
        implicitfit::CertifyConvexity(k, b.data() + i * stride);
    convex += c.convex;
    benchmark::DoNotOptimize(c.min_eigenvalue);
    i = (i + 1) % count;
  }
  benchmark::DoNotOptimize(convex);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Certificate)->Arg(2)->Arg(3)->Arg(4);

}  // namespace

BENCHMARK_MAIN();
