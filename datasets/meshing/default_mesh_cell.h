// The mesher's default grid spacing (model_mesher.h, MeshOptions::cell = 0), from the model.
//   - longest box side / 100 for every model, except:
//   - a Bernstein mesh with sharp (C0) faces (a patch-mesh fit that found creases,
//     docs/patch-mesh.md): the fit rounds each crease over about one finest leaf, edge
//     u = h / 2^max_level, and extended marching cubes (sharp_features.h) restores a crease only
//     where one grid cell spans the rounding (the grad f normals of the cell's patch spread by
//     more than the feature angle). The cell is u / 2, no coarser than longest / 64 (the chord
//     error of the smooth faces). Measured on the CAD-like solids of bench/surface_comparison at
//     two levels, against u / 4 (the benchmark's cell before): Chamfer 4-9% lower, the Fit4CAD
//     parts 0.1-1.2% higher (bench/RESULTS.md, "Mesh cell from the leaves").
// With several Bernstein meshes with creases, the finest of them sets the cell.
#pragma once

#include "model/model.h"

namespace implicitfit {

// `longest`: the longest side of the box to mesh (> 0).
double DefaultMeshCell(const Model& model, double longest);

}  // namespace implicitfit
