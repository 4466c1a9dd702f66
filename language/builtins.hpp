// POV-Ray's built-in functions (sin, vrotate, str, rand ...), by name.
#pragma once

#include <string>
#include <vector>

#include "language/random_stream.hpp"
#include "language/value.hpp"

namespace hexant::language {

// Streams made by seed() and drawn by rand().
struct RandomStreams {
    std::vector<RandomStream> streams;
};

// Calls the function `name` on `args`; throws ValueError for wrong counts
// or types.
Value call_builtin(const std::string& name, const std::vector<Value>& args,
                   RandomStreams& random);

// POV-Ray's str(value, length, precision) formatting.
std::string format_number(double value, int length, int precision);

}  // namespace hexant::language
