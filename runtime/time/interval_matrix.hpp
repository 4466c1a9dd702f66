// Affine maps as 3x4 matrices over a number type (double, Interval, Dual):
// world_i = m[i][0] p_0 + m[i][1] p_1 + m[i][2] p_2 + m[i][3].
//
// With Interval entries, a map encloses a family of maps, e.g. a moving
// object's placement over a time interval, and applying it to a box of
// points bounds every image of every point under every map of the family.
// The products and sums are always formed in the same order, whatever the
// number type, so an interval evaluation repeats the double evaluation's
// operations one by one and encloses its rounded result too.
#pragma once

#include <array>
#include <type_traits>

#include <glm/mat4x4.hpp>

#include "runtime/time/interval.hpp"

namespace hexant::runtime {

template <class Number>
struct AffineMap {
    Number m[3][4];

    static AffineMap identity() {
        AffineMap a;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 4; ++j) a.m[i][j] = Number(i == j ? 1.0 : 0.0);
        return a;
    }

    // The affine part of a glm matrix (column-major: M[column][row]); its
    // last row is assumed to be (0 0 0 1).
    static AffineMap from(const glm::dmat4& matrix) {
        AffineMap a;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 4; ++j) a.m[i][j] = Number(matrix[j][i]);
        return a;
    }

    // Converts entries, e.g. a double map to an interval one (exactly).
    template <class Other>
    static AffineMap from(const AffineMap<Other>& other) {
        AffineMap a;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 4; ++j) a.m[i][j] = Number(other.m[i][j]);
        return a;
    }

    // The image of a point (or, for intervals, of a box of points).
    template <class P>
    std::array<P, 3> apply(const std::array<P, 3>& p) const {
        std::array<P, 3> r;
        for (int i = 0; i < 3; ++i) {
            if constexpr (std::is_same_v<Number, double> && std::is_same_v<P, Interval>) {
                r[i] = sparse_dot(m[i][0], m[i][1], m[i][2], p);
                if (m[i][3] != 0.0) r[i] = r[i] + Interval(m[i][3]);
            } else {
                r[i] = P(m[i][0]) * p[0] + P(m[i][1]) * p[1] + P(m[i][2]) * p[2] + P(m[i][3]);
            }
        }
        return r;
    }

    // The image of a direction (the linear part only).
    template <class P>
    std::array<P, 3> apply_linear(const std::array<P, 3>& v) const {
        std::array<P, 3> r;
        for (int i = 0; i < 3; ++i)
            r[i] = P(m[i][0]) * v[0] + P(m[i][1]) * v[1] + P(m[i][2]) * v[2];
        return r;
    }

    IntervalBox apply(const glm::dvec3& p) const {
        return apply(IntervalBox{Interval(p.x), Interval(p.y), Interval(p.z)});
    }
};

// a * b: first b, then a.
template <class Number>
AffineMap<Number> operator*(const AffineMap<Number>& a, const AffineMap<Number>& b) {
    AffineMap<Number> r;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
        r.m[i][3] =
            a.m[i][0] * b.m[0][3] + a.m[i][1] * b.m[1][3] + a.m[i][2] * b.m[2][3] + a.m[i][3];
    }
    return r;
}

// glm's 4x4 form of a double map.
inline glm::dmat4 to_glm(const AffineMap<double>& a) {
    glm::dmat4 r(1.0);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) r[j][i] = a.m[i][j];
    return r;
}

// An enclosure of a family of affine maps, e.g. a placement over a time
// interval.
using IntervalAffine = AffineMap<Interval>;

}  // namespace hexant::runtime
