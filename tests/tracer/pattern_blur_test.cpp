// An animated pigment blurs as the mean of its instants: a wall whose
// pattern's phase moves with clock (a sine wave through a colour map, or
// through a texture_map of whole textures), rendered as one motion-blurred
// frame, against the brute-force mean of stills at 64 instants across the
// same shutter. The texture is evaluated at each sample's own time
// (runtime/texture/texture_evaluator.cpp).
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "tracer/renderer.hpp"

// The scenes use POV-Ray 3.7's rules (without #version, POV-Ray reads a
// scene with its legacy gamma rule).
constexpr const char* kVersion37 = "#version 3.7;\n";

namespace tr = hexant::tracer;

namespace {

// The pattern barely changes across the wall (gradient x scaled by 10^6),
// so every pixel is the colour of the phase, 0.25 + 0.5 clock, through a
// sine wave: the mean over clock 0 to 1 is a curved integral, far from
// the colour at any one instant.
const char* kScene = R"(
camera { location <0, 0, -5> look_at 0 }
box { <-10, -10, 0>, <10, 10, 1>
  pigment { gradient x scale 1e6 sine_wave phase 0.25 + 0.5 * clock
            color_map { [0 rgb <0, 0, 1>] [0.6 rgb <1, 0.5, 0>] [1 rgb 1] } }
  finish { ambient 1 diffuse 0 } }
)";
// The same colours as whole textures, blended lit (ambient 1, diffuse 0:
// each lit colour is its pigment's).
const char* kTextureMapScene = R"(
camera { location <0, 0, -5> look_at 0 }
#declare Lit = finish { ambient 1 diffuse 0 }
box { <-10, -10, 0>, <10, 10, 1>
  texture { gradient x scale 1e6 sine_wave phase 0.25 + 0.5 * clock
            texture_map { [0 pigment { rgb <0, 0, 1> } finish { Lit }]
                          [0.6 pigment { rgb <1, 0.5, 0> } finish { Lit }]
                          [1 pigment { rgb 1 } finish { Lit }] } } }
)";

hexant::runtime::SceneDescription parse(const std::string& text, int frames, double shutter) {
    hexant::language::ParseOptions options;
    options.animation.width = 16;
    options.animation.height = 12;
    options.animation.initial_frame = 1;
    options.animation.final_frame = frames;
    auto scene =
        hexant::language::parse_scene_text(std::string(kVersion37) + text, "blur.pov", options);
    scene.animation.shutter = shutter;
    return scene;
}

}  // namespace

TEST_CASE("a frame of an animated pigment is the mean of its instants", "[tracer][pattern]") {
    const std::string text = GENERATE(std::string(kScene), std::string(kTextureMapScene));
    INFO(text);
    // Frame 1 of 2 over clock 0 to 1: its shutter is [0, 1).
    const auto blurred_scene = parse(text, 2, 1.0);
    tr::RenderSettings settings;
    settings.samples_per_pixel = 64;
    tr::Renderer blurred_renderer(blurred_scene, settings);
    const tr::Image blurred = blurred_renderer.render_frame(1);
    // 64 stills at clock (k + 1/2) / 64: frames of a shutter-0 animation
    // whose clock steps by 1/64, from 1/128.
    auto stills = parse(text, 65, 0.0);
    stills.animation.initial_clock = 0.5 / 64.0;
    stills.animation.final_clock = 64.5 / 64.0;
    tr::RenderSettings one;
    one.samples_per_pixel = 1;
    one.jitter = false;
    tr::Renderer still_renderer(stills, one);
    tr::Image mean(blurred.width, blurred.height);
    for (int k = 1; k <= 64; ++k) {
        const tr::Image still = still_renderer.render_frame(k);
        for (std::size_t i = 0; i < mean.rgb.size(); ++i) mean.rgb[i] += still.rgb[i] / 64.0f;
    }
    // The blurred frame's samples are stratified in time (one per 1/64 of
    // the shutter), as the instants are: both are within 1/64 of the
    // integral per channel (the colour changes by at most 1 over the
    // shutter); an animated texture evaluated at one instant (the frame's
    // opening, or its middle) is off by 0.2 or more.
    double worst = 0.0;
    for (std::size_t i = 0; i < mean.rgb.size(); ++i)
        worst = std::max(worst, double(std::fabs(blurred.rgb[i] - mean.rgb[i])));
    INFO("worst channel difference " << worst);
    CHECK(worst <= 2.0 / 64.0);
    // And the blur is not the colour of one instant.
    const tr::Image first = still_renderer.render_frame(1);
    double apart = 0.0;
    for (std::size_t i = 0; i < mean.rgb.size(); ++i)
        apart = std::max(apart, double(std::fabs(blurred.rgb[i] - first.rgb[i])));
    CHECK(apart > 0.2);
}
