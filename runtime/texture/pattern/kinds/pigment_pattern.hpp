// POV-Ray 3.7's pigment_pattern { PIGMENT }: the pigment's colour at the
// point, as a grey (pattern.cpp's pigment_pattern: Compute_Pigment, then
// Colour::greyscale: 0.297 red + 0.589 green + 0.114 blue, the channels in
// single precision, the weights in double, the sum rounded to single; no
// clamp: frequency and phase then wrap it as any pattern's value, and a
// grey of 1 stays 1 by their fmod of 1.00001). Filter and transmit are not
// read. The pigment lives in this pattern's space (it sees the point after
// this pattern's transforms and warps) and reads the same surface event
// (its own slope, uv_mapping). Its syntax is its own: the grammar reads
// the block (language/grammar/textures.hpp, pigment_pattern), the texture
// evaluator compiles the pigment and hands it in Values::pigment.
#pragma once

#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct PigmentPattern {
    static constexpr std::string_view keyword = "pigment_pattern";
    static constexpr Kind::Argument argument = Kind::Argument::Own;

    static double grey(const std::array<double, 5>& colour) {
        const auto r = static_cast<float>(colour[0]);
        const auto g = static_cast<float>(colour[1]);
        const auto b = static_cast<float>(colour[2]);
        return static_cast<float>(0.297 * r + 0.589 * g + 0.114 * b);
    }
    static double value(const glm::dvec3& p, const Values& v) {
        if (v.pigment == nullptr) return 0.0;
        static const Hit kNoSurface{};
        return grey(v.pigment->colour_at(p, v.hit ? *v.hit : kNoSurface));
    }
};

}  // namespace hexant::runtime::pattern::kinds
