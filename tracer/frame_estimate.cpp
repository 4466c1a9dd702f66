#include "tracer/frame_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hexant::tracer {

FrameEstimate estimate_frame(const std::vector<double>& squared, int width, int height) {
    if (width <= 0 || height <= 0 || squared.size() != static_cast<std::size_t>(width) * height)
        throw std::invalid_argument("estimate_frame: the squared errors do not fill the frame");
    constexpr int kTile = FrameEstimate::kTile;
    FrameEstimate out;
    double total = 0.0;
    std::vector<FrameEstimate::Tile> tiles;
    for (int ty = 0; ty < height; ty += kTile)
        for (int tx = 0; tx < width; tx += kTile) {
            double sum = 0.0;
            int count = 0;
            for (int y = ty; y < std::min(height, ty + kTile); ++y)
                for (int x = tx; x < std::min(width, tx + kTile); ++x) {
                    sum += squared[static_cast<std::size_t>(y) * width + x];
                    ++count;
                }
            total += sum;
            tiles.push_back({tx, ty, std::sqrt(sum / count)});
        }
    out.rmse = std::sqrt(total / (static_cast<double>(width) * height));
    std::stable_sort(
        tiles.begin(), tiles.end(),
        [](const FrameEstimate::Tile& a, const FrameEstimate::Tile& b) { return a.rmse > b.rmse; });
    tiles.resize(std::min<std::size_t>(tiles.size(), FrameEstimate::kWorst));
    out.worst = std::move(tiles);
    return out;
}

}  // namespace hexant::tracer
