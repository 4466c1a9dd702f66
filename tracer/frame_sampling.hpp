// How a frame's pixels are sampled: uniformly (every pixel the same count)
// or adaptively to a target error, in rounds over bands of the frame.
//
// Adaptive sampling meets the frame's target in the least work: every
// pixel first takes RenderSettings::kFirstRoundSamples; each round then
// estimates every pixel's error from its blocks (block_estimate.hpp; the
// rate from its 16-pixel tile), and while the band's estimated RMSE is
// above the target, gives each pixel the count that brings the band to the
// target at the least total cost by one multiplier over the whole band
// (sample_allocation.hpp): a region whose error is cheap to lower takes
// more, a quiet or costly one less, so the band's error lands at the
// target, not below it in every tile. A band is as many whole rows of
// tiles as kBandPixels holds (a frame up to 640 x 400 is one band): its
// pixels' blocks are kept between rounds, ~200 bytes each.
//
// A sample's cost is counted, not timed, so that the rounds are the same
// on any thread count, in every run and every mode: the rays it traced
// (primary, shadow, reflected, refracted). Not its node or object tests:
// those depend on the hierarchy, which differs between modes and between
// renders of different spans of frames (a farm's windows), and the same
// frame must come out byte for byte the same from each. Every sum over
// pixels is taken in a fixed order (tile by tile, each tile's in its own
// order).
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "tracer/block_estimate.hpp"
#include "tracer/counters.hpp"
#include "tracer/frame_estimate.hpp"
#include "tracer/sample_allocation.hpp"
#include "tracer/sample_pattern.hpp"

