// Branches whose condition depends on `clock` (#if, #elseif on a function
// of time): the interpreter splits the time it is reading for (its time
// domain, Interpreter::domain) into the pieces where the condition holds
// and where it does not (runtime/time/switching_instants.hpp), reads the branch
// that holds on each side with the domain restricted to it, and then makes
// what the sides changed piecewise in time:
//   - objects and lights made on a side exist only during its pieces
//     (ObjectRecord::lifetime, LightRecord::lifetime);
//   - a variable the sides set differently becomes `condition ? a : b`
//     for floats and vectors (exact at every double: the same condition,
//     evaluated the same way), and for objects a union of both, each
//     living on its own side;
//   - the rest of the scene is read once.
// This file holds the merging of the sides' variables; the splitting and
// the re-reading are Interpreter::split_time (interpreter_state.hpp).
#pragma once

#include <optional>
#include <string>

#include "language/value.hpp"
#include "runtime/time/lifetime.hpp"

namespace hexant::language {

// A function of time that is 1 where `when` holds and 0 elsewhere, exactly
// at every double (comparisons of clock with the pieces' ends, in a
// balanced tree of `|`). For #ifdef and defined() of a name declared part
// of the time.
TimeFunction indicator(const runtime::Lifetime& when);

// Are a and b the same value without looking inside (the same constant,
// the same node of a time function, the same shared object)? False when
// unsure.
bool same_value(const Value& a, const Value& b);

// `value` as it is during `when` only: an object (or a light) restricted to
// that lifetime; any other value unchanged.
Value during(const Value& value, const runtime::Lifetime& when);

// The variable `name` (as messages name it: "'V'") after a split on `condition`: `when_true` on the
// side where it held, `when_false` on the other (none: not defined there). Strings become a
// TimedString. Throws ValueError for a kind of value hexant cannot make piecewise in time (a
// texture, an array ...) where the sides differ.
std::optional<Value> merge_sides(const std::string& name, const TimeFunction& condition,
                                 const std::optional<Value>& when_true,
                                 const runtime::Lifetime& true_pieces,
                                 const std::optional<Value>& when_false,
                                 const runtime::Lifetime& false_pieces);

}  // namespace hexant::language
