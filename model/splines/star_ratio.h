// Jensen's blending weights on a star-shaped polygonal domain (docs/maths.md JE-1), templated on
// the scalar so that Jets flow through the placement parameters.
//   tau(p): on the sector of edge i (the triangle centroid c, A_i, B_i), with E = B_i - A_i,
//     tau(p) = 1 - [E_u (c_v - p_v) - E_v (c_u - p_u)] / [E_u (c_v - A_v) - E_v (c_u - A_u)],
//   the paper's Cramer form: 1 - 1/lambda*, lambda* the ray parameter where the ray from c through
//   p meets the boundary; 1 at the centroid, 0 on the boundary, linear on each sector. Outside
//   the polygon it is clamped to 0 (the paper leaves it undefined there).
//   sigma(p) = 1/(4 eps^2) * integral of tau over the square [p_u - eps, p_u + eps] x [p_v - eps,
//   p_v + eps] (the paper omits the normalisation): exact, because tau is linear on each sector
//   triangle T_i and 0 outside: sigma = 1/(4 eps^2) sum_i area(T_i n Q) tau_i(centroid(T_i n Q)),
//   with T_i n Q the triangle clipped to the square (Sutherland-Hodgman). sigma is C^1 in p
//   (the box filter of a continuous function).
//   theta(p) = h(min(1, sigma(p) / band)), h(s) = 3 s^2 - 2 s^3: 0 where the filter square misses
//   the domain, 1 where sigma >= band (a closed set inside it), C^1 (h'(1) = 0). The paper's
//   theta = h_0(sigma) with the usual h_0(0) = 1 would be 1 on the boundary: reversed here.
// The polygon is given counter-clockwise and must be star-shaped about its vertex centroid
// (checked by StarDomainProblem).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <string>
#include <vector>

#include "model/scalar.h"

