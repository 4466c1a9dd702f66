// POV-Ray 3.7's function pattern, `function { EXPRESSION }` (pattern.cpp's
// FunctionPattern::EvaluateRaw): the user function of (x, y, z) at the
// point in pattern space, at the hit's time; a value above 1 wrapped by
// fmod(value, 1) (POV-Ray's rule: 1 itself and everything below, negative
// values too, pass unchanged to frequency, phase and the map). A value that
// is not finite reads as 0, so that no NaN reaches a colour. Its syntax is
// its own: the grammar reads the body as any user function's
// (language/grammar/textures.hpp, function_pattern), the texture evaluator
// hands its tape in Values::function.
#pragma once

#include <cmath>

#include "runtime/texture/pattern/pattern_kind.hpp"
#include "runtime/time/user_function.hpp"

namespace hexant::runtime::pattern::kinds {

struct FunctionPattern {
    static constexpr std::string_view keyword = "function";
    static constexpr Kind::Argument argument = Kind::Argument::Own;
    static constexpr bool single_numbers = false;

    static double value(const glm::dvec3& p, const Values& v) {
        if (v.function == nullptr) return 0.0;
        const double value = v.function->at(p, v.hit ? v.hit->t : 0.0);
        if (!std::isfinite(value)) return 0.0;
        return value > 1.0 ? std::fmod(value, 1.0) : value;
    }
};

}  // namespace hexant::runtime::pattern::kinds
