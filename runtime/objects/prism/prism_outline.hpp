// How POV-Ray 3.7 turns a prism's point list into spline segments: which
// points each segment is made of, where an outline closes, and when it
// refuses the prism or ignores it. Parse_Prism (parse.cpp) checks that the
// last outline closes (a linear one left open gets its first point
// appended, with a warning; any other kind left open is flagged degenerate,
// "Prism not closed. Ignoring it."), then Prism::Compute_Prism (prism.cpp)
// walks the points and throws "Too few points in prism." where a segment
// needs points past the end. Both compare points with POV-Ray's EPSILON
// (1e-10, per coordinate).
//
// The outlines, as the two walks read them:
//   linear     P[i] to P[i+1]; an outline closes at the point equal to its
//              first, and the next point starts the next outline;
//   quadratic  P[i], P[i+1], P[i+2], running from P[i+1] to P[i+2]; an
//              outline's first point steers only, its second is its start,
//              and it closes at the point equal to that start;
//   cubic      P[i] .. P[i+3], running from P[i+1] to P[i+2]; as quadratic,
//              and the point after the closing one steers the last segment;
//   bezier     four points a segment, P[4j] .. P[4j+3]; an outline closes
//              where a segment ends on its first point.
// The coefficients of each segment are the lathe's (lathe_polynomial).
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/objects/lathe/lathe_geometry.hpp"

namespace hexant::runtime::geometry {

// POV-Ray's four spline kinds are the lathe's.
using PrismSpline = LatheSpline;

struct PrismOutline {
    // Each segment's points, as indices into the list (2 used for linear, 3
    // for quadratic, 4 for cubic and bezier); a linear outline closed by
    // POV-Ray ends with a segment back to its first point.
    std::vector<std::array<std::size_t, 4>> segments;
    // Set when POV-Ray ignores the prism (it draws nothing, with a warning).
    bool ignored = false;
    // POV-Ray's error when it refuses the prism (while reading the scene);
    // then there are no segments.
    std::string error;
};

// The count rules Parse_Prism applies before reading the points (its
// messages); empty when the count is allowed.
std::string prism_count_error(PrismSpline spline, long long count);

PrismOutline prism_outline(PrismSpline spline, std::span<const glm::dvec2> points);

}  // namespace hexant::runtime::geometry
