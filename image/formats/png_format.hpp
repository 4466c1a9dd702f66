// PNG through libpng: written as 8-bit sRGB RGB (with its sRGB chunk), read
// in any of PNG's colour types and depths (palette and gray expanded to
// RGB, 16-bit kept exact).
#pragma once

#include "image/image_format.hpp"

namespace hexant::image {

extern const ImageFormat kPngFormat;
// 16 bits a sample, sRGB-encoded, with an sRGB chunk (POV-Ray's +FN16); it
// takes linear floats.
extern const ImageFormat kPng16Format;

}  // namespace hexant::image
