// A union of still members under a moving transform renders as one
// instance (runtime/objects/instance_object.hpp): the image is the one its
// members make as objects of their own, in every mode, and the hierarchy
// holds one object for it.
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "tracer/renderer.hpp"

namespace tr = hexant::tracer;

namespace {

// 36 spheres and a box, checkered in their own space, turning and sliding
// over the shutter, over a floor, with shadows.
constexpr const char* kScene = R"(#version 3.7;
camera { location <0, 4, -9> look_at <0, 0, 0> angle 45 }
light_source { <-10, 20, -15>, rgb 1 }
plane { y, -1.5 pigment { checker rgb 0.8, rgb 0.3 } }
union {
  #declare I = 0;
  #while (I < 36)
    sphere { <mod(I, 6) - 2.5, 0, div(I, 6) - 2.5>, 0.4
             pigment { checker rgb <1, 0.6, 0.2>, rgb <0.2, 0.3, 1> scale 0.15 }
             finish { phong 0.5 } }
    #declare I = I + 1;
  #end
  box { <-3, -1, -3>, <3, -0.8, 3> pigment { rgb 0.6 } }
  rotate y * 40 * clock translate <1.5 * clock, 0, 0>
}
)";

hexant::runtime::SceneDescription parse(const char* text = kScene) {
    hexant::language::ParseOptions options;
    options.animation.width = 64;
    options.animation.height = 48;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 3;
    return hexant::language::parse_scene_text(text, "instance.pov", options);
}

struct Rendered {
    tr::Image image;
    std::uint64_t objects;
};

Rendered render(const hexant::runtime::SceneDescription& scene, tr::Mode mode, bool instances) {
    tr::RenderSettings settings;
    settings.mode = mode;
    settings.samples_per_pixel = 4;
    settings.build.instances = instances;
    tr::Renderer renderer(scene, settings);
    Rendered r{renderer.render_frame(2), 0};
    r.objects = renderer.counters().objects;
    return r;
}

// Pixels whose channels differ by more than `tolerance`.
int differing(const tr::Image& a, const tr::Image& b, float tolerance) {
    REQUIRE(a.rgb.size() == b.rgb.size());
    int n = 0;
    for (std::size_t i = 0; i < a.rgb.size(); i += 3)
        n += std::fabs(a.rgb[i] - b.rgb[i]) > tolerance ||
             std::fabs(a.rgb[i + 1] - b.rgb[i + 1]) > tolerance ||
             std::fabs(a.rgb[i + 2] - b.rgb[i + 2]) > tolerance;
    return n;
}

}  // namespace

TEST_CASE("an instance renders as its members do, in every mode", "[tracer][instance]") {
    const auto scene = parse();
    const Rendered instanced = render(scene, tr::Mode::Spacetime, true);
    const Rendered split = render(scene, tr::Mode::Spacetime, false);
    CHECK(instanced.objects == 2);  // the floor and the instance
    CHECK(split.objects == 38);
    // The same samples meet the same surfaces; a ray moved into the union's
    // space rounds differently from one met by members placed one by one,
    // by about 1e-16 of the scene's size, which moves a shading value by as
    // little (1e-5 is far above it and far below one step of an 8-bit
    // pixel). A sample that grazes an edge may go either way: a handful of
    // pixels of 3,072.
    CHECK(differing(instanced.image, split.image, 1e-5f) <= 3);
    // The three modes use the same objects: equal to the bit.
    CHECK(differing(instanced.image, render(scene, tr::Mode::Frames, true).image, 0.0f) == 0);
    CHECK(differing(instanced.image, render(scene, tr::Mode::Brute, true).image, 0.0f) == 0);
}

// Members placed 10^5 away and brought back by the union's transform: their
// points were rounded at 10^5 in the union's space, and the shadow rays'
// start must clear that, not only the world point's ulps (a first version
// carried the error through the composed map and the spheres were speckled
// with their own shadows: 507 pixels of 19,200 off by up to 0.5).
constexpr const char* kFarMembers = R"(#version 3.7;
camera { location <0, 3, -8> look_at <0, 0.5, 0> }
light_source { <5, 10, -5>, rgb 1 }
plane { y, -1 pigment { rgb 1 } }
union {
  #for (I, 0, 15)
    sphere { <mod(I, 4) - 1.5, 0, div(I, 4) - 1.5>, 0.4 translate 1e5 * x pigment { rgb 1 } }
  #end
  translate -1e5 * x
  translate x * clock
}
)";

TEST_CASE("an instance's members placed far off shade as the members do", "[tracer][instance]") {
    const auto scene = parse(kFarMembers);
    const Rendered instanced = render(scene, tr::Mode::Spacetime, true);
    const Rendered split = render(scene, tr::Mode::Spacetime, false);
    CHECK(instanced.objects == 2);
    CHECK(split.objects == 17);
    // (As above: rounding may move a sample at an edge.)
    CHECK(differing(instanced.image, split.image, 1e-5f) <= 3);
}

TEST_CASE("no instance where a ray may travel in time", "[tracer][instance]") {
    const auto scene = parse();
    tr::RenderSettings settings;
    settings.light_speed = 1000.0;
    tr::Renderer renderer(scene, settings);
    CHECK(renderer.counters().objects == 38);
}
