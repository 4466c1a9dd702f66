// A frame's error estimated from the blocks of its pixels' samples
// (tracer/frame_estimate.hpp, tracer/block_estimate.hpp): the grid
// arithmetic, the same image and estimate for any thread count, and the
// estimate against the true RMSE of the frame against a reference of many
// more samples; adaptive sampling driven by it.
#include "tracer/frame_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "tracer/renderer.hpp"
#include "tracer/sample_pattern.hpp"

// The scenes use POV-Ray 3.7's rules (without #version, POV-Ray reads a
// scene with its legacy gamma rule).
constexpr const char* kVersion37 = "#version 3.7;\n";

namespace tr = hexant::tracer;

namespace {

// A camera that moves and fast spinners: every pixel is blurred, so the
// estimate averages over the whole frame, not a few streaks.
const char* kScene = R"(
camera { location <0, 3, -8> look_at <0, 0.5, 0> angle 45 translate <clock, 0, 0> }
light_source { <-4 + 8 * clock, 8, -6>, rgb 1 }
background { rgb <0.1, 0.1, 0.2> }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.3 } }
#declare I = 0;
#while (I < 12)
  sphere { <1.5 + 0.1 * I, 0.4 + 0.15 * I, 0>, 0.2 rotate y * (360 * (1 + I) * clock + 30 * I)
           pigment { rgb <0.9, 0.3 + 0.05 * I, 0.2> } }
  #declare I = I + 1;
#end
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> translate <-4 + 8 * clock, 0, 1> pigment { rgb <0.2, 0.5, 0.9> } }
)";

hexant::runtime::SceneDescription parse_scene() {
    hexant::language::ParseOptions options;
    options.animation.width = 40;
    options.animation.height = 30;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 4;
    return hexant::language::parse_scene_text(std::string(kVersion37) + kScene, "estimate-test.pov",
                                              options);
}

struct Rendered {
    tr::Image image;
    std::optional<tr::FrameEstimate> estimate;
};

Rendered render(const hexant::runtime::SceneDescription& scene, int spp, int threads = 0,
                std::uint32_t seed = 0) {
    tr::RenderSettings settings;
    settings.samples_per_pixel = spp;
    settings.threads = threads;
    settings.sample_seed = seed;
    tr::Renderer renderer(scene, settings);
    Rendered out{renderer.render_frame(2), {}};
    out.estimate = renderer.last_estimate();
    return out;
}

double rmse(const tr::Image& a, const tr::Image& b) {
    REQUIRE(a.rgb.size() == b.rgb.size());
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i)
        sum += double(a.rgb[i] - b.rgb[i]) * (a.rgb[i] - b.rgb[i]);
    return std::sqrt(sum / double(a.rgb.size()));
}

}  // namespace

TEST_CASE("a frame estimate sums its squared errors over a fixed grid of tiles",
          "[tracer][estimate]") {
    // 20 x 18 pixels: tiles of 16 at x 0, 16 and y 0, 16; one pixel of
    // squared error 4 in the tile at (16, 16), the rest 0.
    std::vector<double> squared(20 * 18, 0.0);
    squared[17 * 20 + 18] = 4.0;
    const tr::FrameEstimate e = tr::estimate_frame(squared, 20, 18);
    CHECK(e.rmse == Approx(std::sqrt(4.0 / 360.0)).epsilon(1e-15));
    REQUIRE(e.worst.size() == 3);
    CHECK(e.worst[0].x == 16);
    CHECK(e.worst[0].y == 16);
    CHECK(e.worst[0].rmse == Approx(std::sqrt(4.0 / 8.0)).epsilon(1e-15));  // a 4 x 2 tile
    CHECK(e.worst[1].rmse == 0.0);
    CHECK_THROWS(tr::estimate_frame(squared, 20, 17));
}

TEST_CASE("a frame's samples give the same image and estimate on 1, 2 and 8 threads",
          "[tracer][estimate]") {
    const auto scene = parse_scene();
    const Rendered one = render(scene, 4, 1);
    REQUIRE(one.estimate);
    for (const int threads : {2, 8}) {
        const Rendered other = render(scene, 4, threads);
        REQUIRE(other.estimate);
        CHECK(other.image.rgb == one.image.rgb);
        CHECK(other.estimate->rmse == one.estimate->rmse);
        CHECK(other.estimate->worst.front().rmse == one.estimate->worst.front().rmse);
    }
    // One sample: nothing to compare, no estimate.
    CHECK(!render(scene, 1, 1).estimate);
}

TEST_CASE("the estimated RMSE is within a factor 1.5 of the true RMSE", "[tracer][estimate]") {
    // The truth: against a reference of 512 samples (another seed). Its own
    // noise adds to the measured error about (n / 512)^1.6 of the frame's
    // MSE (the README's error curve, RMSE ~ spp^-0.8): under 1% at 32
    // samples, well inside the factor. The estimate is the blocks' term
    // scaled by the rate the tile's quarters show (block_estimate.hpp): a
    // model, not an unbiased estimator, whose error is what this measures;
    // 1.5 is the issue's bound. 12 is between powers of two (its prefix of
    // 8 scaled), 2 has halves only (the independent samples' rate assumed).
    const auto scene = parse_scene();
    const tr::Image reference = render(scene, 512, 0, 7).image;
    for (const int spp : {2, 8, 12, 32}) {
        const Rendered r = render(scene, spp);
        REQUIRE(r.estimate);
        const double truth = rmse(r.image, reference);
        INFO("spp " << spp << " estimated " << r.estimate->rmse << " true " << truth);
        CHECK(r.estimate->rmse <= 1.5 * truth);
        CHECK(r.estimate->rmse >= truth / 1.5);
    }
}

