// POV-Ray's julia_fractal { <c> [quaternion | hypercomplex] [sqr | cube |
// reciprocal | exp | ln | sin | ... | atanh | pwr(X, Y)] [max_iteration N]
// [precision P] [slice <S>, D] modifiers }: the 3D slice slice . q = D of
// the 4D Julia set of q -> f(q) + c (runtime/objects/julia_fractal/
// julia_fractal_geometry.hpp). The object kind
// (runtime/objects/shape_kind.hpp); its block has its own rule in the
// grammar (kOwnSyntax), read by language/actions/julia_fractals.hpp.
//
// c, the slice and its distance, and pwr's exponent may be time functions;
// max_iteration and precision are numbers known while the scene is read.
// A quaternion takes only sqr and cube (POV-Ray's SetUp_Fractal).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "runtime/objects/julia_fractal/julia_iteration.hpp"
#include "runtime/objects/shape_kind.hpp"
#include "runtime/time/time_function.hpp"

namespace hexant::runtime {

namespace objects {
class JuliaFractalModel;
}  // namespace objects

struct JuliaFractal {
    static constexpr std::string_view keyword = "julia_fractal";
    static constexpr bool kOwnSyntax = true;
    using Model = objects::JuliaFractalModel;

    // POV-Ray's defaults (the Fractal constructor).
    std::array<TimeFunction, 4> parameter{1.0, 0.0, 0.0, 0.0};
    geometry::JuliaAlgebra algebra = geometry::JuliaAlgebra::quaternion;
    geometry::JuliaFunction function = geometry::JuliaFunction::sqr;
    std::array<TimeFunction, 2> exponent{0.0, 0.0};  // pwr(X, Y)
    int iterations = 20;
    double precision = 20.0;  // as written: the step is 1 / max(P, 1)
    std::array<TimeFunction, 4> slice{0.0, 0.0, 0.0, 1.0};
    TimeFunction slice_distance = 0.0;

    // The function's word, for messages ("sqr").
    static std::string_view function_word(geometry::JuliaFunction f);
    // Set when the algebra does not have the function (POV-Ray's
    // SetUp_Fractal refuses it).
    std::optional<std::string> algebra_error() const;

    template <class F>
    void parameters(F&& f) const {
        static constexpr const char* names[4] = {"c.x", "c.y", "c.z", "c.t"};
        static constexpr const char* slice_names[4] = {"slice.x", "slice.y", "slice.z", "slice.t"};
        f("algebra", "algebra",
          objects::DescribedParameter{std::string(algebra == geometry::JuliaAlgebra::quaternion
                                                      ? "quaternion"
                                                      : "hypercomplex") +
                                      " " + std::string(function_word(function))});
        for (int i = 0; i < 4; ++i) f(names[i], "julia parameter's component", parameter[i]);
        if (function == geometry::JuliaFunction::pwr) {
            f("pwr.x", "pwr's first exponent", exponent[0]);
            f("pwr.y", "pwr's second exponent", exponent[1]);
        }
        for (int i = 0; i < 4; ++i) f(slice_names[i], "slice's component", slice[i]);
        f("slice_distance", "slice's distance", slice_distance);
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/julia_fractal/julia_fractal_model.hpp"
