// When something exists: a set of time intervals. An object, light or value
// made under a branch whose condition depends on `clock` exists only during
// the pieces of time where that branch holds (the interpreter's time
// domain, Interpreter::domain in language/interpreter_state.hpp); the tracer's bounds are empty
// outside them, so the spacetime hierarchy never holds the object there (Glassner 1988: a hierarchy
// in spacetime holds an object only where it exists).
//
// The pieces are closed intervals of doubles, sorted and disjoint. Two
// pieces that meet at neighbouring doubles (a branch that holds up to a and
// the other from next_up(a)) leave no double between them: every instant a
// ray can carry belongs to exactly one side of a switch.
#pragma once

#include <string>
#include <vector>

#include "runtime/time/interval.hpp"

namespace hexant::runtime {

class Lifetime {
  public:
    // Always: no restriction (the default, and what costs nothing).
    Lifetime() = default;
    static Lifetime always() { return {}; }
    // Exactly these pieces (sorted, merged where they overlap or touch at
    // neighbouring doubles; empty ones dropped). None: never.
    static Lifetime of(std::vector<Interval> pieces);
    static Lifetime never() { return of({}); }

    bool is_always() const { return always_; }
    bool is_never() const { return !always_ && pieces_.empty(); }
    // The pieces; only meaningful when !is_always().
    const std::vector<Interval>& pieces() const { return pieces_; }

    bool contains(double t) const;
    // Does it hold every instant of t? Some instant of t?
    bool holds_all(const Interval& t) const;
    bool meets(const Interval& t) const;

    // Both at once.
    Lifetime intersect(const Lifetime& other) const;
    // The pieces of `range` (a finite interval) it holds, as intervals: the
    // whole range when always.
    std::vector<Interval> within(const Interval& range) const;
    // The instants of `range` it does not hold.
    Lifetime complement_within(const Interval& range) const;

    bool operator==(const Lifetime& other) const;
    // "always", "never" or "[0, 0.3137] u [0.5, 1]", for messages and dumps.
    std::string to_string() const;

  private:
    bool always_ = true;
    std::vector<Interval> pieces_;
};

}  // namespace hexant::runtime
