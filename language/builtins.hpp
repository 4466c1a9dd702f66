// POV-Ray's built-in functions (sin, vrotate, str, rand ...), by name.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "language/random_stream.hpp"
#include "language/value.hpp"
#include "runtime/time/interval.hpp"

namespace hexant::language {

// Streams made by seed() and drawn by rand().
struct RandomStreams {
    std::vector<RandomStream> streams;
};

// Calls the function `name` on `args`; throws ValueError for wrong counts
// or types.
Value call_builtin(const std::string& name, const std::vector<Value>& args, RandomStreams& random);

// Where vnormalize(args) has a zero-length argument over `time`: the first
// instant found (POV-Ray gives <0, 0, 0> there, with a warning), or none.
std::optional<double> vnormalize_zero_at(const std::vector<Value>& args,
                                         const runtime::Interval& time);

// POV-Ray's str(value, length, precision) formatting.
std::string format_number(double value, int length, int precision);

}  // namespace hexant::language
