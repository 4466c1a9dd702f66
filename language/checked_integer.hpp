// A scene's number used as an integer (an index, a size, a count, a width,
// a character code, a stream): one checked conversion for all of them.
// NaN, infinities and numbers outside [lo, hi] are a ValueError saying what
// the number was for; the rule that read it adds the file:line:col. Without
// it a NaN or 1e300 cast to int is undefined behaviour in C++ (a NaN index
// passed every range test written as `i < 0 || i >= n`).
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "language/value_ops.hpp"

namespace hexant::language {

// Bounds beyond 2^53 are not asked for: every integer up to there is a
// double, so the range test is exact and the cast that follows defined.
inline constexpr long long kMaxExactInteger = 9007199254740992LL;  // 2^53

// `what` names the number ("an array index", "str()'s length"). The value
// is truncated toward zero, as POV-Ray's (int) casts do; callers that
// floor (array indices) floor first.
inline long long checked_integer(double value, const std::string& what, long long lo,
                                 long long hi) {
    if (!(value >= static_cast<double>(lo) && value <= static_cast<double>(hi))) {
        char shown[64];
        std::snprintf(shown, sizeof shown, "%.17g", value);
        if (!std::isfinite(value))
            throw ValueError(what + " must be a finite number, not " + std::string(shown));
        if (lo == -kMaxExactInteger && hi == kMaxExactInteger)
            throw ValueError(what + " " + shown + " is out of range: beyond 2^53 in size");
        throw ValueError(what + " " + shown + " is out of range " + std::to_string(lo) + " to " +
                         std::to_string(hi));
    }
    return static_cast<long long>(value);
}

}  // namespace hexant::language
