// Objects that live part of the time (runtime/objects/lifetime_object.hpp), made by
// a branch on clock: a blurred frame that holds a switching instant shows
// each side for its share of the shutter, the three modes agree, and
// lights that shine part of the time light only then.
#include <cmath>
#include <string>
#include <utility>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "tracer/renderer.hpp"

// The scenes use POV-Ray 3.7's rules (without #version, POV-Ray reads a
// scene with its legacy gamma rule).
constexpr const char* kVersion37 = "#version 3.7;\n";

namespace tr = hexant::tracer;

namespace {

// Frames 1 and 2 over clock 0 to 1: frame 1's shutter is [0, 1).
hexant::runtime::SceneDescription parse(const std::string& text) {
    hexant::language::ParseOptions options;
    options.animation.width = 24;
    options.animation.height = 16;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 2;
    return hexant::language::parse_scene_text(std::string(kVersion37) + text, "lifetime.pov",
                                              options);
}

tr::Image render(const hexant::runtime::SceneDescription& scene, tr::Mode mode, int spp) {
    tr::RenderSettings settings;
    settings.mode = mode;
    settings.samples_per_pixel = spp;
    tr::Renderer renderer(scene, settings);
    return renderer.render_frame(1);
}

// Frames 1 and 2 of `text` at shutter 0 (clock 0 and clock 1), one sample
// at each pixel.
std::pair<tr::Image, tr::Image> first_and_last(const std::string& text) {
    auto scene = parse(text);
    scene.animation.shutter = 0.0;
    tr::RenderSettings settings;
    settings.samples_per_pixel = 1;
    tr::Renderer renderer(scene, settings);
    tr::Image first = renderer.render_frame(1);
    return {std::move(first), renderer.render_frame(2)};
}

// A white square (ambient 1, nothing else) filling the view while clock >
// `at`, a black background before.
std::string switching_scene(double at) {
    return "camera { location <0, 0, -5> look_at 0 }\n"
           "#if (clock > " +
           std::to_string(at) +
           ")\n"
           "  box { <-10, -10, 0>, <10, 10, 1> pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n"
           "#end\n";
}

}  // namespace

TEST_CASE("a frame blurred across a switch shows each side for its share of the shutter",
          "[tracer][lifetime]") {
    // The pixel is the mean over the shutter of 1 after the switch and 0
    // before: 1 - at. The samples' times are stratified over the shutter
    // (one per stratum of 1/spp), so the mean is within 1/spp of it.
    const int spp = 64;
    for (const double at : {0.1, 0.3137, 0.5, 0.9}) {
        const auto scene = parse(switching_scene(at));
        const tr::Image image = render(scene, tr::Mode::Spacetime, spp);
        double mean = 0.0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) mean += image.at(x, y).x;
        mean /= double(image.width * image.height);
        INFO("switch at " << at << ": mean " << mean);
        CHECK(std::fabs(mean - (1.0 - at)) <= 1.0 / spp);
    }
}

TEST_CASE("spacetime, frames and brute force agree on objects that live part of the time",
          "[tracer][lifetime]") {
    const auto scene = parse(R"(
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <-4, 8, -6>, rgb 1 }
#if (clock > 0.4) light_source { <4, 3, -6>, rgb <1, 0.5, 0.2> } #end
plane { y, 0 pigment { checker rgb 0.8, rgb 0.3 } }
#declare I = 0;
#while (I < 8)
  #if (clock > I / 8)
    sphere { <-2 + 0.6 * I, 0.3, 0>, 0.3 pigment { rgb <0.9, 0.3, 0.1 * I> } }
  #else
    box { <-2.3 + 0.6 * I, 0, -0.3>, <-1.7 + 0.6 * I, 0.6, 0.3> pigment { rgb 0.9 } }
  #end
  #declare I = I + 1;
#end
intersection {
  sphere { <0, 1.5, 1>, 0.8 }
  #if (clock < 0.7) box { <-1, 1.5, 0>, <1, 3, 2> } #end
  pigment { rgb <0.2, 0.6, 0.9> }
}
)");
    const tr::Image brute = render(scene, tr::Mode::Brute, 8);
    CHECK(render(scene, tr::Mode::Spacetime, 8).rgb == brute.rgb);
    CHECK(render(scene, tr::Mode::Frames, 8).rgb == brute.rgb);
    double sum = 0.0;
    for (float v : brute.rgb) sum += v;
    CHECK(sum > 0.1 * brute.rgb.size());
}

TEST_CASE("an intersection's member that does not exist leaves the others whole",
          "[tracer][lifetime]") {
    // While the box is absent (clock >= 0.5) the intersection is the whole
    // sphere (POV-Ray intersects the members there are); while present,
    // the sphere's upper half only. Frame 1 at shutter 0 is clock 0 and
    // frame 2 is clock 1.
    const std::string text = R"(
camera { location <0, 0, -5> look_at 0 }
intersection {
  sphere { 0, 1.5 }
  #if (clock < 0.5) box { <-2, 0, -2>, <2, 2, 2> } #end
  pigment { rgb 1 } finish { ambient 1 diffuse 0 }
}
)";
    const auto [with_box, without] = first_and_last(text);
    const int cx = with_box.width / 2;
    const int below = with_box.height * 3 / 4;  // below the centre: the lower half
    CHECK(with_box.at(cx, below).x == 0.0f);
    CHECK(without.at(cx, below).x == 1.0f);
    CHECK(with_box.at(cx, with_box.height / 4).x == 1.0f);
}

TEST_CASE("a difference whose first member is absent takes the rest from the next one",
          "[tracer][lifetime]") {
    // POV-Ray's difference { sphere } is the sphere: while the box does not
    // exist (clock <= 0.5) the sphere is the base; after, the box minus the
    // sphere. Frames 1 and 2 at shutter 0: clock 0 and 1.
    const std::string text = R"(
camera { location <0, 0, -5> look_at 0 }
difference {
  #if (clock > 0.5) box { <-2, -2, -0.5>, <2, 2, 0.5> } #end
  sphere { <0, 0, -0.5>, 0.7 }
  pigment { rgb 1 } finish { ambient 1 diffuse 0 }
}
)";
    const auto [sphere_only, box_less_sphere] = first_and_last(text);
    auto scene = parse(text);
    scene.animation.shutter = 0.0;
    const int cx = sphere_only.width / 2, cy = sphere_only.height / 2;
    CHECK(sphere_only.at(cx, cy).x == 1.0f);          // the sphere
    CHECK(sphere_only.at(cx / 2, cy).x == 0.0f);      // nothing else
    CHECK(box_less_sphere.at(cx / 2, cy).x == 1.0f);  // the box
    CHECK(box_less_sphere.at(cx, cy).x == 1.0f);      // the hole's floor, inside the box
    CHECK(render(scene, tr::Mode::Brute, 2).rgb == render(scene, tr::Mode::Spacetime, 2).rgb);
}
