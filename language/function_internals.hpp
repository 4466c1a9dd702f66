// functions.inc's internal functions, `function { internal(N) }` (POV-Ray
// 3.7's source/backend/vm/fnintern.cpp, POVFPU_TrapTable): each takes x, y,
// z and its own extra parameters. hexant builds those it has from its time
// operations, so they have interval and derivative evaluators like any
// user function; the others are named and refused where they are called.
#pragma once

#include <memory>

#include "runtime/time/user_function.hpp"

namespace hexant::language {

// Internal function N as a user function. Throws ValueError for an N that
// POV-Ray 3.7 does not have.
std::shared_ptr<const runtime::UserFunction> internal_function(int n);
// POV-Ray's noise with `generator` (taken & 3, as f_noise_generator does)
// as a function a user function calls (runtime/texture/pattern/noise_function.hpp).
std::shared_ptr<const runtime::PointFunction> noise_function(int generator);

}  // namespace hexant::language
