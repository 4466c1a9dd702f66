// Frames to files through OpenImageIO: PNG (and other 8-bit formats) in
// sRGB, EXR as linear float. Every file is written under a temporary name in
// its folder and renamed when complete, so a reader never sees half a frame
// and an interrupted run leaves the finished frames as they were.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tracer/image.hpp"

namespace hexant::tracer {

// The pattern's run of '#' replaced by the frame number, zero-padded to the
// run's length ("out/atom/frame_####.png", 7 -> "out/atom/frame_0007.png");
// a pattern without '#' is returned as it is.
std::string frame_path(const std::string& pattern, int frame);

// Throws std::runtime_error naming the file on failure.
void write_image(const Image& image, const std::filesystem::path& path);

// The frames as a grid read like a book: left to right, top to bottom;
// `columns` 0 chooses a full grid when one is nearly square (32 frames: 8
// by 4), else the smallest square grid.
Image contact_sheet(const std::vector<Image>& frames, int columns = 0);

// An animated file (GIF) of the frames at `fps`.
void write_animation(const std::vector<Image>& frames, const std::filesystem::path& path,
                     double fps = 24.0);

// Linear to sRGB, 8 bits.
unsigned char to_srgb8(double linear);

}  // namespace hexant::tracer
