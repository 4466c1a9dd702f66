// Adaptive sampling's next round: how many samples each pixel of a band
// of the frame should have so that the band meets its target error in the
// least work (tracer/frame_sampling.hpp).
//
// Each pixel's squared error is modelled as falling from its estimate v at
// its count n as v (n / n')^e (block_estimate.hpp gives v, and e from its
// tile's rate), and each of its samples as costing t (work per sample,
// counted on its samples so far). Counts are powers of two: a scrambled
// net's error falls in steps there (block_estimate.hpp: 1.5 n samples
// lower it little more than n). Doubling pixel i then buys a fall
// v_i (1 - 2^-e) for t_i n_i of work; taking the steps of greatest fall per
// work first, until the band's predicted mean squared error is at the
// target, is the least work for it (each pixel's error is convex in its
// work; the Lagrangian optimum n' ~ (v n^e / t)^(1/(e+1)) on the powers of
// two; with e = 1, independent samples, the classic n' ~ sqrt(v / t)). So
// the noisy and cheap pixels take the most.
#pragma once

#include <vector>

namespace hexant::tracer {

struct PixelNeed {
    int count = 0;          // samples taken (>= 1)
    double squared = 0.0;   // estimated squared error at `count`
    double cost = 1.0;      // work per sample (> 0)
    double exponent = 1.0;  // e: the squared error falls as count^-e (> 0)
};

// The counts that bring the predicted mean squared error to at most
// `target_squared` in the least total work: each count a power-of-two
// multiple of its own (or the ceiling), at most 4 times it (the estimate
// after a round corrects the model before a pixel goes far); as far as
// those limits let when they cannot reach it; unchanged when the target is
// met. std::invalid_argument for a pixel without a sample or with a cost
// or exponent not positive.
std::vector<int> allocate_samples(const std::vector<PixelNeed>& pixels, int ceiling,
                                  double target_squared);

// `values` (a width x height block, rows top to bottom) averaged over each
// pixel's (2 radius + 1)^2 neighbours inside the block: a pixel's estimate
// is one squared difference, too noisy alone to place samples by.
std::vector<double> smooth_within(const std::vector<double>& values, int width, int height,
                                  int radius);

}  // namespace hexant::tracer
