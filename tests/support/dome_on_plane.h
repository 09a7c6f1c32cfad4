// Jensen's example as a test fixture (docs/maths.md JE-1): a dome (a cap of the unit hemisphere
// in azimuthal coordinates, over the square [-0.7, 0.7]^2) placed on the plane z = 0 (the
// root, over [-2, 2]^2) by one link (a, b, c, d, theta), band 0.5, filter 0.1.
#pragma once

#include <cmath>

#include "model/splines/patch_tree.h"

namespace testsupport {

inline implicitfit::PatchTree DomeOnPlane(double a = 0.3, double b = -0.2,
                                          double theta = 20.0 * M_PI / 180.0) {
  using implicitfit::PatchKind;
  implicitfit::PatchTree tree;
  implicitfit::ParametricPatch plane;
  plane.kind = PatchKind::kPlane;
  plane.p = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  plane.domain = implicitfit::MakeStarDomain({{-2, -2}, {2, -2}, {2, 2}, {-2, 2}});
  implicitfit::ParametricPatch dome;
  dome.kind = PatchKind::kDome;
  dome.p = {0, 0, 0, 1.0};
  dome.domain = implicitfit::MakeStarDomain({{-0.7, -0.7}, {0.7, -0.7}, {0.7, 0.7}, {-0.7, 0.7}});
  tree.patches = {plane, dome};
  implicitfit::PatchLink link;
  link.parent = 0;
  link.child = 1;
  link.band = 0.5;
  link.filter = 0.1;
  tree.links = {link};
  tree.placements = {a, b, 0.0, 0.0, theta};
  return tree;
}

}  // namespace testsupport
