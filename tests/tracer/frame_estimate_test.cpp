// A frame's error estimated from two independent halves of its samples
// (tracer/frame_estimate.hpp, RenderSettings::sample_sets): the grid
// arithmetic, the same image and estimate for any thread count, and the
// estimate against the true RMSE of the frame against a reference of many
// more samples.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "language/interpreter.hpp"
#include "tracer/frame_estimate.hpp"
#include "tracer/renderer.hpp"
#include "tracer/sample_pattern.hpp"

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
    return hexant::language::parse_scene_text(kScene, "estimate-test.pov", options);
}

struct Rendered {
    tr::Image image;
    std::optional<tr::FrameEstimate> estimate;
};

Rendered render(const hexant::runtime::SceneDescription& scene, int spp, int sets, int threads = 0,
                std::uint32_t seed = 0) {
    tr::RenderSettings settings;
    settings.samples_per_pixel = spp;
    settings.sample_sets = sets;
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
    for (std::size_t i = 0; i < a.rgb.size(); ++i) sum += double(a.rgb[i] - b.rgb[i]) * (a.rgb[i] - b.rgb[i]);
    return std::sqrt(sum / double(a.rgb.size()));
}

}  // namespace

TEST_CASE("a frame estimate sums its squared errors over a fixed grid of tiles", "[tracer][estimate]") {
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

TEST_CASE("the second sample set's seed is none that --seed gives", "[tracer][estimate]") {
    for (int x = 0; x < 64; ++x) {
        const std::uint32_t own = tr::pixel_seed(3, x, 5);
        const std::uint32_t second = tr::second_set_seed(own);
        CHECK(second != own);
        for (std::uint32_t s = 1; s < 64; ++s) CHECK(second != tr::pixel_seed(3, x, 5, s));
    }
}

TEST_CASE("two sample sets give the same image and estimate on 1, 2 and 8 threads", "[tracer][estimate]") {
    const auto scene = parse_scene();
    const Rendered one = render(scene, 4, 2, 1);
    REQUIRE(one.estimate);
    for (const int threads : {2, 8}) {
        const Rendered other = render(scene, 4, 2, threads);
        REQUIRE(other.estimate);
        CHECK(other.image.rgb == one.image.rgb);
        CHECK(other.estimate->rmse == one.estimate->rmse);
        CHECK(other.estimate->worst.front().rmse == one.estimate->worst.front().rmse);
    }
    // One set: no estimate, and the image of every earlier render.
    CHECK(!render(scene, 4, 1, 1).estimate);
}

TEST_CASE("the estimated RMSE is within a factor 1.5 of the true RMSE", "[tracer][estimate]") {
    // The truth: against a reference of 256 samples (another seed). Its own
    // noise adds to the measured error about (n / 256)^1.6 of the frame's
    // MSE (the README's error curve, RMSE ~ spp^-0.8): 0.4% at 8 samples,
    // 4% at 32, well inside the factor. The estimate is unbiased for the
    // frame's variance (independent halves); over the 1,200 pixels, all
    // blurred by the moving camera, its spread is a few per cent, so 1.5 is
    // the issue's bound with room, not a tuned number.
    const auto scene = parse_scene();
    const tr::Image reference = render(scene, 256, 1, 0, 7).image;
    for (const int spp : {8, 32}) {
        const Rendered r = render(scene, spp, 2);
        REQUIRE(r.estimate);
        const double truth = rmse(r.image, reference);
        INFO("spp " << spp << " estimated " << r.estimate->rmse << " true " << truth);
        CHECK(r.estimate->rmse <= 1.5 * truth);
        CHECK(r.estimate->rmse >= truth / 1.5);
    }
}
