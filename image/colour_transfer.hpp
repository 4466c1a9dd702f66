// Colour transfer functions: how stored image values relate to linear
// light. sRGB's curve (IEC 61966-2-1) is the one POV-Ray 3.7 uses for
// `srgb` colours, `gamma srgb` image maps and its sRGB output files.
#pragma once

#include <cmath>

namespace hexant::image {

// sRGB-encoded value in [0, 1] -> linear light in [0, 1] (IEC 61966-2-1's
// decoding; values outside [0, 1] follow the same two pieces).
inline double srgb_decode(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Linear light in [0, 1] -> sRGB-encoded value in [0, 1] (the inverse of
// srgb_decode; the caller clamps).
inline double srgb_encode(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

}  // namespace hexant::image
