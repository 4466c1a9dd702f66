// GIF through giflib, read only, as POV-Ray 3.7's gif.cpp reads it: the
// first image of the file, its palette (the image's own, else the
// file's) and each pixel's index, the graphics control block's
// transparent index as alpha 0. A GIF says nothing of its encoding: read
// as sRGB unless the scene says otherwise. Also Fractint's POT files,
// which are GIFs holding 16-bit values (pot_from_gif). hexant writes
// animated GIFs of its own (tracer/gif_animation.hpp), not frames in GIF.
#pragma once

#include "image/image_format.hpp"

namespace hexant::image {

extern const ImageFormat kGifFormat;

// A POT file's 16-bit gray image from the GIF that holds it: the left half
// holds each value's high byte as a palette index, the right half its low
// byte; the palette is ignored and no gamma applies (POV-Ray's
// GIF::Read with IsPOTFile). Throws std::runtime_error when the GIF is not
// paletted or its width is odd.
StoredImage pot_from_gif(const StoredImage& gif);

}  // namespace hexant::image
