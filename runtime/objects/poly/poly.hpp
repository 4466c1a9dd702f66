// POV-Ray's algebraic surfaces: the points where a polynomial in x, y, z
// is zero; the solid is where it is negative (POV-Ray's Poly::Inside and
// Quadric::Inside). Five keywords, one kind of surface:
//
//   quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }
//       A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J
//   cubic { <20 coefficients> }   quartic { <35 coefficients> }
//   poly { ORDER, <(ORDER+1)(ORDER+2)(ORDER+3)/6 coefficients> }
//   polynomial { ORDER, xyz(i, j, k): c, ... }   (terms left out are 0)
//
// Coefficients in POV-Ray's order (its poly.cpp): x^i y^j z^k for i from
// ORDER down to 0, j from ORDER - i down to 0, k from ORDER - i - j down
// to 0; for a cubic x^3, x^2 y, x^2 z, x^2, x y^2, ..., z, 1. Each may
// move with clock. ORDER is 2 to 15 here (POV-Ray allows 35; hexant's root
// solver, runtime/geometry/polynomial_roots.hpp, takes degree 16 at most).
// `sturm` is read as a flag and needs no switch. The surface has no finite
// extent of its own: bounded_by and clipped_by give it one (as in POV-Ray,
// where a poly's bounded_by is kept: runtime/objects/bounded_object.hpp).
// The cubic, quartic, poly and polynomial blocks have their own rule in the
// grammar (kOwnSyntax); the quadric's values are generic.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class PolyModel;
}  // namespace objects

// The largest order hexant reads.
inline constexpr int kMaxPolyOrder = 15;

// How many terms a polynomial of `order` in three variables has.
constexpr int poly_term_count(int order) {
    return (order + 1) * (order + 2) * (order + 3) / 6;
}
// The index of x^i y^j z^k among a polynomial of `order`'s terms in POV-Ray's
// order (i + j + k <= order).
int poly_term_index(int order, int i, int j, int k);

struct PolySurface {
    using Model = objects::PolyModel;

    int order = 0;
    std::vector<TimeFunction> coefficients;  // poly_term_count(order), POV-Ray's order

    std::optional<std::string> standalone_error() const {
        if (order < 2) return "a polynomial surface needs its order and coefficients";
        return std::nullopt;
    }
    template <class F>
    void parameters(F&& f) const {
        f("order", "order", objects::DescribedParameter{std::to_string(order)});
        f("coefficients", "coefficients", coefficients);
    }
};

struct Quadric : PolySurface {
    static constexpr std::string_view keyword = "quadric";
    static Quadric read(const objects::ShapeArguments& a);
};
struct Cubic : PolySurface {
    static constexpr std::string_view keyword = "cubic";
    static constexpr bool kOwnSyntax = true;
};
struct Quartic : PolySurface {
    static constexpr std::string_view keyword = "quartic";
    static constexpr bool kOwnSyntax = true;
};
struct Poly : PolySurface {
    static constexpr std::string_view keyword = "poly";
    static constexpr bool kOwnSyntax = true;
};
struct Polynomial : PolySurface {
    static constexpr std::string_view keyword = "polynomial";
    static constexpr bool kOwnSyntax = true;
};

}  // namespace hexant::runtime

#include "runtime/objects/poly/poly_model.hpp"
