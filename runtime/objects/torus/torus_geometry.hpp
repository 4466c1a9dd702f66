// POV-Ray's torus { major, minor } in object space: the points at distance
// minor from the circle of radius major about the y axis in the x-z plane.
//
// Hits: part 0, normal outward (from the nearest point of the core circle);
// uv as POV-Ray's uv_mapping: u = 1 - (atan2(z, x) + pi) / 2pi around the y
// axis, v = (atan2(y, sqrt(x^2 + z^2) - major) + pi) / 2pi around the tube.
// inside: the closed solid tube. minor > major (a spindle torus) is the
// boundary of the union of the balls, without POV-Ray's inner lemon surface.
// major < 0 or minor <= 0 is an empty shape.
//
// Accuracy: no quartic solver. Roots are isolated along the ray on
// D(t) = (rho - major)^2 + y^2 - minor^2 (rho = distance from the y axis),
// which has the sign of the quartic but none of its cancellation for thin
// tori (the quartic is D times a positive factor). Pieces of the ray are
// halved, nearest first, and a piece is dropped only when an outward-rounded
// interval enclosure of D over it excludes zero, so no root is skipped;
// once D is provably monotone on a piece (its derivative's enclosure excludes
// zero), a sign change is polished by safeguarded Newton to full precision. A
// piece that stays undecided down to a few ulps is a tangency within
// rounding and counts as a hit where D <= 0. Origins are moved next to the
// torus first. Accuracy: s to a few ulps, hit points within a few ulps of
// max(|point|) of the surface, for radii from 1e-6 to 1e6 and origins 1e6
// away.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

struct TorusGeometry {
    double major = 1.0;
    double minor = 0.25;
};

std::optional<SurfaceHit> intersect(const TorusGeometry& torus, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const TorusGeometry& torus, glm::dvec3 p);
Box3 object_bounds(const TorusGeometry& torus);
bool surface_may_meet(const TorusGeometry& torus, const Box3& box);

}  // namespace hexant::runtime::geometry
