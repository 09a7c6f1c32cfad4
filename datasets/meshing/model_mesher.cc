#include "datasets/meshing/model_mesher.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <thread>

#include "datasets/io/atomic_file.h"
#include "datasets/generators/model_sampler.h"
#include "datasets/meshing/default_mesh_cell.h"
#include "datasets/meshing/sharp_features.h"
#include "model/worker_threads.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// The grid: values at origin + h (i, j, k), i fastest (VTK's point order).
struct Grid {
  Vec origin;
  double h = 0.0;
  int n[3] = {0, 0, 0};
  std::vector<double> values;
  long Index(int i, int j, int k) const {
    return i + static_cast<long>(n[0]) * (j + static_cast<long>(n[1]) * k);
  }
  Vec Point(int i, int j, int k) const { return origin + h * Vec(i, j, k); }
};

int ThreadsOrDefault(int num_threads) {
  return std::max(1, num_threads > 0 ? num_threads
                                     : static_cast<int>(std::thread::hardware_concurrency()));
}

void FillGrid(const Model& model, int num_threads, Grid* grid) {
  grid->values.assign(static_cast<size_t>(grid->n[0]) * grid->n[1] * grid->n[2], 0.0);
  const int threads = ThreadsOrDefault(num_threads);
  const double tiny = 1e-12 * grid->h;
  auto slab = [&](int t) {
    for (int k = t; k < grid->n[2]; k += threads)
      for (int j = 0; j < grid->n[1]; ++j)
        for (int i = 0; i < grid->n[0]; ++i) {
          double v = model.Value(grid->Point(i, j, k));
          if (std::isnan(v)) v = grid->h;  // undefined counts as outside
          if (v == 0.0) v = tiny;          // no vertex exactly on a grid node
          grid->values[grid->Index(i, j, k)] = v;
        }
  };
  RunWorkers(threads, slab);
}

// Root of f on the segment a + s (b - a), s in [0, 1], given fa < 0 <= fb or fa >= 0 > fb:
// Illinois method (regula falsi that halves the retained end's value when it is kept twice).
Vec RootOnEdge(const Model& model, const Vec& a, const Vec& b, double fa, double fb) {
  double s0 = 0.0, s1 = 1.0, f0 = fa, f1 = fb;
  int side = 0;
  double s = 0.5;
  for (int it = 0; it < 60; ++it) {
    s = (s0 * f1 - s1 * f0) / (f1 - f0);
    if (!(s > s0 && s < s1)) s = 0.5 * (s0 + s1);
    const double fs = model.Value(a + s * (b - a));
    if (fs == 0.0 || std::isnan(fs) || s1 - s0 < 1e-13) break;
    if ((fs < 0) == (f0 < 0)) {
      s0 = s;
      f0 = fs;
      if (side == -1) f1 *= 0.5;
      side = -1;
    } else {
      s1 = s;
      f1 = fs;
      if (side == 1) f0 *= 0.5;
      side = 1;
    }
  }
  return a + s * (b - a);
}

// A model whose root is a Bernstein mesh (a patch-mesh fit) without stated bounds: f is fitted
// on the grid box only; outside it the boundary tetrahedra's polynomials are extrapolated
// (docs/patch-mesh.md) and can change sign, sheets that are no surface of the fit (measured on a
// box fitted at one level: 1.5-10% of the mesh's area half a box away, growing with the cell).
// Its default mesh box is therefore the grid box itself, not enlarged.
bool DefinedOnItsGridBoxOnly(const Model& model) {
  return !model.claims().has_bounds && model.root() >= 0 &&
         model.nodes()[model.root()].type == NodeType::kBernsteinMesh;
}

}  // namespace

void DefaultMeshBox(const Model& model, Vec* box_min, Vec* box_max) {
  if (DefinedOnItsGridBoxOnly(model)) {
    const BernsteinGrid& grid = model.nodes()[model.root()].grid;
    *box_min = grid.BoxMin();
    *box_max = grid.BoxMax();
    return;
  }
  if (model.claims().has_bounds) {  // the writer's box of {f <= 0} (a verified solid's)
    *box_min = model.claims().bounds_min;
    *box_max = model.claims().bounds_max;
  } else {
    SamplingBox(model, box_min, box_max);
  }
  const Vec margin = 0.1 * (*box_max - *box_min);
  *box_min -= margin;
  *box_max += margin;
}

