// A string that depends on `clock`: str(clock, 0, 2), concat("frame",
// str(frame_number, 0, 0)), or a name a branch on clock sets to two
// different strings. Its text on each piece of time; where one text is
// needed (an #include's file name), the interpreter splits time on it as on
// a condition (language/time_branch.hpp).
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "runtime/time/interval.hpp"
#include "runtime/time/lifetime.hpp"

namespace hexant::language {

struct TimedString {
    struct Piece {
        runtime::Interval time;  // closed, finite
        std::string text;
    };
    // In time order, disjoint; two pieces that meet (at neighbouring
    // doubles) have different texts.
    std::vector<Piece> pieces;

    // The longest text (string length limits).
    std::size_t longest() const;
    // Each distinct text with the time it holds, in order of first use.
    std::vector<std::pair<std::string, runtime::Lifetime>> by_text() const;
    // `"a" until clock 0.5, then "b"` (the first few pieces), for messages.
    std::string describe() const;
    bool operator==(const TimedString& other) const;
};

// Pieces in time order, disjoint, possibly with neighbours of one text:
// merged; one text over all of them is a plain std::string.
struct Value;
Value timed_string(std::vector<TimedString::Piece> pieces);

// The text pieces of a string value (a plain string: one piece per
// interval of `when`), restricted to `when`.
std::vector<TimedString::Piece> string_pieces(const Value& value, const runtime::Lifetime& when,
                                              const runtime::Interval& animation);

}  // namespace hexant::language
