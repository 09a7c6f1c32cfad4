// Separators of a fillet (concave, and since PC155 convex: below) for the separation of
// `reconstruct` (fit/reconstruct/csg_separation.h).
//
// A concave fillet is a torus that is a hole (its points' normals point into the tube): the
// material is outside the tube, in the corner between the two faces it joins (Fit4CAD PC124:
// the torus R = 9.05, r = 4 between a stem of radius 5.05 and a ball). That corner has the sign
// vector of the empty space around the part (outside the tube, outside both faces): no
// expression over the detected surfaces holds it, and a plane does not cut it out of that cell
// (it is a ring). Its material lies in the box of revolution of the fillet's contact circles:
// axial coordinate h = (x - c) . u between the lowest and highest h of the torus's points, radial
// distance rho = |(x - c) x u| between their smallest and largest rho (the rolling ball touches
// both faces on the circles that bound the points). The four bounds are added as separators:
// two planes across the axis and two coaxial cylinders, each moved outwards by `margin`; the
// separation keeps those it needs.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "fit/reconstruct/solid_bounding.h"
#include "model/model.h"

namespace implicitfit {

// A coaxial cylinder literal: f = |(x - point) x axis| - radius, material where f < 0.
struct CylinderLiteral {
  Eigen::Vector3d point = Eigen::Vector3d::Zero(), axis = Eigen::Vector3d::UnitZ();
  double radius = 1.0;
  Model ToModel(const std::string& name) const;  // a fixed cylinder node
};

struct FilletBounds {
  PlaneLiteral low, high;        // h above the lowest, below the highest
  CylinderLiteral inner, outer;  // rho below the smallest, below the largest
};

// The box of revolution of the points about the torus's axis (header); false when `torus` is
// not a one-node torus or there are fewer than 3 points.
bool FilletBoundsOf(const Model& torus, const std::vector<Eigen::Vector3d>& points, double margin,
                    FilletBounds* bounds);

// A convex fillet (a torus that is solid, a rounded edge: Fit4CAD PC155's slab rim) is joined
// tangentially by its faces, so near the contact circles the face points lie within the
// tolerance of the torus too and some are assigned to it: their (h, rho) overshoot the contact
// circle (a plane tangent at rho = R gains points down to rho = R - 0.08 in a 0.2% noise test),
// and the body under the face loses that ring. Here each point is replaced by the foot on the
// tube that its normal gives: rho = R + r w_rho, h = r w_h, w = the normal in the meridian
// plane, signed away from the centre circle; a face point (normal along the face's normal)
// maps onto the contact circle itself. Points whose normal leaves the meridian plane (its
// projection shorter than 0.5) are skipped; false when fewer than 3 remain.
bool FilletBoundsOf(const Model& torus, const std::vector<Eigen::Vector3d>& points,
                    const std::vector<Eigen::Vector3d>& normals, double margin,
                    FilletBounds* bounds);

}  // namespace implicitfit
