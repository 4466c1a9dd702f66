// JPEG through libjpeg (libjpeg-turbo on Debian), read only: 8-bit
// baseline and progressive files, gray or colour (YCbCr, RGB), decoded to
// RGB as POV-Ray 3.7's jpeg.cpp decodes them. A JPEG says nothing of its
// encoding; it is read as sRGB unless the scene says otherwise, as POV-Ray
// does (W3C's recommendation). hexant does not write JPEG: its frames are
// checked to read back as written, which a lossy format cannot.
#pragma once

#include "image/image_format.hpp"

namespace hexant::image {

extern const ImageFormat kJpegFormat;

}  // namespace hexant::image
