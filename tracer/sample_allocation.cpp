#include "tracer/sample_allocation.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <stdexcept>

namespace hexant::tracer {

namespace {

// A round multiplies a pixel's count by at most this: the estimate after
// it corrects the model before a pixel goes far on a few samples' word.
constexpr int kMaxGrowth = 4;

// A pixel's next step: from its count to twice it (or to the ceiling, the
// last step when that is not a power of two), and what that step buys:
// the fall in its predicted squared error per unit of work it costs.
struct Step {
    double gain;
    std::size_t pixel;
    bool operator<(const Step& o) const {
        // (Ties go to the earlier pixel: the same choice on every run.)
        return gain != o.gain ? gain < o.gain : pixel > o.pixel;
    }
};

}  // namespace

std::vector<int> allocate_samples(const std::vector<PixelNeed>& pixels, int ceiling,
                                  double target_squared) {
    if (ceiling < 1) throw std::invalid_argument("allocate_samples: a ceiling of 1 or more");
    for (const PixelNeed& p : pixels)
        if (!(p.exponent > 0.0) || !(p.cost > 0.0) || p.count < 1)
            throw std::invalid_argument(
                "allocate_samples: each pixel needs a sample, a positive cost and exponent");
    std::vector<int> counts(pixels.size());
    std::vector<double> error(pixels.size());  // predicted at counts[i]
    double total = 0.0;
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        counts[i] = pixels[i].count;
        error[i] = std::max(0.0, pixels[i].squared);
        total += error[i];
    }
    const double wanted = target_squared * double(pixels.size());
    const auto limit = [&](std::size_t i) {
        return std::min(ceiling, kMaxGrowth * pixels[i].count);
    };
    const auto next = [&](std::size_t i) { return std::min(2 * counts[i], limit(i)); };
    const auto step_of = [&](std::size_t i) {
        const int to = next(i);
        const double after = error[i] * std::pow(double(counts[i]) / to, pixels[i].exponent);
        return Step{(error[i] - after) / (pixels[i].cost * double(to - counts[i])), i};
    };
    // Greedy by gain per work: each pixel's predicted error falls convexly
    // in its work, so taking the best step first is the least work to any
    // total the steps reach (the Lagrangian optimum on the powers of two).
    std::priority_queue<Step> steps;
    for (std::size_t i = 0; i < pixels.size(); ++i)
        if (error[i] > 0.0 && counts[i] < limit(i)) steps.push(step_of(i));
    while (total > wanted && !steps.empty()) {
        const std::size_t i = steps.top().pixel;
        steps.pop();
        const int to = next(i);
        const double after = error[i] * std::pow(double(counts[i]) / to, pixels[i].exponent);
        total -= error[i] - after;
        error[i] = after;
        counts[i] = to;
        if (counts[i] < limit(i)) steps.push(step_of(i));
    }
    return counts;
}

std::vector<double> smooth_within(const std::vector<double>& values, int width, int height,
                                  int radius) {
    if (width <= 0 || height <= 0 || radius < 0 || values.size() != std::size_t(width) * height)
        throw std::invalid_argument("smooth_within: the values do not fill the block");
    std::vector<double> out(values.size(), 0.0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double sum = 0.0;
            int n = 0;
            for (int v = std::max(0, y - radius); v <= std::min(height - 1, y + radius); ++v)
                for (int u = std::max(0, x - radius); u <= std::min(width - 1, x + radius); ++u) {
                    sum += values[std::size_t(v) * width + u];
                    ++n;
                }
            out[std::size_t(y) * width + x] = sum / n;
        }
    return out;
}

}  // namespace hexant::tracer
