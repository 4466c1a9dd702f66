// POV-Ray's string functions (str, vstr, concat, chr, substr, strlen, val
// ...) on arguments that depend on `clock`. Each needs concrete arguments,
// so time is split into the pieces where every argument keeps what the
// function reads of it (str()'s number to its precision, chr()'s code, a
// string's text), exactly (runtime::split_by_key), and the function is
// called once a piece. A string result becomes a TimedString; a number
// result a piecewise constant function of time, exact at every double.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "language/builtins.hpp"
#include "language/value.hpp"

namespace hexant::language {

// The result of `name(args)` over `domain` (closed intervals of time), or
// none when `name` is not one of these functions or no argument depends on
// clock (call_builtin then calls it as usual). Throws ValueError when the
// result would change more than `max_pieces` times.
std::optional<Value> call_over_time(const std::string& name, const std::vector<Value>& args,
                                    const std::vector<runtime::Interval>& domain,
                                    std::size_t max_pieces, RandomStreams& random);

// A function of time that is `values[i]` on `times[i]` (sorted, disjoint
// intervals), by comparisons of clock with the pieces' starts in a
// balanced tree: exact at every double of every piece.
TimeFunction piecewise_constant(const std::vector<runtime::Interval>& times,
                                const std::vector<double>& values);

}  // namespace hexant::language