namespace implicitfit {

struct StarDomain {
  std::vector<Eigen::Vector2d> vertices;  // counter-clockwise
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();  // the vertices' mean
};

// "" when the polygon has >= 3 vertices, is counter-clockwise and every vertex is seen from the
// centroid strictly counter-clockwise after the previous one (star-shaped), else the problem.
std::string StarDomainProblem(const std::vector<Eigen::Vector2d>& vertices);
StarDomain MakeStarDomain(const std::vector<Eigen::Vector2d>& vertices);

// The sector (edge index) whose angular range from the centroid holds p.
int SectorOf(const StarDomain& d, double u, double v);

template <typename T>
T StarRatio(const StarDomain& d, const T& u, const T& v, bool clamp = true) {
  const int i = SectorOf(d, ValueOf(u), ValueOf(v));
  const Eigen::Vector2d& a = d.vertices[i];
  const Eigen::Vector2d& b = d.vertices[(i + 1) % d.vertices.size()];
  const double eu = b[0] - a[0], ev = b[1] - a[1];
  const double cu = d.centroid[0], cv = d.centroid[1];
  const T tau = 1.0 - (eu * (cv - v) - ev * (cu - u)) / (eu * (cv - a[1]) - ev * (cu - a[0]));
  if (clamp && ValueOf(tau) < 0.0) return T(0.0);
  return tau;
}

namespace star_ratio_internal {

template <typename T>
struct P2 {
  T u, v;
};

// Clips a convex polygon (counter-clockwise) to u >= lo (axis 0) / u <= hi / v >= lo / v <= hi.
template <typename T>
std::vector<P2<T>> Clip(const std::vector<P2<T>>& poly, int axis, const T& bound, bool keep_above) {
  std::vector<P2<T>> out;
  const size_t n = poly.size();
  auto coord = [axis](const P2<T>& p) -> const T& { return axis == 0 ? p.u : p.v; };
  auto inside = [&](const P2<T>& p) {
    return keep_above ? ValueOf(coord(p)) >= ValueOf(bound) : ValueOf(coord(p)) <= ValueOf(bound);
  };
  for (size_t k = 0; k < n; ++k) {
    const P2<T>& p = poly[k];
    const P2<T>& q = poly[(k + 1) % n];
    const bool pin = inside(p), qin = inside(q);
    if (pin) out.push_back(p);
    if (pin != qin) {
      const T s = (bound - coord(p)) / (coord(q) - coord(p));
      out.push_back({p.u + s * (q.u - p.u), p.v + s * (q.v - p.v)});
    }
  }
  return out;
}

}  // namespace star_ratio_internal

// sigma(p) of the header, with filter half-width eps > 0.
template <typename T>
T SmoothedStarRatio(const StarDomain& d, const T& u, const T& v, double eps) {
  using star_ratio_internal::P2;
  const T lo_u = u - eps, hi_u = u + eps, lo_v = v - eps, hi_v = v + eps;
  T total = T(0.0);
  const size_t m = d.vertices.size();
  for (size_t i = 0; i < m; ++i) {
    const Eigen::Vector2d& a = d.vertices[i];
    const Eigen::Vector2d& b = d.vertices[(i + 1) % m];
    // Quick reject: the triangle's box misses the square.
    const double tu0 = std::min({d.centroid[0], a[0], b[0]}), tu1 = std::max({d.centroid[0], a[0], b[0]});
    const double tv0 = std::min({d.centroid[1], a[1], b[1]}), tv1 = std::max({d.centroid[1], a[1], b[1]});
    if (tu1 <= ValueOf(lo_u) || tu0 >= ValueOf(hi_u) || tv1 <= ValueOf(lo_v) || tv0 >= ValueOf(hi_v))
      continue;
    std::vector<P2<T>> poly = {{T(d.centroid[0]), T(d.centroid[1])}, {T(a[0]), T(a[1])},
                               {T(b[0]), T(b[1])}};
    poly = star_ratio_internal::Clip(poly, 0, lo_u, true);
    if (poly.size() >= 3) poly = star_ratio_internal::Clip(poly, 0, hi_u, false);
    if (poly.size() >= 3) poly = star_ratio_internal::Clip(poly, 1, lo_v, true);
    if (poly.size() >= 3) poly = star_ratio_internal::Clip(poly, 1, hi_v, false);
    if (poly.size() < 3) continue;
    T area2 = T(0.0), cu = T(0.0), cv = T(0.0);  // shoelace: twice the area, centroid sums
    for (size_t k = 0; k < poly.size(); ++k) {
      const P2<T>& p = poly[k];
      const P2<T>& q = poly[(k + 1) % poly.size()];
      const T cross = p.u * q.v - q.u * p.v;
      area2 += cross;
      cu += (p.u + q.u) * cross;
      cv += (p.v + q.v) * cross;
    }
    if (!(ValueOf(area2) > 0.0)) continue;
    cu /= 3.0 * area2;
    cv /= 3.0 * area2;
    // tau_i at the clipped polygon's centroid (the sector's linear form, unclamped inside T_i).
    const double eu = b[0] - a[0], ev = b[1] - a[1];
    const double cu0 = d.centroid[0], cv0 = d.centroid[1];
    const T tau = 1.0 - (eu * (cv0 - cv) - ev * (cu0 - cu)) / (eu * (cv0 - a[1]) - ev * (cu0 - a[0]));
    total += 0.5 * area2 * tau;
  }
  return total / (4.0 * eps * eps);
}

// theta(p) of the header.
template <typename T>
T BlendWeight(const StarDomain& d, const T& u, const T& v, double eps, double band) {
  const T sigma = SmoothedStarRatio(d, u, v, eps);
  if (!(ValueOf(sigma) > 0.0)) return T(0.0);
  if (ValueOf(sigma) >= band) return T(1.0);
  const T s = sigma / band;
  return s * s * (3.0 - 2.0 * s);
}

}  // namespace implicitfit
