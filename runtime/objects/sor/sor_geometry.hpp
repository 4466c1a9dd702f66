// POV-Ray's sor { N, <P0>, ..., <PN-1> [open] } in object space: a surface
// of revolution about the y axis whose squared radius is, between the
// heights of P[i+1] and P[i+2], the cubic in y r^2 = A y^3 + B y^2 + C y + D
// through P[i+1].x^2 and P[i+2].x^2 with the slopes of r^2 from the
// neighbouring points (2 x1 (x2 - x0) / (y2 - y0) at P[i+1], likewise at
// P[i+2]): N - 3 segments, the first and last points only steering, as
// POV-Ray 3.7's Sor::Compute_Sor (sor.cpp) makes them, including its quirk
// of setting a coefficient below 1e-10 in magnitude to 0. Closed (not open):
// the base disc at the lowest height and the cap disc at the highest, each
// only when its squared radius exceeds POV-Ray's 1e-4 and only for rays
// whose |direction.y| (unit direction) exceeds 1e-10.
//
// Hits: part 0 the base (normal -y), 1 the cap (+y), 2 + i segment i
// (normal (x, -(r^2)'(y) / 2, z), outward). uv as POV-Ray's Sor::UVCoord:
// u = the angle about y from +x toward +z over 2pi; v on segment i =
// (i + (y - its lower height) / its height) / segments, on the base
// rho / base radius - 1 (in [-1, 0]), on the cap 2 - rho / cap radius (in
// [1, 2]). inside: the first segment (in order) whose heights hold y, and
// x^2 + z^2 <= its r^2(y): the closed solid, also when open (POV-Ray's).
// An empty shape (no hits) when a point is not finite or POV-Ray's rules
// fail (fewer than 4 points, a negative radius, heights of P[1] .. P[N-2]
// not increasing, P[i+2].y - P[i].y below 1e-10).
//
// Accuracy: along the ray (moved next to the object) each segment is a cubic
// in the ray parameter, solved by polynomial_roots over the stretch where the
// ray is within the segment's heights and radius: k to a few ulps of the
// coefficients' rounding.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

struct SorSegment {
    double a = 0.0, b = 0.0, c = 0.0, d = 0.0;  // r^2 = a y^3 + b y^2 + c y + d
    double y_lo = 0.0, y_hi = 0.0;              // P[i+1].y, P[i+2].y
    double r_hi = 0.0;                          // the largest radius (widened)

    double r2(double y) const { return ((a * y + b) * y + c) * y + d; }
    double r2_slope(double y) const { return (3.0 * a * y + 2.0 * b) * y + c; }
};

struct SorGeometry {
    std::vector<SorSegment> segments;
    double radius = 0.0;
    double height1 = 0.0, height2 = 0.0;
    double base_radius_squared = 0.0, cap_radius_squared = 0.0;
    bool open = false;
};

// The surface from its points (<r, y>); no segments when POV-Ray's rules fail.
SorGeometry make_sor(const std::vector<glm::dvec2>& points, bool open);

std::optional<SurfaceHit> intersect(const SorGeometry& sor, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const SorGeometry& sor, glm::dvec3 p);
Box3 object_bounds(const SorGeometry& sor);
bool surface_may_meet(const SorGeometry& sor, const Box3& box);

}  // namespace hexant::runtime::geometry