namespace {

// 1. The box (given, or the model's own plus two cells on every side, so that a closed surface
// stays off the faces), the cell (given, or DefaultMeshCell), f at every grid node.
Grid SampleGrid(const Model& model, const MeshOptions& options, MeshResult* result) {
  Vec lo, hi;
  if (options.has_box) {
    lo = options.box_min;
    hi = options.box_max;
  } else {
    DefaultMeshBox(model, &lo, &hi);
  }
  if (!lo.allFinite() || !hi.allFinite() || !((hi - lo).array() > 0).all())
    throw std::invalid_argument("mesh box must have min < max on every axis");
  const double longest = (hi - lo).maxCoeff();
  const double h = options.cell > 0 ? options.cell : DefaultMeshCell(model, longest);
  if (!(h > 0) || !std::isfinite(h)) throw std::invalid_argument("mesh cell must be > 0");
  if (!options.has_box && !DefinedOnItsGridBoxOnly(model)) {
    lo -= Vec::Constant(2 * h);
    hi += Vec::Constant(2 * h);
  }
  Grid grid;
  grid.origin = lo;
  grid.h = h;
  double points = 1.0;
  for (int a = 0; a < 3; ++a) {
    const double cells = std::ceil((hi[a] - lo[a]) / h - 1e-9);
    points *= cells + 1;
    if (points > static_cast<double>(options.max_grid_points))
      throw std::invalid_argument("mesh grid too fine: more than " +
                                  std::to_string(options.max_grid_points) +
                                  " grid points (use a larger cell)");
    grid.n[a] = static_cast<int>(cells) + 1;
  }
  result->box_min = lo;
  result->box_max = lo + h * Vec(grid.n[0] - 1, grid.n[1] - 1, grid.n[2] - 1);
  result->cell = h;
  FillGrid(model, options.num_threads, &grid);
  return grid;
}

// 2. VTK's flying edges on the grid, in index space (origin 0, spacing 1): VTK's points are
// float, so small numbers keep them precise enough to tell which grid edge each vertex lies on.
vtkSmartPointer<vtkPolyData> ContourInIndexSpace(Grid* grid) {
  vtkNew<vtkImageData> image;
  image->SetDimensions(grid->n[0], grid->n[1], grid->n[2]);
  image->SetOrigin(0, 0, 0);
  image->SetSpacing(1, 1, 1);
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("f");
  scalars->SetNumberOfComponents(1);
  scalars->SetArray(grid->values.data(), static_cast<vtkIdType>(grid->values.size()),
                    1);  // no copy
  image->GetPointData()->SetScalars(scalars);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetNumberOfContours(1);
  contour->SetValue(0, 0.0);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->InterpolateAttributesOff();
  contour->Update();
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->ShallowCopy(contour->GetOutput());
  return poly;
}

// 3. Each vertex: its grid edge (the edge from the nearest node whose linear interpolation lands
// on the vertex), then the root of f on that edge. abs_value: |f| at each vertex.
void PlaceVerticesOnRoots(const Model& model, const Grid& grid, vtkPolyData* poly, int num_threads,
                          TriangleMesh* mesh, std::vector<double>* abs_value) {
  const vtkIdType num_points = poly->GetNumberOfPoints();
  mesh->vertices.resize(num_points);
  abs_value->assign(num_points, 0.0);
  const int threads = ThreadsOrDefault(num_threads);
  auto refine = [&](int t) {
    double u[3];
    for (vtkIdType v = t; v < num_points; v += threads) {
      poly->GetPoint(v, u);
      int node[3];
      for (int a = 0; a < 3; ++a)
        node[a] = std::clamp(static_cast<int>(std::lround(u[a])), 0, grid.n[a] - 1);
      const double f_node = grid.values[grid.Index(node[0], node[1], node[2])];
      double best = std::numeric_limits<double>::infinity();
      int best_other[3] = {node[0], node[1], node[2]};
      for (int a = 0; a < 3; ++a)
        for (int step : {-1, 1}) {
          int other[3] = {node[0], node[1], node[2]};
          other[a] += step;
          if (other[a] < 0 || other[a] >= grid.n[a]) continue;
          const double f_other = grid.values[grid.Index(other[0], other[1], other[2])];
          if ((f_node < 0) == (f_other < 0)) continue;
          const double s = f_node / (f_node - f_other);
          double d2 = 0;
          for (int b = 0; b < 3; ++b) {
            const double x = node[b] + s * (other[b] - node[b]);
            d2 += (x - u[b]) * (x - u[b]);
          }
          if (d2 < best) {
            best = d2;
            std::copy(other, other + 3, best_other);
          }
        }
      const Vec a = grid.Point(node[0], node[1], node[2]);
      if (best < 1e-4) {
        const Vec b = grid.Point(best_other[0], best_other[1], best_other[2]);
        const double f_b = grid.values[grid.Index(best_other[0], best_other[1], best_other[2])];
        mesh->vertices[v] = RootOnEdge(model, a, b, f_node, f_b);
      } else {  // not expected; keep VTK's interpolated position
        mesh->vertices[v] = grid.origin + grid.h * Vec(u[0], u[1], u[2]);
      }
      const double f = model.Value(mesh->vertices[v]);
      (*abs_value)[v] = std::isfinite(f) ? std::abs(f) : std::numeric_limits<double>::infinity();
    }
  };
  RunWorkers(threads, refine);
}

// The triangles of the contour, and the grid cell of each (step 5): its vertices lie on edges
// of one cell, so its centroid (index space) is inside it.
void CollectTriangles(vtkPolyData* poly, const Grid& grid, TriangleMesh* mesh,
                      std::vector<Eigen::Vector3i>* cells) {
  vtkCellArray* polys = poly->GetPolys();
  mesh->triangles.reserve(polys->GetNumberOfCells());
  cells->reserve(polys->GetNumberOfCells());
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c) {
    polys->GetCellAtId(c, ids);
    if (ids->GetNumberOfIds() != 3) continue;  // flying edges emits triangles only
    mesh->triangles.emplace_back(static_cast<int>(ids->GetId(0)), static_cast<int>(ids->GetId(1)),
                                 static_cast<int>(ids->GetId(2)));
    Vec centroid = Vec::Zero();
    for (int k = 0; k < 3; ++k) {
      double u[3];
      poly->GetPoint(ids->GetId(k), u);
      centroid += Vec(u[0], u[1], u[2]) / 3.0;
    }
    Eigen::Vector3i cell;
    for (int a = 0; a < 3; ++a)
      cell[a] = std::clamp(static_cast<int>(std::floor(centroid[a])), 0, grid.n[a] - 2);
    cells->push_back(cell);
  }
}

