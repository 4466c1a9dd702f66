// The heights of `height_field { function W, H { F } }`, as POV-Ray 3.7
// makes them (parser_materials.cpp's Make_Pattern_Image, then
// imageutil.cpp's image_height_at): F is sampled at x = i / (W - 1),
// y = j / (H - 1), z = 0 into a 16-bit image (a float function into a grey
// one; a pigment's red, green and blue into a colour one, read back as
// their grey 0.297 r + 0.589 g + 0.114 b), each value clipped to [0, 1]
// and rounded to 1/65535 in single precision, and read back as
// height = (unsigned short)(value * 65535.0f). Image row j is POV-Ray's
// row j, so the grid's row z = 0 (the image's bottom) is y = 1.
#pragma once

#include <array>
#include <functional>
#include <memory>

#include "runtime/objects/height_field/height_field_data.hpp"

namespace hexant::runtime::objects {

// Throws HeightFieldError for a grid smaller than 2 x 2 or larger than
// kMaxFunctionGridSide on a side.
inline constexpr int kMaxFunctionGridSide = 16384;

std::shared_ptr<const HeightFieldData> heights_of_function(
    int width, int height, const std::function<double(double x, double y)>& value);
std::shared_ptr<const HeightFieldData> heights_of_pigment(
    int width, int height, const std::function<std::array<double, 3>(double x, double y)>& colour);

}  // namespace hexant::runtime::objects
