#include "tracer/radiosity_pretrace.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "tracer/sample_pattern.hpp"

namespace hexant::tracer {

namespace {

constexpr int kTile = 32;  // POV-Ray's default render block size
constexpr int kMostPasses = 32;

// A reproducible jitter in [-1, 1) for the k-th ray of a tile's pass.
// POV-Ray seeds its jitter by pass and tile alike, not by frame: where
// nothing moves, every frame's pretrace meets the same points and gathers
// the same samples, so a still part of an animation does not flicker.
double jitter_at(std::uint32_t pass, std::uint32_t tile, std::uint32_t k) {
    using sobol_detail::hash;
    const std::uint32_t h = hash(hash(pass * 17u + tile * 13u) ^ hash(k + 0x9e3779b9u));
    return h * (2.0 / 4294967296.0) - 1.0;
}

}  // namespace

std::vector<double> pretrace_sizes(const runtime::RadiositySettings& settings, int width,
                                   int height) {
    const double larger = std::max(width, height);
    const double start = larger * settings.pretrace_start;
    const double end = std::max(1.0, larger * settings.pretrace_end);
    // (View::StartRender's count, EPSILON 1e-10.)
    const int steps = std::min(
        kMostPasses,
        static_cast<int>(std::floor(std::log(start / end) / std::log(2.0) + (1.0 - 1e-10))) + 1);
    std::vector<double> sizes;
    for (int k = 0; k < steps; ++k) sizes.push_back(std::max(start * std::pow(0.5, k), end));
    return sizes;
}

void radiosity_pretrace(const runtime::RadiositySettings& settings, int width, int height,
                        RadiosityCache& cache,
                        const std::function<void(double, double, ThreadState&)>& trace,
                        const std::function<ThreadState&()>& state) {
    const int tiles_x = (width + kTile - 1) / kTile, tiles_y = (height + kTile - 1) / kTile;
    const int tiles = tiles_x * tiles_y;
    const std::vector<double> sizes = pretrace_sizes(settings, width, height);
    std::vector<std::vector<RadiosityRecord>> kept(static_cast<std::size_t>(tiles));
    for (std::size_t pass = 0; pass < sizes.size(); ++pass) {
        const double size = sizes[pass];
        const double jitter = std::min(1.0, size / 2.0);
        const double offset = (size - 1.0) / 2.0;
        tbb::parallel_for(0, tiles, 1, [&](int tile) {
            ThreadState& s = state();
            std::vector<RadiosityRecord>& records = kept[static_cast<std::size_t>(tile)];
            records.clear();
            s.radiosity.depth = 0;
            s.radiosity.pretrace = true;
            s.radiosity.kept = &records;
            const int left = (tile % tiles_x) * kTile, top = (tile / tiles_x) * kTile;
            const int right = std::min(width, left + kTile) - 1;
            const int bottom = std::min(height, top + kTile) - 1;
            const double start_x = std::ceil((left - 0.5) / size) * size;
            const double start_y = std::ceil((top - 0.5) / size) * size;
            std::uint32_t k = 0;
            for (double y = start_y; y < bottom + 0.5; y += size)
                for (double x = start_x; x < right + 0.5; x += size, k += 2) {
                    const double px = x + offset + jitter * jitter_at(std::uint32_t(pass), tile, k);
                    const double py =
                        y + offset + jitter * jitter_at(std::uint32_t(pass), tile, k + 1);
                    // (The point within the image, a pixel's centre at +0.5.)
                    trace(std::clamp(px + 0.5, 0.0, width - 1e-9),
                          std::clamp(py + 0.5, 0.0, height - 1e-9), s);
                }
            s.radiosity.pretrace = false;
            s.radiosity.kept = nullptr;
        });
        std::vector<RadiosityRecord> pass_records;
        for (const auto& records : kept)
            pass_records.insert(pass_records.end(), records.begin(), records.end());
        cache.add(pass_records);
    }
}

}  // namespace hexant::tracer
