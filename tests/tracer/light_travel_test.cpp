// A finite speed of light (tracer/light_travel.hpp): a sphere moving along
// x is seen where it was when its light left it, directly and in a mirror,
// against the analytic displacement; before the animation's first instant
// the scene is held as it was then; infinite light is today's image.
#include <cmath>
#include <limits>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "tracer/renderer.hpp"

namespace rt = hexant::runtime;
namespace tr = hexant::tracer;

namespace {

constexpr int kSize = 64;

// Two frames, clock 0 and 1 (clock_delta 1), each an instant.
rt::SceneDescription parse(const std::string& text) {
    hexant::language::ParseOptions options;
    options.animation.width = kSize;
    options.animation.height = kSize;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 2;
    options.animation.shutter = 0.0;
    return hexant::language::parse_scene_text(text, "light-travel-test.pov", options);
}

tr::Image render(const rt::SceneDescription& scene, int frame, double light_speed,
                 tr::Mode mode = tr::Mode::Spacetime) {
    tr::RenderSettings settings;
    settings.samples_per_pixel = 16;
    settings.light_speed = light_speed;
    settings.mode = mode;
    tr::Renderer renderer(scene, settings);
    return renderer.render_frame(frame);
}

// The brightness-weighted mean column, in screen units (-0.5 .. 0.5 across).
double centre(const tr::Image& image) {
    double sum = 0.0, weighted = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double b = image.at(x, y).x;
            sum += b;
            weighted += b * (x + 0.5);
        }
    REQUIRE(sum > 0.0);
    return weighted / sum / kSize - 0.5;
}

// The eye at z = -10 looks along +z through a screen 10 away: screen unit
// = scene unit on z = 0. A light leaving an event at distance D reached
// the eye D / C later. Unfolded, a ray from the eye along unit d meets the
// sphere (centre (v t, 0, D), moving) at time T - s / C exactly where the
// ray along d + (v / C) x meets the still sphere at (v T, 0, D): the image
// is the still one shifted by -(v / C) n on the screen, n = |(u, y, 10)|
// (10.0005 at most here).
const char* kCamera = R"(
camera { location <0, 0, -10> direction <0, 0, 10> right x up y }
background { rgb 0 }
)";

// (Tolerance: a tenth of a pixel, 0.0016 of the screen; the displacements
// tested are 60 times that.)
constexpr double kTolerance = 0.1 / kSize;

}  // namespace

TEST_CASE("a sphere moving along x is seen where it was when its light left it",
          "[tracer][light speed]") {
    // v = 0.2, distance 10 to the centre, C = 20: seen at v (T - 0.5).
    const auto scene = parse(
        std::string(kCamera) +
        "sphere { <0.2 * clock, 0, 0>, 0.05 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }");
    const double v = 0.2, c = 20.0, shift = v / c * 10.0;
    CHECK(centre(render(scene, 2, std::numeric_limits<double>::infinity())) ==
          Approx(v * 1.0).margin(kTolerance));
    CHECK(centre(render(scene, 2, c)) == Approx(v * 1.0 - shift).margin(kTolerance));
    // Per-frame hierarchies reach back as far (each frame's cells span the
    // time its light left at).
    CHECK(centre(render(scene, 2, c, tr::Mode::Frames)) ==
          Approx(v * 1.0 - shift).margin(kTolerance));
    CHECK(centre(render(scene, 2, c, tr::Mode::Brute)) ==
          Approx(v * 1.0 - shift).margin(kTolerance));
    // Frame 1 at clock 0: its light left before the animation began, when
    // the scene is held as at clock 0, the sphere at x = 0.
    CHECK(centre(render(scene, 1, c)) == Approx(0.0).margin(kTolerance));
}

TEST_CASE("reflected rays run back in time too: a mirror adds its path", "[tracer][light speed]") {
    // A mirror on z = 0 and, behind the eye at z = -20, the sphere: the
    // path eye-mirror-sphere is 30 long, so the sphere is seen at
    // x = v (T - 30 / C), on the screen a third of that (it appears 30
    // away). v = 0.6, C = 60, T = 1: 0.1 (instant light: 0.2).
    const auto scene = parse(
        std::string(kCamera) +
        "plane { z, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } }\n"
        "sphere { <0.6 * clock, 0, -20>, 0.15 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }");
    CHECK(centre(render(scene, 2, std::numeric_limits<double>::infinity())) ==
          Approx(0.2).margin(kTolerance));
    CHECK(centre(render(scene, 2, 60.0)) == Approx(0.1).margin(kTolerance));
}

