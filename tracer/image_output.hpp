// Frames to files: PNG in 8- or 16-bit sRGB, EXR as linear float, Targa,
// TIFF, PPM, BMP (8-bit sRGB) and Radiance HDR (linear RGBE) through
// OpenImageIO (image_format.hpp), animations as GIF. Every file is written under a temporary name
// in its folder and renamed when complete, so a reader never sees half a frame and an interrupted
// run leaves the finished frames as they were.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "image/image_format.hpp"
#include "tracer/image.hpp"

namespace hexant::tracer {

using image::ImageFormat;

// The pattern's run of '#' replaced by the frame number, zero-padded to the
// run's length ("out/atom/frame_####.png", 7 -> "out/atom/frame_0007.png");
// a pattern without '#' is returned as it is.
std::string frame_path(const std::string& pattern, int frame);
// Throws std::runtime_error naming the pattern when it has more than one run
// of '#' (the second would stay in the name as it is), or none while
// `frames` is more than one (each would be written over the last); `flag`
// names the option in the message.
void check_frame_pattern(const std::string& pattern, std::size_t frames,
                         const std::string& flag = "-o");

// The format a frame's name asks for (its extension, and `variant`: see
// image::image_format_for); throws std::runtime_error naming the file when
// there is none, so that a command can refuse a name before it renders
// anything.
const ImageFormat& check_image_name(const std::filesystem::path& path,
                                    const std::string& variant = "");
// check_image_name, and also that an image of width x height fits the
// format's own limit (ImageFormat::max_side; PNG 10^6 a side): a frame too
// tall for its file is refused before it is rendered (issue 45).
void check_image_size(const std::filesystem::path& path, int width, int height,
                      const std::string& variant = "");
// The size of contact_sheet()'s grid of `frames` frames of width x height.
std::pair<int, int> contact_sheet_size(int frames, int width, int height, int columns = 0);
// Throws std::runtime_error naming the file unless it is a .gif.
void check_animation_name(const std::filesystem::path& path);

// The format is the name's extension and `variant` (image_format_for).
// Throws std::runtime_error naming the file on failure, or for a name of no
// format.
void write_image(const Image& image, const std::filesystem::path& path,
                 const std::string& variant = "");

// The frames as a grid read like a book: left to right, top to bottom;
// `columns` 0 chooses a full grid when one is nearly square (32 frames: 8
// by 4), else the smallest square grid.
Image contact_sheet(const std::vector<Image>& frames, int columns = 0);

// An animated GIF of the frames at `fps`; throws std::runtime_error naming
// the file for another name, frames of different sizes, or a failed write.
void write_animation(const std::vector<Image>& frames, const std::filesystem::path& path,
                     double fps = 24.0);

// A frame read back from a file hexant wrote (PNG, 8 or 16 bits, Targa,
// PPM, BMP, TIFF: sRGB decoded to linear, so that writing it again gives
// the same bytes; EXR, HDR: linear as stored);
// alpha, if any, dropped. std::runtime_error naming the file otherwise,
// image::ImageTooLarge (from its header, before any pixel is decoded) when
// it declares more than `max_pixels`.
Image read_image(const std::filesystem::path& path,
                 std::size_t max_pixels = image::kMaxImagePixels);

// Linear to sRGB, 8 bits.
unsigned char to_srgb8(double linear);

}  // namespace hexant::tracer
