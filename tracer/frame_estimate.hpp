// A frame's error, estimated without a reference from its pixels' own
// samples (tracer/block_estimate.hpp: the variance between aligned blocks
// of each pixel's one scrambled sequence, scaled by the rate its tile
// shows). Monte Carlo noise only: a renderer's bias is not seen.
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
    // The photon map's part, which more samples do not lower (a frame's
    // photons are shot once): the RMSE over pixels of the photon
    // estimates their samples saw, each estimate's variance its photons'
    // terms squared. 0 without photons. Not in `rmse`, which is what
    // sampling can lower.
    double photon_rmse = 0.0;
};

// From `squared`: per pixel (rows top to bottom), the estimated squared
// error averaged over its three channels; width * height entries.
FrameEstimate estimate_frame(const std::vector<double>& squared, int width, int height);

}  // namespace hexant::tracer
