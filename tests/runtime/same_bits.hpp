// Bit-for-bit equality of evaluations that must agree exactly (a tape and
// the function it was compiled from, a line in clock and its tape): the
// same bits, or both NaN (whose payloads may differ).
#pragma once

#include <cmath>
#include <cstring>

#include "runtime/time/interval.hpp"

namespace hexant::test {

inline bool same_bits(double a, double b) {
    return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0;
}
inline bool same_bits(const runtime::Interval& a, const runtime::Interval& b) {
    return same_bits(a.lo, b.lo) && same_bits(a.hi, b.hi);
}

}  // namespace hexant::test
