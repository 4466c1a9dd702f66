// POV-Ray 3.7's object pattern, `object { OBJECT LIST_ENTRY, LIST_ENTRY }`
// (pattern.cpp's object_pattern): 1 where the point in pattern space is
// inside the object (Inside_Object), 0 outside; a blend list of 2 whose
// default is checker's (POV-Ray's Check_Default_Map), frequency 0. Its
// syntax is its own (language/grammar/textures.hpp, object_pattern); the
// inside test reaches the evaluator as the function in Values::function
// (language/scene_queries.hpp's InsideFunction, of x, y, z and time).
#pragma once

#include <cmath>

#include "runtime/texture/pattern/pattern_kind.hpp"
#include "runtime/time/user_function.hpp"

namespace hexant::runtime::pattern::kinds {

struct ObjectPattern {
    static constexpr std::string_view keyword = "object";
    // A block pattern (its list read by its own rule).
    static constexpr Kind::Argument argument = Kind::Argument::Colours;
    static constexpr int colours = 2;
    static constexpr bool frequency = false;
    static constexpr bool single_numbers = false;
    static constexpr std::array default_map = {MapEntry{0.0, {0, 0, 1, 0, 0}},
                                               MapEntry{1.0, {0, 1, 0, 0, 0}}};

    static double value(const glm::dvec3& p, const Values& v) {
        if (v.function == nullptr) return 0.0;
        return v.function->at(p, v.hit ? v.hit->t : 0.0) > 0.5 ? 1.0 : 0.0;
    }
};

}  // namespace hexant::runtime::pattern::kinds
