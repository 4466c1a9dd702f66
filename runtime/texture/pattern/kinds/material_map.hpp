// POV-Ray 3.7's material_map, `texture { material_map { TYPE "FILE"
// [once] [interpolate N] [map_type N] texture { } ... } }`: an image picks
// one of the textures at each point (its pixel's palette index, or red x
// 255), with no blend. Its syntax is its own: the grammar reads the image
// and the textures, the texture evaluator hands the image in Values::image
// and the textures' count in number[0]; the textures stand at 0, 1, ...
// in the texture's map.
#pragma once

#include <algorithm>

#include "runtime/texture/pattern/image_map.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct MaterialMap {
    static constexpr std::string_view keyword = "material_map";
    static constexpr Kind::Argument argument = Kind::Argument::Own;
    static constexpr bool frequency = false;
    static constexpr bool single_numbers = false;

    // The texture's place in the map: the image's number, taken modulo the
    // count only when above it, and the last texture when equal to it
    // (POV-Ray's material_map walks its list no further than its end).
    static double value(const glm::dvec3& p, const Values& v) {
        const int count = static_cast<int>(v.number[0]);
        if (v.image == nullptr || count < 1) return 0.0;
        int number = material_number(*v.image, p, v.hit ? v.hit->t : 0.0);
        if (number > count) number %= count;
        return std::min(number, count - 1);
    }
};

}  // namespace hexant::runtime::pattern::kinds