// 3b. Jumps: a grid edge whose ends differ in sign but across which f jumps instead of passing
// through 0 (the signed distance to an open patch, beyond its boundary) leaves its vertex at |f|
// far above the rounding level: triangles touching such a vertex are dropped, and the vertices
// no triangle keeps.
void DropJumpTriangles(double h, const std::vector<double>& abs_value, TriangleMesh* mesh,
                       std::vector<Eigen::Vector3i>* cells, MeshResult* result) {
  std::vector<Eigen::Vector3i> kept, kept_cells;
  for (size_t t = 0; t < mesh->triangles.size(); ++t) {
    const Eigen::Vector3i& tri = mesh->triangles[t];
    if (abs_value[tri[0]] > kJumpFraction * h || abs_value[tri[1]] > kJumpFraction * h ||
        abs_value[tri[2]] > kJumpFraction * h) {
      ++result->jump_triangles;
      continue;
    }
    kept.push_back(tri);
    kept_cells.push_back((*cells)[t]);
  }
  if (result->jump_triangles == 0) return;
  std::vector<int> remap(mesh->vertices.size(), -1);
  std::vector<Vec> vertices;
  std::vector<double> values;
  for (Eigen::Vector3i& tri : kept)
    for (int k = 0; k < 3; ++k) {
      if (remap[tri[k]] < 0) {
        remap[tri[k]] = static_cast<int>(vertices.size());
        vertices.push_back(mesh->vertices[tri[k]]);
        values.push_back(abs_value[tri[k]]);
      }
      tri[k] = remap[tri[k]];
    }
  mesh->vertices.swap(vertices);
  mesh->triangles.swap(kept);
  cells->swap(kept_cells);
  result->max_abs_value = values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

// 4. Normals from grad f; the triangles oriented with them (one global decision by majority, so
// the case table's consistent orientation is kept); where grad f vanishes, the faces' normal.
void OrientWithTheGradient(const Model& model, TriangleMesh* mesh) {
  const size_t num_vertices = mesh->vertices.size();
  mesh->normals.assign(num_vertices, Vec::Zero());
  std::vector<Vec> face_sum(num_vertices, Vec::Zero());
  for (size_t v = 0; v < num_vertices; ++v) {
    const Vec g = model.Gradient(mesh->vertices[v]);
    const double n = g.norm();
    if (std::isfinite(n) && n > 0) mesh->normals[v] = g / n;
  }
  long agree = 0, disagree = 0;
  for (const Eigen::Vector3i& t : mesh->triangles) {
    const Vec& p0 = mesh->vertices[t[0]];
    const Vec cross = (mesh->vertices[t[1]] - p0).cross(mesh->vertices[t[2]] - p0);
    const double s = cross.dot(mesh->normals[t[0]] + mesh->normals[t[1]] + mesh->normals[t[2]]);
    if (s > 0) ++agree;
    if (s < 0) ++disagree;
  }
  const bool flip = disagree > agree;
  for (Eigen::Vector3i& t : mesh->triangles) {
    if (flip) std::swap(t[1], t[2]);
    const Vec& p0 = mesh->vertices[t[0]];
    const Vec cross = (mesh->vertices[t[1]] - p0).cross(mesh->vertices[t[2]] - p0);
    for (int k = 0; k < 3; ++k) face_sum[t[k]] += cross;
  }
  for (size_t v = 0; v < num_vertices; ++v)
    if (mesh->normals[v].isZero()) {
      const double n = face_sum[v].norm();
      mesh->normals[v] = n > 0 ? Vec(face_sum[v] / n) : Vec(0, 0, 1);
    }
}

}  // namespace

