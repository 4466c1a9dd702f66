// POV-Ray's `spline { ... }`: keys (t, value) and one of four interpolation
// kinds, evaluated exactly as POV-Ray 3.7 evaluates them (see spline.cpp for
// the rules at the ends and between keys).
#pragma once

#include <array>
#include <vector>

namespace hexant::runtime {

using Vector5 = std::array<double, 5>;

enum class SplineKind { Linear, Quadratic, Cubic, Natural };

class Spline {
  public:
    struct Key {
        double t;
        Vector5 value;
    };

    Spline(SplineKind kind, std::vector<Key> keys, int dimensions);

    SplineKind kind() const { return kind_; }
    const std::vector<Key>& keys() const { return keys_; }
    // How many components the values carry (1 for floats, 2..5 for vectors).
    int dimensions() const { return dimensions_; }

    // The spline's value at t, as POV-Ray computes S(t).
    Vector5 evaluate(double t) const;

  private:
    SplineKind kind_;
    std::vector<Key> keys_;  // sorted by t, as POV-Ray keeps them
    int dimensions_;
    // Second derivatives per key for natural splines, computed once.
    std::vector<Vector5> natural_second_derivatives_;
};

}  // namespace hexant::runtime
