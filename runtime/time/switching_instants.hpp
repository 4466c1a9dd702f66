// Where a condition that depends on `clock` changes its truth: the
// switching instants of a branch (#if, #while, #switch on a function of
// time), found exactly.
//
// The range of the condition's point values over a piece of time
// (runtime/time/point_range.hpp: an interval evaluation whose sums and products
// round to nearest, the rest outward) decides the piece whole when it is
// all true (|c| > 1e-10, POV-Ray's truth) or all false; an undecided piece
// is halved, down to neighbouring doubles, where the point evaluator
// decides each instant. So a switch is placed between two neighbouring
// doubles, exactly where the double evaluation of the condition changes
// its answer: for a continuous condition the root of (left - right) to
// full precision, for a step (int, floor, mod, frame_number) its jump,
// with no sampling. The range holds the point evaluator's value for every
// t of the piece, so a piece decided whole is decided right at every
// double in it.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "runtime/time/interval.hpp"
#include "runtime/time/lifetime.hpp"
#include "runtime/time/limit_error.hpp"
#include "runtime/time/time_function.hpp"

namespace hexant::runtime {

struct TruthPieces {
    Lifetime when_true;
    Lifetime when_false;
    // Where the truth changes: the first double of each piece after the
    // first, within each interval of the domain.
    std::vector<double> instants;
};

// Splits `domain` (closed, finite intervals of time) by the truth of
// `condition`. Throws LimitError when the condition changes more than
// `max_pieces` times, or when pieces cannot be decided within a work
// budget proportional to it (a condition that flickers without end,
// sin(1 / (clock - 0.5)) > 0, or one the interval evaluation cannot
// resolve).
TruthPieces split_by_truth(const TimeFunction& condition, const std::vector<Interval>& domain,
                           std::size_t max_pieces);

// The pieces of `domain` over which a step function of time (the floor of
// an array index, frame_number) is constant, in order, each with its
// value; split as split_by_truth splits (where the interval evaluation is
// one number, the piece is decided). Throws LimitError likewise.
struct ValuePiece {
    Interval time;
    double value;
};
std::vector<ValuePiece> split_by_value(const TimeFunction& f, const std::vector<Interval>& domain,
                                       std::size_t max_pieces);

// The pieces of `domain` over which key(i, f_i(t)) is the same for every
// function f_i: where a value that needs one concrete number (str()'s
// argument, formatted to its precision; chr()'s code) keeps its key. A
// piece is decided where, for each function, the two ends of its interval
// range have the same key; so each key must be monotone in the value (every
// value between two with the same key has it too: rounding to a precision,
// floor). The pieces are in order; any instant of a piece has the piece's
// keys. Throws LimitError as split_by_value does.
using KeyOf = std::function<std::string(std::size_t which, double value)>;
struct KeyPiece {
    Interval time;
};
std::vector<KeyPiece> split_by_key(const std::vector<TimeFunction>& functions,
                                   const std::vector<Interval>& domain, std::size_t max_pieces,
                                   const KeyOf& key);

}  // namespace hexant::runtime
