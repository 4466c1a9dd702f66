// Where a time function is NaN or infinite over an animation's time: the
// check behind "a radius of sqrt(-1) is an error", for parameters that
// depend on `clock` as well as for numbers.
//
// By interval evaluation (time_tape.hpp) and bisection: an interval of
// times over which the function is bounded, and no operation leaves its
// domain (interval.hpp clamps arguments into the domain, so a bounded
// interval alone would not show sqrt of a negative), holds no such instant.
// Any other interval is halved, the left half first, and each half's
// first instant evaluated at the point; an instant counts only when the
// point evaluation (the value the renderer computes there) is NaN or
// infinite. So an interval that merely could hold an infinity (1/(t - 0.3)
// near 0.3, where no double gives zero) is not an error.
#pragma once

#include <optional>

#include "runtime/time/time_function.hpp"

namespace hexant::runtime {

// The first instant found in [begin, end] at which f(t) is NaN or
// infinite, or none. At most a few thousand interval evaluations of f: a
// function suspect over a whole interval whose points stay finite (tan of
// a fast clock, near its poles) gives up and says none.
std::optional<double> first_non_finite(const TimeFunction& f, double begin, double end);

}  // namespace hexant::runtime
