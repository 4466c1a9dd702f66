// POV-Ray 3.7's density_file pattern, `density_file df3 "FILE" [interpolate
// N]`: the voxels of a .df3 file over the unit cube (density_file.hpp). Its
// syntax is its own: the grammar reads the file's name and the texture
// evaluator hands the voxels in Values::density_file.
#pragma once

#include "runtime/texture/pattern/density_file.hpp"
#include "runtime/texture/pattern/pattern_kind.hpp"

namespace hexant::runtime::pattern::kinds {

struct DensityFilePattern {
    static constexpr std::string_view keyword = "density_file";
    static constexpr Kind::Argument argument = Kind::Argument::Own;
    static constexpr bool single_numbers = false;
    static constexpr int kInterpolation = 0;
    // interpolate 0 (none), 1 (trilinear), 2 (tricubic): POV-Ray reads it
    // modulo 10, any other value as 2.
    static constexpr std::array settings = {
        Setting::of_integer("interpolate", kInterpolation, 0.0, 0, 1000000, false)};

    static double value(const glm::dvec3& p, const Values& v) {
        if (v.density_file == nullptr) return 0.0;
        return v.density_file->value(p, int(v.number[kInterpolation]));
    }
};

}  // namespace hexant::runtime::pattern::kinds
