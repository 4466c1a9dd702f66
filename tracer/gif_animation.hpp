// Animated GIF through giflib: each frame quantized to its own 256-colour
// map (giflib's median cut), looping forever, frame delay in hundredths of
// a second.
#pragma once

#include <filesystem>
#include <vector>

namespace hexant::tracer {

// A GIF's sides are 16-bit numbers.
inline constexpr int kGifMaxSide = 65535;

// `frames` are sRGB bytes, RGB, `width` x `height` each, written to the
// open descriptor `fd` from its start (the caller keeps and closes it).
// Throws std::runtime_error with the reason.
void write_gif_animation(int fd, int width, int height,
                         const std::vector<std::vector<unsigned char>>& frames, double fps);

// The number of frames the GIF open at `fd` holds (read from its start;
// the caller keeps the descriptor), each checked to be `width` x `height`
// and decoded whole; throws std::runtime_error with the reason.
int count_gif_frames(int fd, int width, int height);

}  // namespace hexant::tracer
