// An image_map's file as POV-Ray 3.7 reads it (Parse_Image, and its PNG
// reader's gamma): the file's values decoded to linear light by the file's
// own transfer function (a PNG's sRGB or gAMA chunk; sRGB when it says
// nothing; linear for OpenEXR) or the scene's `gamma` for it, then encoded
// into the scene's working space (assumed_gamma), in single precision.
#pragma once

#include <optional>

#include "image/image_format.hpp"
#include "runtime/texture/pattern/image_map.hpp"

namespace hexant::language {

// How the scene says to decode the file: nothing (the file's own), a power
// `gamma G` (decoding: value^G), or `gamma srgb`.
struct ImageGamma {
    std::optional<double> power;
    bool srgb = false;
    // POV-Ray's kPOVList_GammaMode_AssumedGamma36 (a scene of a #version
    // below 3.7 that set assumed_gamma before): a file that does not say
    // its encoding is taken as encoded in the working space.
    bool legacy_default = false;
    // A bump_map's (POV-Ray reads it as a height_field's): the file's
    // values as they are unless the scene gave a gamma, no working space.
    bool undecoded = false;
};

// The pixels of `stored` (3 or 4 channels, rows top to bottom) in the
// working space of `assumed_gamma`: red, green, blue decoded and encoded,
// transmit 1 - alpha (alpha is not gamma-encoded).
runtime::pattern::ImagePixels image_pixels(const image::StoredImage& stored,
                                           const ImageGamma& gamma, double assumed_gamma);

}  // namespace hexant::language
