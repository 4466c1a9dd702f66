// The formats hexant reads and writes through OpenImageIO, in its module
// loaded on first use (image/oiio_library.hpp): Targa, TIFF, Radiance HDR,
// PPM/PGM and BMP, as POV-Ray 3.7 reads them (source/base/image/*.cpp):
//   Targa and BMP: 8-bit, decoded as sRGB unless the scene says otherwise
//     (POV-Ray's default file gamma); an 8-bit gray Targa is an RGB image,
//     as POV-Ray keeps it.
//   PPM (P3, P6) and PGM (P2, P5), 8 or 16 bits: POV-Ray applies no gamma
//     unless the scene gives one (its readers: "may or may not be
//     gamma-encoded"): the values are taken as they are; a PGM is gray.
//   TIFF: as PPM, no gamma unless the scene gives one; POV-Ray reads it as
//     8-bit RGBA (16-bit samples "crunched to 8"), and so does hexant.
//   Radiance HDR: linear light.
// (IFF, Amiga ILBM, is not read: POV-Ray 3.7.0.10's iff.cpp fails on every
// file, its loop ending only at the end of the file with an error.)
// A colour-mapped Targa keeps its indices and map (read by hexant: OpenImageIO
// expands palettes), as POV-Ray keeps them for a height_field (index x 256)
// or use_index; a palette BMP or TIFF is read as its colours, its height
// field made from them (POV-Ray takes the indices there).
// Frames are written as Targa (uncompressed, +FT, and run-length, +FC),
// PPM (P6), BMP (24-bit), TIFF and Radiance HDR (RGBE), all 8-bit sRGB but
// HDR, which is linear.
#pragma once

#include "image/image_format.hpp"

namespace hexant::image {

extern const ImageFormat kTgaFormat;
extern const ImageFormat kTgaRleFormat;
extern const ImageFormat kTiffFormat;
extern const ImageFormat kHdrFormat;
extern const ImageFormat kPnmFormat;
extern const ImageFormat kBmpFormat;

}  // namespace hexant::image
