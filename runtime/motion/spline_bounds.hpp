// A spline's pieces as polynomials, for the two evaluators a Spline itself
// lacks: the range of a component over an interval of the parameter, and its
// derivative at a point.
//
// Each segment POV-Ray evaluates (see spline.cpp) is a polynomial of degree
// at most 3 in the segment's own parameter u = (p - t[i-1]) / h in [0, 1];
// outside the segments the value is held at a key. The coefficients are kept
// as intervals around the exact polynomial. A range is the hull over the
// pieces touched; on a segment, the cubic's exact range is found from its
// Bernstein coefficients on the monotone stretches between its critical
// points, then widened by a bound on the rounding of Spline::evaluate's own
// formula there, so that the range holds the doubles Spline::evaluate returns.
#pragma once

#include <array>
#include <vector>

#include "runtime/motion/spline.hpp"
#include "runtime/time/interval.hpp"

namespace hexant::runtime {

class SplineBounds {
  public:
    explicit SplineBounds(const Spline& spline);

    // Holds spline.evaluate(p)[component] for every p in `parameter`.
    Interval range(int component, const Interval& parameter) const;

    // d/dp of spline.evaluate(p)[component]: of the piece POV-Ray evaluates at
    // p (the left segment at a key), 0 where the value is held at a key.
    double derivative(int component, double parameter) const;

    // The range of a cubic c[0] + c[1] u + c[2] u^2 + c[3] u^3 with interval
    // coefficients over u in [u0, u1]: holds every value, and is exact up to
    // rounding (public for tests).
    static Interval cubic_range(const std::array<Interval, 4>& c, double u0, double u1);

  private:
    // What POV-Ray evaluates for parameters whose segment index is i (see
    // spline.cpp): a held value, or a polynomial over (t[i-1], t[i]).
    struct Piece {
        bool held = true;
        double value = 0.0;           // when held
        std::array<Interval, 4> c{};  // in u, when not held
        double rounding = 0.0;        // bound on Spline::evaluate's rounding error
        Interval whole{0.0};          // range over the whole segment, rounding included
    };

    std::vector<double> t_;                     // key parameters, sorted
    std::array<std::vector<Piece>, 5> pieces_;  // per component, index 0 .. n
};

}  // namespace hexant::runtime