MeshResult MeshModel(const Model& model, const MeshOptions& options) {
  MeshResult result;
  const auto step = [&](const std::string& what) {
    if (options.on_step) options.on_step(what);
  };
  Grid grid = SampleGrid(model, options, &result);
  step("grid " + std::to_string(grid.n[0]) + "x" + std::to_string(grid.n[1]) + "x" +
       std::to_string(grid.n[2]) + " sampled");
  const vtkSmartPointer<vtkPolyData> poly = ContourInIndexSpace(&grid);
  step("contoured: " + std::to_string(poly->GetNumberOfPoints()) + " vertices");
  std::vector<double> abs_value;
  PlaceVerticesOnRoots(model, grid, poly, options.num_threads, &result.mesh, &abs_value);
  step("vertices on the zero set");
  result.max_abs_value =
      abs_value.empty() ? 0.0 : *std::max_element(abs_value.begin(), abs_value.end());
  std::vector<Eigen::Vector3i> triangle_cells;  // the grid cell of each triangle (step 5)
  CollectTriangles(poly, grid, &result.mesh, &triangle_cells);
  if (options.drop_jumps)
    DropJumpTriangles(grid.h, abs_value, &result.mesh, &triangle_cells, &result);
  OrientWithTheGradient(model, &result.mesh);
  if (options.sharp_features) {  // 5.
    SharpFeatureOptions sharp;
    sharp.feature_angle_deg = options.feature_angle_deg;
    const SharpFeatureStats stats =
        InsertSharpFeatures(model, grid.origin, grid.h, triangle_cells, &result.mesh, sharp);
    result.feature_points = stats.feature_points;
    result.feature_flips = stats.flips;
    result.max_feature_distance = stats.max_distance;
    step("sharp features: " + std::to_string(stats.feature_points) + " points");
  }
  return result;
}

void WriteMeshPlyFile(const TriangleMesh& mesh, const std::string& path) {
  if (mesh.normals.size() != mesh.vertices.size())
    throw std::invalid_argument("WriteMeshPlyFile: normals do not match the vertices");
  std::string out = "ply\nformat binary_little_endian 1.0\ncomment written by implicitfit mesh\n";
  out += "element vertex " + std::to_string(mesh.vertices.size()) + "\n";
  for (const char* name : {"x", "y", "z", "nx", "ny", "nz"})
    out += std::string("property double ") + name + "\n";
  out += "element face " + std::to_string(mesh.triangles.size()) + "\n";
  out += "property list uchar int vertex_indices\nend_header\n";
  const std::uint16_t one = 1;
  std::uint8_t first;
  std::memcpy(&first, &one, 1);
  const bool swap = first != 1;
  auto append = [&](const void* data, size_t size) {
    char bytes[8];
    std::memcpy(bytes, data, size);
    if (swap) std::reverse(bytes, bytes + size);
    out.append(bytes, size);
  };
  out.reserve(out.size() + mesh.vertices.size() * 48 + mesh.triangles.size() * 13);
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    for (int k = 0; k < 3; ++k) {
      const double x = mesh.vertices[v][k];
      if (!std::isfinite(x))
        throw std::invalid_argument("WriteMeshPlyFile: vertex " + std::to_string(v) +
                                    " is not finite");
      append(&x, 8);
    }
    for (int k = 0; k < 3; ++k) append(&mesh.normals[v][k], 8);
  }
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const std::uint8_t three = 3;
    out.push_back(static_cast<char>(three));
    for (int k = 0; k < 3; ++k) {
      const std::int32_t i = t[k];
      append(&i, 4);
    }
  }
  WriteFileAtomically(path, out);
}

}  // namespace implicitfit
