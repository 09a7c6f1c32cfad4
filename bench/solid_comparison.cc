// implicitfit reconstruct + mesh vs Poisson surface reconstruction (PCL's pcl::Poisson and
// CGAL 5.5's poisson_surface_reconstruction_delaunay) on the same clouds and the same normals, in
// one run.
// Clouds (bench/solid_cases.h):
//   generated solids (datasets/generators/generated_solids.h: the three of issue 14 and three
//     parts) sampled with noise 0.2% of their size (--outliers adds uniform outliers); truth: the
//     model (first-order distance |f| / |grad f|, normal grad f / |grad f|); truth samples:
//     noise-free samples of it. Two clouds each: exact normals, implicitfit started from
//     primitives fitted to ground-truth labels (diagnostic rows, `--labels 0` leaves them out),
//     and points only (normals stripped, estimated and oriented: datasets/normals/
//     normal_estimation.h), implicitfit end to end;
//   the Fit4CAD parts (../shared/data/fit4cad, GPL-3, read only; points and labels, no normals:
//     estimated and oriented as `reconstruct` does, for every method); truth: each labelled
//     point's ground-truth surface (planes and quadrics: the implicit equation; tori: the exact
//     torus distance, the torus read from the parametric file by
//     datasets/generators/fit4cad_torus.h); implicitfit from the labels (diagnostic) and end to
//     end;
//   CGAL's box-on-ground scan (exact outward normals, no labels): with the file's normals
//     (detect first, diagnostic) and points only (normals estimated); truth: the tangent plane of
//     each point (its faces are planar);
//   the Kinect milk carton of datasets/data (points only; normals estimated and oriented toward
//     the PCD's viewpoint, as `reconstruct` does); truth: each point's tangent plane from those
//     normals (no CAD truth: the figures measure agreement with the scan).
//   For the real clouds, the distance of x to the truth is the least, over its 16 nearest truth
//   points p, of: e, the first-order distance of x to p's surface (equation or tangent plane),
//   when x projects onto that surface within twice the local sampling radius of p
//   (sqrt(|x - p|^2 - e^2) <= 2 r_p, r_p the distance from p to its 8th nearest truth point:
//   random samples leave holes that large, e.g. 0.58 on Fit4CAD PC33's top face; a face wrongly
//   extended by less than that is still caught from the other side, truth -> mesh, by the
//   neighbouring face), else |x - p| (x is beyond the sampled part of p's surface). Truth
//   samples: the points. A Fit4CAD part whose truth holds an internal face (two labels on one
//   surface, interleaved: PC155's slab top under the dome's own base, two bodies touching) gets
//   a second row per method without those truth points (bench/solid_cases.h), since no one-piece
//   solid has a surface there.
// End to end is implicitfit/reconstruct.h's ReconstructCloud, what `reconstruct CLOUD` runs after
// reading the cloud: detect, orientation, CSG, fit, verification; then the mesh (256 cells on
// the longest side of the meshing box, --cells: the finest grid of PCL's Poisson at depth 8; the
// box is `mesh`'s default, the verified solid's proven bounds enlarged by 10%; an unverified
// solid gets no row figures). When reconstruct closed an open scan, a
// second row judges the mesh without its faces on closure planes (fit/reconstruct/
// solid_bounding.h: not measured). Figures: Chamfer distance (mean of the two directed mean
// distances: mesh -> truth at 50 000 area-uniform mesh points, truth -> mesh by exact
// point-triangle distance from the truth samples), Hausdorff distance (largest of both), normal
// consistency (mean of n_face . n_truth, signed: 1 is perfect, orientation included), connected
// components of the mesh (triangles sharing vertices), watertightness (edges not in exactly two
// triangles), bounded (implicitfit: f > 0 at every point of a 33 x 33 grid on the faces of boxes
// 2, 10 and 1000 times the cloud's box, a far-field check of the model itself, which the mesh
// box would hide), time (implicitfit: detect, reconstruction and meshing, not the normals, which
// every method is given; Poisson: its reconstruction). The last column gives implicitfit / the
// best Poisson figure on the same cloud and normals.
//   build/bench/solid_comparison [--points 20000] [--outliers 0] [--seed 1] [--only NAME]
//                                [--cells 256] [--fit-iterations n] [--no-poisson 1]
//                                [--fixed-offset 1] [--labels 0] [--heldout 1]
// stderr: each implicitfit expression and where its Hausdorff distance is reached.
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "implicitfit/reconstruct.h"
#ifdef IMPLICITFIT_HAVE_CGAL_POISSON
#include "bench/cgal_poisson.h"
#endif
#include "bench/mesh_judging.h"
#include "bench/solid_cases.h"
#include "datasets/meshing/model_mesher.h"
#include "fit/reconstruct/solid_reconstruction.h"

