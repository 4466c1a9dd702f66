// Animated GIF through giflib: each frame quantized to its own 256-colour
// map (giflib's median cut), looping forever, frame delay in hundredths of
// a second.
#pragma once

#include <filesystem>
#include <vector>

namespace hexant::tracer {

// A GIF's sides are 16-bit numbers.
inline constexpr int kGifMaxSide = 65535;

// `frames` are sRGB bytes, RGB, `width` x `height` each. Throws
// std::runtime_error with the reason.
void write_gif_animation(const std::filesystem::path& file, int width, int height,
                         const std::vector<std::vector<unsigned char>>& frames, double fps);

// The number of frames a GIF holds, each checked to be `width` x
// `height` and decoded whole; throws std::runtime_error with the reason.
int count_gif_frames(const std::filesystem::path& file, int width, int height);

}  // namespace hexant::tracer