namespace {

// Adaptive sampling wants a frame where some tiles need many samples and
// most few: a still camera and a plain floor (a checker's edges would need
// samples everywhere), a box, and spinners whose blur covers a few tiles.
const char* kAdaptiveScene = R"(
camera { location <0, 3, -8> look_at <0, 0.5, 0> angle 45 }
light_source { <-4, 8, -6>, rgb 1 }
background { rgb <0.1, 0.1, 0.2> }
plane { y, 0 pigment { rgb 0.6 } }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> translate <-2, 0, 1> pigment { rgb <0.2, 0.5, 0.9> } }
#declare I = 0;
#while (I < 6)
  sphere { <1 + 0.1 * I, 0.4 + 0.2 * I, 0>, 0.15 rotate y * (360 * (1 + I) * clock + 60 * I)
           translate <1.5, 0, 0> pigment { rgb <0.9, 0.3 + 0.1 * I, 0.2> } }
  #declare I = I + 1;
#end
)";

hexant::runtime::SceneDescription parse_adaptive_scene() {
    hexant::language::ParseOptions options;
    options.animation.width = 64;
    options.animation.height = 48;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 4;
    return hexant::language::parse_scene_text(std::string(kVersion37) + kAdaptiveScene,
                                              "adaptive-test.pov", options);
}

struct Adaptive {
    tr::Image image;
    tr::FrameEstimate estimate;
    std::vector<int> samples;
    std::uint64_t total = 0;
};

Adaptive render_adaptive(const hexant::runtime::SceneDescription& scene, int ceiling, double target,
                         int threads = 0) {
    tr::RenderSettings settings;
    settings.samples_per_pixel = ceiling;
    settings.target_error = target;
    settings.threads = threads;
    tr::Renderer renderer(scene, settings);
    Adaptive out{renderer.render_frame(2), {}, {}, 0};
    REQUIRE(renderer.last_estimate());
    out.estimate = *renderer.last_estimate();
    out.samples = renderer.last_samples();
    out.total = renderer.last_sample_count();
    return out;
}

}  // namespace

TEST_CASE("adaptive sampling gives the same image, estimate and samples on 1, 2 and 8 threads",
          "[tracer][estimate][adaptive]") {
    const auto scene = parse_adaptive_scene();
    const Adaptive one = render_adaptive(scene, 64, 0.01, 1);
    // (Not every tile stopped at the first round or went to the ceiling:
    // the rounds were decided, so their order could have mattered.)
    const auto [least, most] = std::minmax_element(one.samples.begin(), one.samples.end());
    REQUIRE(*least == tr::RenderSettings::kFirstRoundSamples);
    REQUIRE(*most > *least);
    for (const int threads : {2, 8}) {
        const Adaptive other = render_adaptive(scene, 64, 0.01, threads);
        CHECK(other.image.rgb == one.image.rgb);
        CHECK(other.samples == one.samples);
        CHECK(other.estimate.rmse == one.estimate.rmse);
    }
}

TEST_CASE(
    "a tile's rounds are the uniform render's samples: an unreachable target is the uniform image",
    "[tracer][estimate][adaptive]") {
    const auto scene = parse_adaptive_scene();
    // Target far below any tile's error: every pixel goes to the ceiling
    // and takes exactly the uniform render's samples, in the same order.
    const Adaptive all = render_adaptive(scene, 32, 1e-12);
    const Rendered uniform = [&] {
        tr::RenderSettings settings;
        settings.samples_per_pixel = 32;
        tr::Renderer renderer(scene, settings);
        return Rendered{renderer.render_frame(2), renderer.last_estimate()};
    }();
    CHECK(all.image.rgb == uniform.image.rgb);
    CHECK(all.estimate.rmse == uniform.estimate->rmse);
    CHECK(std::all_of(all.samples.begin(), all.samples.end(), [](int n) { return n == 32; }));
    // A target above every tile's error: one round everywhere.
    const Adaptive none = render_adaptive(scene, 32, 1.0);
    CHECK(none.total == std::uint64_t(64 * 48 * tr::RenderSettings::kFirstRoundSamples));
}

TEST_CASE("adaptive sampling reaches its target with fewer samples than uniform sampling",
          "[tracer][estimate][adaptive]") {
    // The truth against a reference of 1,024 samples (another seed); its
    // own RMSE is well under a tenth of the targets here (the README's
    // curve), so the factor 1.2 the issue allows is the estimate's and the
    // stopping rule's, not the reference's. Each tile stops when its
    // estimate is under the target, so the frame's true RMSE is at most the
    // target but for the estimate's spread over 256 pixels.
    const auto scene = parse_adaptive_scene();
    tr::RenderSettings settings;
    settings.samples_per_pixel = 1024;
    settings.sample_seed = 7;
    const tr::Image reference = tr::Renderer(scene, settings).render_frame(2);
    for (const double target : {0.01, 0.004}) {
        const Adaptive a = render_adaptive(scene, 1024, target);
        const double truth = rmse(a.image, reference);
        const double mean = double(a.total) / (64.0 * 48.0);
        // Uniform sampling with as many samples (to the count above) is
        // worse: the adaptive sampler put them where the error was.
        const int count = int(std::ceil(mean));
        const double uniform = rmse(render(scene, count).image, reference);
        INFO("target " << target << " true " << truth << " estimated " << a.estimate.rmse
                       << " mean spp " << mean << " uniform at " << count << ": " << uniform);
        CHECK(truth <= 1.2 * target);
        CHECK(uniform > truth);
    }
}