namespace {

using bench::SolidCloud;
using bench::TruthDistance;
using implicitfit::TriangleMesh;
using Vec = Eigen::Vector3d;

double Seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec ClosestOnTriangle(const Vec& p, const Vec& a, const Vec& b, const Vec& c) {
  const Vec ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

struct Figures {
  double chamfer = 0, hausdorff = 0, normal_consistency = 0, seconds = 0;
  long bad_edges = 0;
  int components = 0;
  size_t triangles = 0;
  bool ok = false;
  std::string bounded = "-";   // implicitfit: "yes" / "no (n points)"
  Vec worst = Vec::Zero();     // where the Hausdorff distance is reached
  bool worst_on_mesh = false;  // ... at a mesh point (mesh -> truth) or a truth point
};

// Connected components of the mesh: triangles joined through shared vertices (union-find).
int Components(const TriangleMesh& mesh) {
  std::vector<int> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const Eigen::Vector3i& t : mesh.triangles) {
    parent[find(t[1])] = find(t[0]);
    parent[find(t[2])] = find(t[0]);
  }
  std::vector<bool> root(mesh.vertices.size(), false);
  int count = 0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const int r = find(t[0]);
    if (!root[r]) ++count;
    root[r] = true;
  }
  return count;
}

Figures Judge(const TriangleMesh& mesh, const TruthDistance& truth,
              const std::vector<Vec>& truth_points, unsigned seed) {
  Figures fig;
  fig.triangles = mesh.triangles.size();
  if (mesh.triangles.empty()) return fig;
  fig.ok = true;
  std::map<std::pair<int, int>, int> uses;
  for (const Eigen::Vector3i& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  for (const auto& [e, n] : uses) fig.bad_edges += n != 2;
  fig.components = Components(mesh);
  // mesh -> truth at area-uniform mesh points.
  std::vector<double> cumulative;
  double area = 0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    area += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                      .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                      .norm();
    cumulative.push_back(area);
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  double sum_mt = 0, max_mt = 0, normals = 0;
  const int samples = 50000;
  for (int s = 0; s < samples; ++s) {
    const size_t i = std::min(
        cumulative.size() - 1,
        static_cast<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), u(rng) * area) -
                            cumulative.begin()));
    const Eigen::Vector3i& t = mesh.triangles[i];
    const double r1 = std::sqrt(u(rng)), r2 = u(rng);
    const Vec x = (1 - r1) * mesh.vertices[t[0]] + r1 * (1 - r2) * mesh.vertices[t[1]] +
                  r1 * r2 * mesh.vertices[t[2]];
    Vec n_truth;
    const double d = truth(x, &n_truth);
    sum_mt += d;
    if (d > max_mt) {
      max_mt = d;
      fig.worst = x;
      fig.worst_on_mesh = true;
    }
    const Vec n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                      .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                      .normalized();
    if (n.allFinite()) normals += n.dot(n_truth);
  }
  // truth -> mesh: exact distance to the nearest of the 16 triangles with the nearest centroids.
  pcl::PointCloud<pcl::PointXYZ>::Ptr centroids(new pcl::PointCloud<pcl::PointXYZ>);
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Vec c = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3;
    centroids->push_back(pcl::PointXYZ(c.x(), c.y(), c.z()));
  }
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(centroids);
  std::vector<int> idx;
  std::vector<float> d2;
  double sum_tm = 0, max_tm = 0;
  for (const Vec& p : truth_points) {
    tree.nearestKSearch(pcl::PointXYZ(p.x(), p.y(), p.z()), 16, idx, d2);
    double best = 1e300;
    for (int i : idx) {
      const Eigen::Vector3i& t = mesh.triangles[i];
      best = std::min(best, (p - ClosestOnTriangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]],
                                                   mesh.vertices[t[2]]))
                                .norm());
    }
    sum_tm += best;
    if (best > max_tm) {
      max_tm = best;
      if (max_tm > max_mt) {
        fig.worst = p;
        fig.worst_on_mesh = false;
      }
    }
  }
  fig.chamfer = 0.5 * (sum_mt / samples + sum_tm / truth_points.size());
  fig.hausdorff = std::max(max_mt, max_tm);
  fig.normal_consistency = normals / samples;
  return fig;
}

