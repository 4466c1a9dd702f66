// A frame's error, estimated without a reference from two independently
// scrambled halves of its samples (the "half buffers" of Cycles' and
// denoisers' variance estimates): with halves A and B of n/2 samples each,
// independent and alike, the frame (A + B) / 2 has variance E[(A - B)^2] / 4,
// so (A - B)^2 / 4 per pixel and channel is an unbiased estimate of its
// squared error (Monte Carlo noise only; a renderer's bias is not seen).
// Plain sample variance is biased for the stratified (quasi-random) samples
// hexant takes; two independent scrambles are not.
//
// Summed in a fixed order over a fixed grid of tiles, so that the figures
// do not depend on the thread count.
#pragma once

#include <vector>

namespace hexant::tracer {

struct FrameEstimate {
    static constexpr int kTile = 16;  // the tiles' side, in pixels
    // The frame's estimated RMSE in linear light, over pixels and channels.
    double rmse = 0.0;
    struct Tile {
        int x = 0, y = 0;  // its top left pixel
        double rmse = 0.0;
    };
    // The tiles of largest estimated RMSE, largest first (at most kWorst;
    // ties in grid order).
    static constexpr int kWorst = 3;
    std::vector<Tile> worst;
};

// From `squared`: per pixel (rows top to bottom), the estimated squared
// error averaged over its three channels; width * height entries.
FrameEstimate estimate_frame(const std::vector<double>& squared, int width, int height);

}  // namespace hexant::tracer
