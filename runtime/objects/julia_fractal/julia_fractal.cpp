#include "runtime/objects/julia_fractal/julia_fractal.hpp"

#include <array>

namespace hexant::runtime {

std::string_view JuliaFractal::function_word(geometry::JuliaFunction f) {
    // fractal.h's STYPE order.
    static constexpr std::array<std::string_view, 18> words{
        "exp",   "ln",   "sin",   "asin", "cos",   "acos", "tan", "atan", "sinh",
        "asinh", "cosh", "acosh", "tanh", "atanh", "pwr",  "sqr", "cube", "reciprocal"};
    return words[static_cast<std::size_t>(f)];
}

// POV-Ray's SetUp_Fractal: "Illegal function: quaternion only supports sqr
// and cube"; the hypercomplex numbers take every function.
std::optional<std::string> JuliaFractal::algebra_error() const {
    if (algebra == geometry::JuliaAlgebra::quaternion && function != geometry::JuliaFunction::sqr &&
        function != geometry::JuliaFunction::cube)
        return "a quaternion julia_fractal takes only sqr and cube, not " +
               std::string(function_word(function)) + " (add hypercomplex for the others)";
    return std::nullopt;
}

}  // namespace hexant::runtime