TEST_CASE("shadow rays run back in time: a moving occluder's shadow lags",
          "[tracer][light speed]") {
    // A point light far along -z (at z = -1000: rays toward it nearly
    // parallel to z) lights a white wall on z = 0; a small occluder behind
    // the eye, at z = -20 (out of its sight), moves along x at v. The
    // shadow ray from the wall runs back 20 / C by the time it reaches the
    // occluder, which was then v 20 / C further back; and the eye sees the
    // wall's light that left it 10 / C before T: the shadow it sees is
    // where the occluder was at T - 30 / C.
    const auto scene = parse(std::string(kCamera) +
                             "light_source { <0, 0, -1000>, rgb 1 }\n"
                             "plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
                             "sphere { <0.3 * clock, 0, -20>, 0.1 pigment { rgb 1 } }");
    const auto shadow_centre = [&](double light_speed) {
        const tr::Image image = render(scene, 2, light_speed);
        double sum = 0.0, weighted = 0.0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const double dark = 1.0 - std::min(1.0, image.at(x, y).x / image.at(0, 0).x);
                sum += dark;
                weighted += dark * (x + 0.5);
            }
        REQUIRE(sum > 0.0);
        return weighted / sum / kSize - 0.5;
    };
    // (A light 1000 away casts the shadow of a sphere 20 off the wall at
    // its x times 1000 / 980.)
    const double grow = 1000.0 / 980.0;
    CHECK(shadow_centre(std::numeric_limits<double>::infinity()) ==
          Approx(0.3 * grow).margin(kTolerance));
    CHECK(shadow_centre(150.0) == Approx(0.3 * (1.0 - 30.0 / 150.0) * grow).margin(kTolerance));
}

TEST_CASE(
    "light barely finite differs from instant light by rounding only, and instant light runs no "
    "ray "
    "through time",
    "[tracer][light speed]") {
    // (Instant light is today's image bit for bit: its rays carry w exactly
    // 0 and take the path they always took, which the counter shows; the
    // golden frames and the exact POV-Ray stills hold the images.)
    const auto scene = parse(std::string(kCamera) +
                             "light_source { <-3, 4, -6>, rgb 1 }\n"
                             "plane { y, -0.3 pigment { checker rgb 0.9, rgb 0.2 scale 0.1 } "
                             "finish { reflection 0.3 } }\n"
                             "sphere { <0.2 * clock, 0, 0>, 0.2 pigment { rgbf <0.9, 0.9, 1, 0.8> "
                             "} interior { ior 1.4 } }\n"
                             "box { <-0.4, -0.3, 0.2>, <-0.2, 0.1, 0.4> rotate y * 90 * clock "
                             "pigment { rgb <1, 0.4, 0.2> } }");
    tr::RenderSettings settings;
    settings.samples_per_pixel = 4;
    tr::Renderer instant(scene, settings);
    const tr::Image a = instant.render_frame(2);
    CHECK(instant.counters().travelling_rays == 0);
    // C = 10^12: every ray takes the time-travelling walk, and its times
    // differ from the instant's by 10^-11 at most.
    settings.light_speed = 1e12;
    tr::Renderer fast(scene, settings);
    const tr::Image c = fast.render_frame(2);
    double largest = 0.0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i)
        largest = std::max(largest, double(std::fabs(a.rgb[i] - c.rgb[i])));
    CHECK(largest < 1e-4);
    CHECK(fast.counters().travelling_rays >= fast.counters().primary_rays);
}

TEST_CASE("a surface that moves does not shadow itself under light of finite speed",
          "[tracer][light speed]") {
    // A ball whose centre moves with clock (its geometry changes along a
    // ray that runs through time): each hit must lie on the surface as it
    // stands at the hit's own instant, or the shadow ray leaving it meets
    // the surface as it stood a moment earlier, just behind its start
    // (found by a fresh user: half the ball dark at C = 10^6, where it moves
    // at 6 10^-6 of light's speed). At such a speed the image is the
    // instant one but for edges moved by 6 10^-5 (a flipped sample here
    // and there: 1/16 of a pixel's contrast); a self-shadow darkens
    // whole regions by more than half. In every mode.
    const auto scene =
        parse(std::string(kCamera) +
              "light_source { <2, 4, -3>, rgb 1 }\n"
              "plane { y, -0.3 pigment { checker rgb 1, rgb 0.2 scale 0.2 } }\n"
              "sphere { <6 * clock - 6, 0, 0>, 0.25 pigment { rgb <1, 0.3, 0.2> } }");
    const tr::Image instant = render(scene, 2, std::numeric_limits<double>::infinity());
    for (const tr::Mode mode : {tr::Mode::Spacetime, tr::Mode::Frames, tr::Mode::Brute}) {
        const tr::Image fast = render(scene, 2, 1e6, mode);
        int changed = 0;
        for (std::size_t i = 0; i < fast.rgb.size(); ++i)
            if (std::fabs(fast.rgb[i] - instant.rgb[i]) > 0.2) ++changed;
        INFO(tr::mode_name(mode));
        CHECK(changed == 0);
    }
}

TEST_CASE("the speed of light must be positive", "[tracer][light speed]") {
    const auto scene = parse(std::string(kCamera));
    tr::RenderSettings settings;
    for (const double bad : {0.0, -1.0, std::nan("")}) {
        settings.light_speed = bad;
        CHECK_THROWS_WITH(tr::Renderer(scene, settings), Catch::Contains("speed of light"));
    }
}