void Row(const std::string& cloud, const std::string& start, const std::string& method,
         const Figures& f, double size, const Figures* best_poisson = nullptr) {
  if (!f.ok) {
    std::printf("| %s | %s | %s | failed | | | | | | | %.2f | |\n", cloud.c_str(), start.c_str(),
                method.c_str(), f.seconds);
    std::fflush(stdout);
    return;
  }
  std::string ratio;
  if (best_poisson && best_poisson->ok) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.2f / %.2f", f.chamfer / best_poisson->chamfer,
                  f.hausdorff / best_poisson->hausdorff);
    ratio = buffer;
  }
  std::printf(
      "| %s | %s | %s | %.5f (%.2e) | %.5f (%.2e) | %.4f | %d | %s (%ld) | %s | %zu | %.2f | %s "
      "|\n",
      cloud.c_str(), start.c_str(), method.c_str(), f.chamfer, f.chamfer / size, f.hausdorff,
      f.hausdorff / size, f.normal_consistency, f.components, f.bad_edges ? "no" : "yes",
      f.bad_edges, f.bounded.c_str(), f.triangles, f.seconds, ratio.c_str());
  std::fflush(stdout);
}

// Grid points on the faces of boxes 2, 10 and 1000 times the cloud's box where f <= 0 (2: a
// closure box in the part's frame may reach beyond 1.5 times the cloud's axis-aligned box).
int NonPositiveFarAway(const implicitfit::Model& m, const std::vector<Vec>& points) {
  Vec lo = points[0], hi = points[0];
  for (const Vec& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Vec c = 0.5 * (lo + hi);
  const int n = 32;
  int bad = 0;
  for (const double scale : {2.0, 10.0, 1000.0}) {
    const Vec h = 0.5 * scale * (hi - lo);
    for (int axis = 0; axis < 3; ++axis)
      for (const double side : {-1.0, 1.0})
        for (int u = 0; u <= n; ++u)
          for (int v = 0; v <= n; ++v) {
            const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
            Vec x;
            x[axis] = c[axis] + side * h[axis];
            x[a1] = c[a1] + h[a1] * (2.0 * u / n - 1);
            x[a2] = c[a2] + h[a2] * (2.0 * v / n - 1);
            bad += !(m.Value(x) > 0);
          }
  }
  return bad;
}

// The row label of the figures without the truth's internal-face points (bench/solid_cases.h).
std::string InternalFacesText(const SolidCloud& c) {
  return "internal faces of the truth left out (" + std::to_string(c.internal_face_points) +
         " of " + std::to_string(c.truth_points.size()) + " truth points)";
}

int g_cells = 256;         // cells of implicitfit's mesh on the longest side (--cells)
int g_fit_iterations = 0;  // --fit-iterations: the tree fitter's iterations per pass (0: default)
bool g_poisson = true;     // --no-poisson: implicitfit's rows only
bool g_adaptive = true;    // --fixed-offset 1: the inside/outside samples at the fixed offset

// implicitfit on one cloud: from its labelled primitives (labelled) or end to end; one or two
// rows (the second without the closure faces).
void RunImplicitfit(const SolidCloud& c, bool labelled, unsigned seed, const Figures& best,
                    const Figures& best_outer) {
  const std::string start = labelled ? "labels, " + c.normals + " normals"
                                     : "points only, " + c.normals + " normals";
  auto t0 = std::chrono::steady_clock::now();
  Figures f, measured;  // measured: without the faces on closure planes (not seen in the data)
  Figures outer;        // against the truth points off internal faces (SolidCloud)
  bool closed = false;
  std::string method = "implicitfit";
  try {
    implicitfit::SolidReconstruction r;
    size_t primitives = c.labelled.size();
    if (!labelled) {  // implicitfit/reconstruct.h: detect, then reconstruct
      implicitfit::PointCloud cloud;
      cloud.points = c.points;
      cloud.normals = c.normals_of_points;
      implicitfit::ReconstructJobOptions options;
      options.seed = seed;
      const implicitfit::CloudReconstruction job =
          implicitfit::ReconstructCloud(cloud, c.name, c.normals, options);
      r = job.result;
      primitives = job.primitives.size();
    } else {
      implicitfit::SolidReconstructionOptions ro;
      ro.seed = seed;
      if (g_fit_iterations > 0) ro.tree.max_iterations = g_fit_iterations;
      ro.adaptive_offset = g_adaptive;
      r = implicitfit::ReconstructSolid(c.points, c.normals_of_points, c.labelled, ro);
    }
    if (r.success) {
      // `mesh`'s default box (the verified solid's proven bounds, enlarged by 10%), the cell
      // of --cells on its longest side: what `reconstruct --mesh` and `mesh MODEL.json` mesh.
      implicitfit::MeshOptions mo;
      implicitfit::DefaultMeshBox(r.model, &mo.box_min, &mo.box_max);
      mo.cell = (mo.box_max - mo.box_min).maxCoeff() / g_cells;
      const TriangleMesh ours = implicitfit::MeshModel(r.model, mo).mesh;
      const double seconds = Seconds(t0);
      f = Judge(ours, c.truth, c.truth_points, seed);
      f.seconds = seconds;
      if (c.internal_face_points > 0) {
        outer = Judge(ours, c.truth, c.truth_points_outside_internal_faces, seed);
        outer.seconds = seconds;
      }
      const int far = NonPositiveFarAway(r.model, c.points);
      f.bounded = far ? "no (" + std::to_string(far) + ")" : "yes";
      if (!r.closures.empty()) {
        // The measured part: triangles with a vertex off every closure plane.
        closed = true;
        TriangleMesh seen = ours;
        seen.triangles.clear();
        const double tolerance = 1e-7 * c.size;
        for (const Eigen::Vector3i& t : ours.triangles) {
          bool on_closure = false;
          for (const implicitfit::AddedPlane& q : r.closures) {
            bool all = true;
            for (int k = 0; k < 3; ++k)
              all = all && std::abs(q.normal.dot(ours.vertices[t[k]]) - q.offset) < tolerance;
            on_closure = on_closure || all;
          }
          if (!on_closure) seen.triangles.push_back(t);
        }
        measured = Judge(seen, c.truth, c.truth_points, seed);
        measured.seconds = seconds;
        measured.bounded = f.bounded;
      }
      outer.bounded = f.bounded;
    } else {
      method += " (" + r.message + ")";
      f.seconds = outer.seconds = Seconds(t0);
    }
    std::fprintf(stderr,
                 "%s [%s]: %s, %zu primitives, %zu blends, %.1f s (tree fit %.1f s, %d "
                 "iterations)\n",
                 c.name.c_str(), start.c_str(), r.expression.c_str(), primitives, r.blends.size(),
                 r.seconds, r.fit_seconds, r.fit_iterations);
    std::string sides;  // per primitive: s(olid), h(ole), u(nused)
    for (const std::string& side : r.sides) sides += side.empty() ? '?' : side[0];
    std::fprintf(stderr, "%s [%s]: sides %s, normal agreement %.4f of %d inliers (sigma %.3g), %s\n",
                 c.name.c_str(), start.c_str(), sides.c_str(), r.normal_agreement, r.inliers,
                 r.sigma, r.message.c_str());
    if (f.ok)  // where implicitfit's largest deviation is (stderr, for the analysis)
      std::fprintf(
          stderr, "%s [%s]: Hausdorff distance at (%.6g, %.6g, %.6g), %s\n", c.name.c_str(),
          start.c_str(), f.worst.x(), f.worst.y(), f.worst.z(),
          f.worst_on_mesh ? "a mesh point far from the truth" : "a truth point far from the mesh");
  } catch (const std::exception& e) {
    method += std::string(" (") + e.what() + ")";
    f.seconds = outer.seconds = Seconds(t0);
  }
  Row(c.name, start, method, f, c.size, &best);
  if (c.internal_face_points > 0)
    Row(c.name, start, method + ", " + InternalFacesText(c), outer, c.size, &best_outer);
  if (closed)
    Row(c.name, start, method + ", closure faces left out (not measured)", measured, c.size,
        &best);
}

// Every row of one cloud: Poisson (PCL depths 7, 8; CGAL) on its points and normals, then
// implicitfit from the labels and/or end to end, compared with the best Poisson figures.
void RunCloud(const SolidCloud& c, unsigned seed) {
  // Per Poisson method: its figures against every truth point, and (when the truth has internal
  // faces) against the points off them.
  std::vector<std::pair<std::string, std::array<Figures, 2>>> poisson;
  auto judge_poisson = [&](const std::string& name, const TriangleMesh& mesh, double seconds) {
    std::array<Figures, 2> p;
    p[0] = Judge(mesh, c.truth, c.truth_points, seed);
    if (c.internal_face_points > 0)
      p[1] = Judge(mesh, c.truth, c.truth_points_outside_internal_faces, seed);
    p[0].seconds = p[1].seconds = seconds;
    poisson.emplace_back(name, p);
  };
  if (g_poisson) {
    for (int depth : {7, 8}) {
      const auto t0 = std::chrono::steady_clock::now();
      const TriangleMesh mesh = bench::PoissonMesh(c.points, c.normals_of_points, depth);
      judge_poisson("PCL Poisson depth " + std::to_string(depth), mesh, Seconds(t0));
    }
#ifdef IMPLICITFIT_HAVE_CGAL_POISSON
    const implicitfit_bench::CgalPoissonResult cgal =
        implicitfit_bench::CgalPoisson(c.points, c.normals_of_points);
    if (cgal.success)
      judge_poisson("CGAL Poisson", cgal.mesh, cgal.seconds);
    else
      poisson.push_back({"CGAL Poisson", {}});
#endif
  }
  std::array<Figures, 2> best;  // the best Poisson figure of each kind (the strictest comparison)
  for (int v = 0; v < 2; ++v) {
    best[v].chamfer = best[v].hausdorff = 1e300;
    for (const auto& [name, q] : poisson)
      if (q[v].ok) {
        best[v].ok = true;
        best[v].chamfer = std::min(best[v].chamfer, q[v].chamfer);
        best[v].hausdorff = std::min(best[v].hausdorff, q[v].hausdorff);
      }
  }
  if (!c.labelled.empty()) RunImplicitfit(c, true, seed, best[0], best[1]);
  if (c.end_to_end) RunImplicitfit(c, false, seed, best[0], best[1]);
  const std::string start = c.normals + " normals";
  for (const auto& [name, q] : poisson) {
    Row(c.name, start, name, q[0], c.size);
    if (c.internal_face_points > 0) Row(c.name, start, name + ", " + InternalFacesText(c), q[1], c.size);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int points = 20000;
  double outliers = 0.0;
  unsigned seed = 1;
  bool labels = true, heldout = false;
  std::string only;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--points"))
      points = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--outliers"))
      outliers = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--seed"))
      seed = static_cast<unsigned>(std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--cells"))
      g_cells = std::max(8, std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--only"))
      only = argv[i + 1];
    else if (!std::strcmp(argv[i], "--fit-iterations"))
      g_fit_iterations = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--no-poisson") && !std::strcmp(argv[i + 1], "1"))
      g_poisson = false;
    else if (!std::strcmp(argv[i], "--fixed-offset") && !std::strcmp(argv[i + 1], "1"))
      g_adaptive = false;
    else if (!std::strcmp(argv[i], "--labels") && !std::strcmp(argv[i + 1], "0"))
      labels = false;
    else if (!std::strcmp(argv[i], "--heldout") && !std::strcmp(argv[i + 1], "1"))
      heldout = true;
  }
  std::printf(
      "| cloud | start | method | Chamfer (/ size) | Hausdorff (/ size) | normal consistency | "
      "components | watertight (bad edges) | bounded | triangles | seconds | Chamfer / "
      "Hausdorff vs best Poisson |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  auto wanted = [&](const std::string& name) {
    return only.empty() || name.find(only) != std::string::npos;
  };
  for (const SolidCloud& c : bench::GeneratedClouds(points, outliers, seed, labels))
    if (wanted(c.name)) RunCloud(c, seed);
  if (heldout)
    for (const SolidCloud& c : bench::HeldOutClouds(points, seed))
      if (wanted(c.name)) RunCloud(c, seed);
  const std::string data = IMPLICITFIT_SHARED_DATA;
  for (const std::string part : {"test_PC33", "test_PC34", "test_PC35", "test_PC21", "train_PC124",
                                 "train_PC131", "train_PC145", "train_PC155"}) {
    if (!wanted("Fit4CAD " + part)) continue;
    SolidCloud c;
    std::string why;
    if (bench::Fit4CadCloud(data, part, seed, labels, &c, &why))
      RunCloud(c, seed);
    else
      std::printf("| Fit4CAD %s | | skipped: %s | | | | | | | | | |\n", part.c_str(), why.c_str());
  }
  const std::string box = data + "/cgal/cgal_point_set_3_box_on_ground.xyz";
  const std::string milk = std::string(IMPLICITFIT_SOURCE_DIR) +
                           "/datasets/data/pcl_milk_carton_kinect.pcd";
  for (const auto& [path, name, points_only] :
       {std::tuple<std::string, std::string, bool>{box, "CGAL box on ground", false},
        {box, "CGAL box on ground", true},
        {milk, "Kinect milk carton", true}}) {
    if (!wanted(name) || (!points_only && !labels)) continue;
    SolidCloud c;
    std::string why;
    if (bench::ScanCloud(path, name, points_only, &c, &why))
      RunCloud(c, seed);
    else
      std::printf("| %s | | skipped: %s | | | | | | | | | |\n", name.c_str(), why.c_str());
  }
  return 0;
}
