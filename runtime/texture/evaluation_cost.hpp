// How many pigments, normals and textures one point of a texture may
// evaluate at most: a blend takes the two map entries around the
// pattern's value, a block pattern (checker) one, `average` all of them,
// a layered texture each layer.
// A declared chain of maps sharing their entries (`#declare P = pigment {
// gradient x pigment_map { [0 P] [1 P] } }` written n times) is n records
// long but 2^n evaluations a point; the language refuses a texture past
// kMostEvaluations where the object using it is written, rather than
// rendering for ever (issue 45).
#pragma once

#include "runtime/texture/material.hpp"

namespace hexant::runtime {

// A million evaluations a point: a hundred times what the deepest maps of
// POV-Ray's distribution scenes ask, and still about a second a point.
inline constexpr double kMostEvaluations = 1e6;

// The count for `texture` (each shared entry counted by its address once,
// so the walk is linear in the records), at most about 1e300; chains of
// maps deeper than 10,000 count as past any limit (the evaluator would
// not follow them on a thread's stack either).
double evaluation_cost(const Texture& texture);

}  // namespace hexant::runtime
