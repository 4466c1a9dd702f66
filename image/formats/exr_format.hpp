// OpenEXR through the OpenEXR library: written as 32-bit float R, G, B in
// linear light (ZIP compression, lossless), read from any file with R, G
// and B channels (and A when it has one), half or float.
#pragma once

#include "image/image_format.hpp"

namespace hexant::image {

extern const ImageFormat kExrFormat;

}  // namespace hexant::image