namespace hexant::tracer {

struct FramePlan {
    int frame = 0;
    std::uint32_t sample_seed = 0;
    int width = 0, height = 0;
    bool estimate = false;  // estimate each pixel's error (2 or more jittered samples)
    bool adaptive = false;  // to target_error, `ceiling` at most
    int ceiling = 1;        // the samples per pixel (adaptive: at most)
    int first_round = 8;
    double target_error = 0.0;
};

inline constexpr std::size_t kBandPixels = std::size_t(1) << 18;
// A round aims under the target by this (in squared error): the estimate
// of pixels a round passed by is the one that kept them there, low more
// often than high, so the band's figure after the round runs under the
// truth (measured 0.78-0.97 in RMSE, docs/benchmarks.md).
inline constexpr double kAim = 0.9;
// The radius of the neighbourhood a pixel's need is averaged over (5 x 5):
// one pixel's estimate from 4 samples is one squared difference.
inline constexpr int kSmoothing = 2;
// The pixels a thread takes at a time in a round.
inline constexpr std::size_t kRun = 16;

// A sample's cost in counted work (see above).
inline double sample_work(const Counters& c) {
    return double(c.rays());
}

struct FrameSamplingResult {
    std::uint64_t samples = 0;
    int tiles_over_target = 0;  // tiles all at the ceiling in a band above the target
    int tiles = 0;
};

// Samples the frame. `trace(x, y, seed, index, count, state)` gives one
// sample's colour, `linear` takes a colour to linear light, `state()` the
// calling thread's ThreadState; `finish(x, y, blocks, squared)` is told
// each pixel's samples and estimated squared error once (from any
// thread); `progress(fraction, samples)` from one thread at a time.
template <class Trace, class Linear, class State, class Finish, class Progress>
FrameSamplingResult sample_frame(const FramePlan& plan, Trace&& trace, Linear&& linear,
                                 State&& state, Finish&& finish, Progress&& progress) {
    constexpr int kTile = FrameEstimate::kTile;
    const int tiles_x = (plan.width + kTile - 1) / kTile;
    const int tiles_y = (plan.height + kTile - 1) / kTile;
    const int rows_per_band =
        std::max<int>(1, static_cast<int>(kBandPixels / (std::size_t(plan.width) * kTile)));
    const int bands = (tiles_y + rows_per_band - 1) / rows_per_band;
    const double target_squared = plan.target_error * plan.target_error;
    FrameSamplingResult result;
    result.tiles = tiles_x * tiles_y;
    std::atomic<std::uint64_t> samples{0};
    std::mutex progress_mutex;
    double reported = 0.0;

    struct Tile {
        int x0, y0, width, pixels;
        std::size_t first;  // its first pixel in the band's arrays
    };
    for (int band = 0; band < bands; ++band) {
        std::vector<Tile> tiles;
        std::size_t count = 0;
        for (int ty = band * rows_per_band; ty < std::min(tiles_y, (band + 1) * rows_per_band);
             ++ty)
            for (int tx = 0; tx < tiles_x; ++tx) {
                const int x0 = tx * kTile, y0 = ty * kTile;
                const int w = std::min(plan.width, x0 + kTile) - x0;
                const int h = std::min(plan.height, y0 + kTile) - y0;
                tiles.push_back({x0, y0, w, w * h, count});
                count += std::size_t(w) * h;
            }
        std::vector<PixelBlocks> blocks(count);
        std::vector<double> work(count, 0.0), squared(plan.estimate ? count : 0, 0.0);
        std::vector<double> exponent(tiles.size(), 1.0), tile_squared(tiles.size(), 0.0);
        std::vector<int> goal(
            count, plan.adaptive ? std::min(plan.ceiling, plan.first_round) : plan.ceiling);
        const int tile_count = static_cast<int>(tiles.size());
        const auto each_tile = [&](auto&& body) {
            tbb::parallel_for(tbb::blocked_range<int>(0, tile_count, 1),
                              [&](const tbb::blocked_range<int>& range) {
                                  for (int t = range.begin(); t < range.end(); ++t) body(t);
                              });
        };
        // Samples every pixel of the band up to its goal, in runs of
        // kRun pixels (not whole tiles: a later round's work sits in a
        // few tiles' noisy pixels, and a tile to a thread would leave the
        // others idle). A pixel's samples and work are its own.
        const auto sample_round = [&] {
            std::uint64_t planned = 0;
            for (std::size_t i = 0; i < count; ++i)
                planned += std::uint64_t(std::max(0, goal[i] - blocks[i].count));
            std::atomic<std::uint64_t> taken_in_round{0};
            tbb::parallel_for(
                tbb::blocked_range<std::size_t>(0, count, kRun),
                [&](const tbb::blocked_range<std::size_t>& range) {
                    auto& s = state();
                    std::uint64_t taken = 0;
                    for (std::size_t at = range.begin(); at < range.end(); ++at) {
                        // (The tile holding pixel `at`: the last to start at or before it.)
                        const Tile& tile = *(std::upper_bound(tiles.begin(), tiles.end(), at,
                                                              [](std::size_t i, const Tile& t) {
                                                                  return i < t.first;
                                                              }) -
                                             1);
                        const int p = static_cast<int>(at - tile.first);
                        const int x = tile.x0 + p % tile.width, y = tile.y0 + p / tile.width;
                        PixelBlocks& b = blocks[at];
                        if (b.count >= goal[at]) continue;
                        const std::uint32_t seed = pixel_seed(plan.frame, x, y, plan.sample_seed);
                        const double before = sample_work(s.counters);
                        ++s.pixel_run;
                        for (int i = b.count; i < goal[at]; ++i) {
                            b.add(trace(x, y, seed, i, plan.ceiling, s));
                            ++taken;
                        }
                        work[at] += sample_work(s.counters) - before;
                    }
                    const std::uint64_t total = samples += taken;
                    const double fraction =
                        (band + double(taken_in_round += taken) /
                                    double(std::max<std::uint64_t>(1, planned))) /
                        bands;
                    const std::lock_guard<std::mutex> lock(progress_mutex);
                    if (fraction > reported) {
                        reported = fraction;
                        progress(fraction, total);
                    }
                });
        };
        // Each pixel's estimated squared error, its tile's rate and sum.
        const auto estimate_round = [&] {
            each_tile([&](int t) {
                const Tile& tile = tiles[std::size_t(t)];
                std::vector<BlockTerms> terms(std::size_t(tile.pixels));
                for (int p = 0; p < tile.pixels; ++p)
                    terms[std::size_t(p)] =
                        block_terms(blocks[tile.first + std::size_t(p)], linear);
                const double ratio = block_ratio(terms);
                exponent[std::size_t(t)] = error_exponent(ratio);
                double sum = 0.0;
                for (int p = 0; p < tile.pixels; ++p) {
                    const std::size_t at = tile.first + std::size_t(p);
                    squared[at] =
                        pixel_squared_error(terms[std::size_t(p)], blocks[at].count, ratio);
                    sum += squared[at];
                }
                tile_squared[std::size_t(t)] = sum;
            });
        };
        sample_round();
        bool over = false;
        while (plan.estimate) {
            estimate_round();
            double band_squared = 0.0;
            for (const double s : tile_squared) band_squared += s;
            band_squared /= double(count);
            if (!plan.adaptive || band_squared <= target_squared) break;
            if (std::all_of(blocks.begin(), blocks.end(),
                            [&](const PixelBlocks& b) { return b.count >= plan.ceiling; })) {
                over = true;  // (the ceiling reached above the target)
                break;
            }
            // What each pixel needs, from its estimate smoothed over its
            // neighbours in the tile at one count (v n^e), rescaled to the
            // tile's own sum.
            std::vector<PixelNeed> needs(count);
            each_tile([&](int t) {
                const Tile& tile = tiles[std::size_t(t)];
                const double e = exponent[std::size_t(t)];
                std::vector<double> scaled(std::size_t(tile.pixels));
                for (int p = 0; p < tile.pixels; ++p) {
                    const std::size_t at = tile.first + std::size_t(p);
                    scaled[std::size_t(p)] = squared[at] * std::pow(double(blocks[at].count), e);
                }
                const std::vector<double> smooth =
                    smooth_within(scaled, tile.width, tile.pixels / tile.width, kSmoothing);
                double sum = 0.0;
                for (int p = 0; p < tile.pixels; ++p) {
                    const std::size_t at = tile.first + std::size_t(p);
                    const int n = blocks[at].count;
                    needs[at] = {n, smooth[std::size_t(p)] / std::pow(double(n), e),
                                 std::max(1.0, work[at] / n), e};
                    sum += needs[at].squared;
                }
                if (sum > 0.0)
                    for (int p = 0; p < tile.pixels; ++p)
                        needs[tile.first + std::size_t(p)].squared *=
                            tile_squared[std::size_t(t)] / sum;
            });
            goal = allocate_samples(needs, plan.ceiling, kAim * target_squared);
            bool grows = false;
            for (std::size_t i = 0; i < count; ++i) grows = grows || goal[i] > blocks[i].count;
            if (!grows)  // (the model says enough, the estimate not: double)
                for (std::size_t i = 0; i < count; ++i)
                    goal[i] = std::min(plan.ceiling, 2 * blocks[i].count);
            sample_round();
        }
        for (std::size_t t = 0; t < tiles.size(); ++t) {
            const Tile& tile = tiles[t];
            bool all = true;
            for (int p = 0; p < tile.pixels; ++p) {
                const std::size_t at = tile.first + std::size_t(p);
                all = all && blocks[at].count >= plan.ceiling;
                finish(tile.x0 + p % tile.width, tile.y0 + p / tile.width, blocks[at],
                       plan.estimate ? squared[at] : 0.0);
            }
            if (over && all) ++result.tiles_over_target;
        }
    }
    result.samples = samples;
    return result;
}

}  // namespace hexant::tracer
