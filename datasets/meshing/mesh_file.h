// Triangle meshes from PLY files (what `mesh` and `reconstruct --mesh` write, or any PLY with a
// "face" element): the vertices through the cloud reader (datasets/clouds/ply_reader.h, with its
// checks; normals kept when every one is valid), the faces through PCL's PLY reader, polygons
// split into triangle fans. Errors: InputError "<file>: <problem>" (no faces, a face indexing
// past the vertices, a build without PCL).
#pragma once

#include <string>

#include "datasets/meshing/model_mesher.h"

namespace implicitfit {

// True when the PLY header declares a "face" element with at least one face (a mesh rather
// than a cloud). Throws InputError when the file cannot be read.
bool PlyHasFaces(const std::string& path);

TriangleMesh ReadMeshPlyFile(const std::string& path);

}  // namespace implicitfit
