// POV-Ray's min_extent(OBJECT) and max_extent(OBJECT): the corners of the
// box around an object as placed in the world (its transforms applied), the
// usual way to centre or align a text (shapes.inc's Center_Object,
// Align_Object). The box is the intelligent object's own (runtime's
// box_over), the tight box of its surface, where POV-Ray's is the box of
// its bounding boxes: the two agree for the shapes scenes centre (texts,
// boxes, spheres, moved and scaled); a turned object's box may be tighter
// here. An object without a finite extent (a plane) gives POV-Ray's
// +-BOUND_HUGE / 2.
#pragma once

#include "language/value.hpp"
#include "runtime/objects/object.hpp"
#include "runtime/time/interval.hpp"

namespace hexant::language {

// The corner (`max`: the upper one) of the box around `object` over the
// animation's time `time`: a constant vector, or, for an object whose
// parts only appear and vanish with clock (a text of str(clock), objects
// under #if on clock), a vector that is piecewise constant in time, at most
// `max_pieces` pieces. Throws ValueError for an object whose shape or
// transforms move with clock (its box would be a function of time that
// hexant does not form yet), or that has no surface at some instant.
// Whether the object's shape, transforms or parts (their lifetimes) change
// anywhere over `time`.
bool changes_with_clock(const runtime::ObjectRecord& object, const runtime::Interval& time);

Value object_extent(const runtime::ObjectRecord& object, bool max, const runtime::Interval& time,
                    std::size_t max_pieces);

}  // namespace hexant::language
