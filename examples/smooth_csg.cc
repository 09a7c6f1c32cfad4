// Builds a smooth-CSG model (a box-like block: intersection of two slabs of planes, rounded by
// Li & Phillips blends, minus a cylindrical hole), evaluates f along a line and writes the
// model file. f < 0 inside, f > 0 outside, grad f outward.
//   smooth_csg [MODEL.json]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "implicitfit/implicitfit.h"

int main(int argc, char** argv) {
  using implicitfit::NodeType;
  implicitfit::Model model;
  // Planes: normal (3), offset d: f = n.x - d.
  const int top = model.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0.5}, "top");
  const int bottom = model.AddPrimitive(NodeType::kPlane, {0, 0, -1, 0.5}, "bottom");
  const int right = model.AddPrimitive(NodeType::kPlane, {1, 0, 0, 1.0}, "right");
  const int left = model.AddPrimitive(NodeType::kPlane, {-1, 0, 0, 1.0}, "left");
  // Cylinder: point (3), axis (3), radius.
  const int hole = model.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 0.25}, "hole");
  // Operators: children, delta, epsilon (0 < epsilon <= delta), order n of H_n (0 = sharp).
  const int block =
      model.AddOperator(NodeType::kIntersection, {top, bottom, right, left}, 0.2, 0.1, 3, "block");
  model.SetRoot(model.AddOperator(NodeType::kDifference, {block, hole}, 0.1, 0.05, 3, "part"));

  // Along a line through the block, beside the hole's axis (where grad f is undefined).
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i <= 12; ++i) line.emplace_back(-1.5 + 0.25 * i, 0.1, 0.2);
  std::printf("    x  f(x, 0.1, 0.2)  |grad f|\n");
  for (const Eigen::Vector3d& x : line) {
    double f = 0.0;
    const Eigen::Vector3d g = model.Gradient(x, &f);
    std::printf("%5.2f  %14.6f  %8.4f\n", x[0], f, g.norm());
  }
  if (argc > 1) {
    implicitfit::WriteModelFile(model, argv[1]);
    // Read back, the file gives the same function (node order may differ: compare values).
    const implicitfit::Model again = implicitfit::ReadModelFile(argv[1]);
    double largest_difference = 0.0;
    for (const Eigen::Vector3d& x : line)
      largest_difference = std::max(largest_difference, std::abs(again.Value(x) - model.Value(x)));
    std::printf("wrote %s (%zu parameters); read back, f differs by at most %g\n", argv[1],
                again.parameters().size(), largest_difference);
    if (largest_difference != 0.0) return 1;
  }
  return 0;
}
