// Ground truth of the segmentation benchmarks, for tests and bench/ (never for detection):
//   Fit4CAD  NAME_implicit.txt lines "PrimitiveK :=[Kind, [coefficients]];" (Kind: Plane,
//            Sphere, Cylinder, Cone, Torus), in primitive order; the per-point labels come
//            with the .xyzl cloud (1-based primitive number; CloudFileInfo::labels).
//   PLY      one integer vertex property of an ASCII PLY file, e.g. CGAL's "segment_index"
//            (the cloud readers keep x y z and normals only).
// Both throw InputError naming the file (and the line) on any problem.
#pragma once

#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

std::vector<NodeType> ReadFit4CadKinds(const std::string& implicit_path);
// The same file's coefficients, one list per primitive (plane 4, quadrics 10, torus 35).
std::vector<std::vector<double>> ReadFit4CadCoefficients(const std::string& implicit_path);

std::vector<int> ReadPlyIntProperty(const std::string& path, const std::string& property);

}  // namespace implicitfit
