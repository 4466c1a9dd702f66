// The robustness suite (label `robust`, issue 16): scenes whose right image
// is known without a reference renderer, at world scales from small to huge.
//
// Self-shadowing: a surface lit from its own side cannot shadow itself, so
// each scene is rendered twice, its light casting shadows and `shadowless`,
// with the same samples. A ground with no other object shades the same in
// both (no phong or specular, whose shadowless rule differs), so any pixel
// darker with shadows is a false shadow: the count must be zero, in every
// mode, and the three modes must give the same pixels.
//
// The scenes are numerics case 18 (a sphere of radius R as the
// ground) and 11 (a floor of one triangle, smooth triangle or polygon whose
// vertices lie Half from the origin), at the radii and halves the issue
// names: 10 to 1e8.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "tracer/renderer.hpp"

namespace tr = hexant::tracer;

namespace {

// 64 by 48, one sample per pixel: 3,072 shadow rays per render, from every
// part of the ground the camera sees (near, far, grazing at the horizon).
tr::Image render(const std::string& sdl, tr::Mode mode) {
    hexant::language::ParseOptions options;
    options.animation.width = 64;
    options.animation.height = 48;
    const auto scene = hexant::language::parse_scene_text(sdl, "robust.pov", options);
    tr::RenderSettings settings;
    settings.mode = mode;
    tr::Renderer renderer(scene, settings);
    return renderer.render_frame(scene.animation.initial_frame);
}

// Pixels darker with shadows than without. Both renders trace the same
// camera rays and shade with the same code; only the shadow test differs,
// so an unshadowed pixel is equal bit for bit: any darkening is a shadow.
int false_shadows(const tr::Image& shadowed, const tr::Image& lit) {
    int count = 0;
    for (int y = 0; y < lit.height; ++y)
        for (int x = 0; x < lit.width; ++x) {
            const glm::dvec3 a = shadowed.at(x, y), b = lit.at(x, y);
            if (a.x < b.x || a.y < b.y || a.z < b.z) ++count;
        }
    return count;
}

bool same_pixels(const tr::Image& a, const tr::Image& b) {
    return a.width == b.width && a.height == b.height && a.rgb == b.rgb;
}

std::string number(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

// Renders the scene (with LIGHT where its light goes) in the three modes
// with shadows and once without: no false shadow, the modes identical.
void check_no_self_shadow(const std::string& scene) {
    const auto with = [&](const std::string& light) {
        std::string s = scene;
        s.replace(s.find("LIGHT"), 5, light);
        return s;
    };
    const std::string shadows = with("light_source { <-4, 7, -5>, rgb 1 }");
    const std::string none = with("light_source { <-4, 7, -5>, rgb 1 shadowless }");
    const tr::Image lit = render(none, tr::Mode::Spacetime);
    const tr::Image spacetime = render(shadows, tr::Mode::Spacetime);
    const tr::Image frames = render(shadows, tr::Mode::Frames);
    const tr::Image brute = render(shadows, tr::Mode::Brute);
    CHECK(false_shadows(spacetime, lit) == 0);
    CHECK(false_shadows(frames, lit) == 0);
    CHECK(false_shadows(brute, lit) == 0);
    CHECK(same_pixels(spacetime, frames));
    CHECK(same_pixels(spacetime, brute));
}

}  // namespace

namespace {

// A ground (an object's text up to its closing brace) under the camera and
// the light of case 18, for check_no_self_shadow.
std::string ground_scene(const std::string& ground) {
    return "camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 45 }\n"
           "LIGHT\n"
           "background { rgb <0.15, 0.2, 0.35> }\n" +
           ground + " pigment { rgb <0.75, 0.7, 0.6> } }\n";
}

}  // namespace

TEST_CASE("a big sphere used as the ground does not shadow itself", "[robust]") {
    for (const double r : {10.0, 1e3, 1e5, 1e6, 1e8}) {
        const std::string rs = number(r);
        // Its size in its own centre and radius; a unit sphere placed by
        // scale and translate (the error carried through the placement);
        // the same turning slowly about the vertical through its centre
        // (a moving object: the placement evaluated at the ray's time).
        const std::string spheres[] = {
            "sphere { <0, -" + rs + ", 0>, " + rs,
            "sphere { 0, 1 scale " + rs + " translate <0, -" + rs + ", 0>",
            "sphere { 0, 1 scale " + rs + " rotate y * 30 * clock translate <0, -" + rs + ", 0>",
        };
        for (const std::string& sphere : spheres) {
            INFO(sphere);
            check_no_self_shadow(ground_scene(sphere));
        }
    }
}

TEST_CASE("a floor of huge triangles does not shadow itself", "[robust]") {
    for (const double half : {10.0, 1e3, 1e6, 1e8}) {
        const std::string h = number(half);
        const std::string a = "<-" + h + ", 0, -" + h + ">", b = "<" + h + ", 0, -" + h + ">",
                          c = "<0, 0, " + h + ">";
        const std::string floors[] = {
            "triangle { " + a + ", " + b + ", " + c + " pigment { rgb 0.8 } }",
            "smooth_triangle { " + a + ", y, " + b + ", y, " + c + ", y pigment { rgb 0.8 } }",
            "polygon { 4, " + a + ", " + b + ", " + c + ", " + a + " pigment { rgb 0.8 } }",
        };
        for (const std::string& floor : floors) {
            INFO("Half = " << half << ": " << floor.substr(0, floor.find(' ')));
            check_no_self_shadow(
                "camera { location <0, 2.2, -6> look_at <0, 0.3, 0> angle 45 }\n"
                "LIGHT\n"
                "background { rgb <0.3, 0.4, 0.6> }\n" +
                floor + "\n");
        }
    }
}

namespace {

// Every frame of an animation in one mode.
std::vector<tr::Image> render_all(const std::string& sdl, tr::Mode mode, int frames) {
    hexant::language::ParseOptions options;
    options.animation.width = 64;
    options.animation.height = 48;
    options.animation.initial_frame = 1;
    options.animation.final_frame = frames;
    const auto scene = hexant::language::parse_scene_text(sdl, "robust.pov", options);
    tr::RenderSettings settings;
    settings.mode = mode;
    settings.samples_per_pixel = 2;
    tr::Renderer renderer(scene, settings);
    std::vector<tr::Image> images;
    for (int k = 1; k <= frames; ++k) images.push_back(renderer.render_frame(k));
    return images;
}

}  // namespace

// The second kind: a floor of two huge triangles sliding and
// turning under a ball, where the hierarchy once changed the answer. Every
// mode calls the same routines on the same rays, so the frames must be
// equal bit for bit.
TEST_CASE("the modes agree on a moving floor of huge triangles", "[robust]") {
    for (const double half : {1e3, 1e6, 1e8}) {
        INFO("Half = " << half);
        const std::string h = number(half);
        const std::string move = " rotate y * 20 * clock translate <3 * clock, 0, 2 * clock>";
        const std::string sdl =
            "camera { location <0, 2.2, -6> look_at <0, 0.3, 0> angle 45 }\n"
            "light_source { <-4, 7, -5>, rgb 1 }\n"
            "triangle { <-" +
            h + ", 0, -" + h + ">, <" + h + ", 0, -" + h + ">, <" + h + ", 0, " + h + ">" + move +
            " pigment { rgb 0.8 } }\n"
            "triangle { <-" +
            h + ", 0, -" + h + ">, <" + h + ", 0, " + h + ">, <-" + h + ", 0, " + h + ">" + move +
            " pigment { rgb 0.7 } }\n"
            "sphere { <0, 0.5, 0>, 0.5 pigment { rgb <1, 0.4, 0.2> } }\n";
        const auto spacetime = render_all(sdl, tr::Mode::Spacetime, 4);
        const auto frames = render_all(sdl, tr::Mode::Frames, 4);
        const auto brute = render_all(sdl, tr::Mode::Brute, 4);
        for (std::size_t k = 0; k < spacetime.size(); ++k) {
            INFO("frame " << k + 1);
            CHECK(same_pixels(spacetime[k], frames[k]));
            CHECK(same_pixels(spacetime[k], brute[k]));
        }
    }
}

TEST_CASE("big grounds of every kind do not shadow themselves", "[robust]") {
    for (const double r : {10.0, 1e3, 1e6, 1e8}) {
        const std::string rs = number(r);
        const std::string grounds[] = {
            "box { <-" + rs + ", -" + rs + ", -" + rs + ">, <" + rs + ", 0, " + rs + ">",
            "box { -1, 1 scale " + rs + " translate <0, -" + rs + ", 0>",
            "cylinder { <-" + rs + ", -" + rs + ", 0>, <" + rs + ", -" + rs + ", 0>, " + rs,
            "cone { <-" + rs + ", -" + rs + ", 0>, " + rs + ", <" + rs + ", -" + rs + ", 0>, " + rs,
            "disc { 0, y, " + rs,
            "plane { y, 0 scale " + rs,
            "torus { " + number(2 * r) + ", " + rs + " translate <0, -" + rs + ", " +
                number(2 * r) + ">",
            "prism { -" + rs + ", 0, 4, <-" + rs + ", -" + rs + ">, <" + rs + ", -" + rs +
                ">, <0, " + rs + ">, <-" + rs + ", -" + rs + ">",
            // Deformed: the curved-path search (a slight twist keeps the top
            // flat enough to be lit everywhere).
            "box { -1, <1, 0, 1> twist y, 1 scale " + rs,
            "sphere { 0, 1 twist y, 1 scale " + rs + " translate <0, -" + rs + ", 0>",
        };
        for (const std::string& ground : grounds) {
            INFO(ground);
            check_no_self_shadow(ground_scene(ground));
        }
    }
}

namespace {

// Pixels whose colour differs by more than `tolerance` in some channel.
int differing(const tr::Image& a, const tr::Image& b, double tolerance) {
    int count = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const glm::dvec3 d = glm::abs(a.at(x, y) - b.at(x, y));
            if (d.x > tolerance || d.y > tolerance || d.z > tolerance) ++count;
        }
    return count;
}

}  // namespace

// numerics case 09: a checkered plane at an integer height (on a
// cell boundary) in a world scaled by Sc, camera and light scaled too. The
// image must not depend on Sc. Tolerance 0.05 per channel: scaling changes
// only roundings (relative 1e-12 in the shading), while a checker that
// flips changes a channel by 0.35 (0.8 against 0.45) and a lost or false
// shadow by more; a pixel whose sample lands within rounding of a cell's
// edge or the ball's outline could flip at one scale and not another, so a
// few such pixels (under 1%) are allowed, none at all on the boundary face.
TEST_CASE("a checkered plane on a cell boundary renders alike at every world scale", "[robust]") {
    for (const char* y : {"-1", "0", "-0.999"}) {
        const auto scene = [&](double sc) {
            const std::string s = number(sc);
            return "camera { location <0, 2.5, -6> * " + s + " look_at <0, 0.3, 0> * " + s +
                   " angle 40 }\n"
                   "light_source { <-5, 8, -6> * " +
                   s +
                   ", rgb 1 }\n"
                   "plane { y, " +
                   std::string(y) + " pigment { checker rgb 0.8, rgb 0.45 } scale " + s +
                   " }\n"
                   "sphere { 0, 0.5 pigment { rgb <1, 0.4, 0.2> } translate <0.3, " +
                   std::string(y) + " + 0.5, 0> scale " + s + " }\n";
        };
        const tr::Image unit = render(scene(1.0), tr::Mode::Spacetime);
        for (const double sc : {1e-6, 1e-3, 1e5, 3e5, 5e5, 1e6, 1e9}) {
            INFO("Y = " << y << ", Sc = " << sc);
            const tr::Image scaled = render(scene(sc), tr::Mode::Spacetime);
            CHECK(differing(unit, scaled, 0.05) <= unit.width * unit.height / 100);
        }
    }
}

// A scale of exactly 0, as POV-Ray 3.7 takes it: a constant factor 0 is
// warned about and becomes 1; a factor that passes through 0 is 1 at that
// instant (a frame POV-Ray renders there shows the object so) and itself at
// every other. Here the factor 2 clock - 1 is -1, 0 and 1 at the three
// frames' instants (shutter closed): each frame shows the plain sphere
// (a sphere mirrored in y is itself), in every mode.
TEST_CASE("a scale through zero keeps the object at every instant", "[robust]") {
    const std::string lights =
        "camera { location <0, 1, -5> look_at 0 }\n"
        "light_source { <-3, 5, -4>, rgb 1 }\n";
    const auto frames_of = [&](const std::string& object, tr::Mode mode) {
        hexant::language::ParseOptions options;
        options.animation.width = 48;
        options.animation.height = 32;
        options.animation.initial_frame = 1;
        options.animation.final_frame = 3;
        options.animation.shutter = 0.0;
        const auto scene =
            hexant::language::parse_scene_text(lights + object, "robust.pov", options);
        tr::RenderSettings settings;
        settings.mode = mode;
        tr::Renderer renderer(scene, settings);
        std::vector<tr::Image> images;
        for (int k = 1; k <= 3; ++k) images.push_back(renderer.render_frame(k));
        return images;
    };
    const auto plain = frames_of("sphere { 0, 1 pigment { rgb 0.8 } }\n", tr::Mode::Spacetime);
    for (const tr::Mode mode : {tr::Mode::Spacetime, tr::Mode::Frames, tr::Mode::Brute}) {
        const auto moving =
            frames_of("sphere { 0, 1 pigment { rgb 0.8 } scale <1, 2 * clock - 1, 1> }\n", mode);
        const auto constant =
            frames_of("sphere { 0, 1 pigment { rgb 0.8 } scale <1, 0, 1> }\n", mode);
        for (int k = 0; k < 3; ++k) {
            INFO("frame " << k + 1 << ", mode " << int(mode));
            // Tolerance 1e-6: the mirrored sphere's normals and points are
            // the plain one's up to rounding; a missing or flattened sphere
            // differs by the whole of its shading.
            CHECK(differing(plain[k], moving[k], 1e-6) == 0);
            CHECK(differing(plain[k], constant[k], 1e-6) == 0);
        }
    }
}

// POV-Ray lights a smooth triangle with its interpolated normal turned to
// face the ray by its own sign, whichever way the triangle winds (trace.cpp);
// hexant once fell back to the flat normal when the vertex normals faced
// away from the winding. So negating every vertex normal changes nothing.
// Tolerance 1e-6: the two renders differ only in the signs of the normals.
TEST_CASE("a smooth triangle shades alike whichever way its normals point", "[robust]") {
    const auto scene = [](double sign) {
        const auto n = [&](const char* v) { return "<" + std::string(v) + "> * " + number(sign); };
        return "camera { location <0, 3, -4> look_at 0 }\n"
               "light_source { <-2, 6, -3>, rgb 1 }\n"
               "smooth_triangle { <-2, 0, -1>, " +
               n("0.6, 1, 0") + ", <2, 0, -1>, " + n("-0.6, 1, 0") + ", <0, 0, 2>, " +
               n("0, 1, -0.5") + " pigment { rgb 0.8 } finish { phong 0.5 } }\n";
    };
    const tr::Image up = render(scene(1.0), tr::Mode::Spacetime);
    const tr::Image down = render(scene(-1.0), tr::Mode::Spacetime);
    CHECK(differing(up, down, 1e-6) == 0);
    // The shading does follow the normals: a flat triangle differs.
    const tr::Image flat = render(
        "camera { location <0, 3, -4> look_at 0 }\n"
        "light_source { <-2, 6, -3>, rgb 1 }\n"
        "triangle { <-2, 0, -1>, <2, 0, -1>, <0, 0, 2> pigment { rgb 0.8 }"
        " finish { phong 0.5 } }\n",
        tr::Mode::Spacetime);
    CHECK(differing(up, flat, 1e-3) > 100);
}

namespace {

// Every kind of object, one of them moving, with its camera and light, all
// scaled by sc about the origin.
std::string scaled_scene(double sc) {
    const std::string s = number(sc);
    return "camera { location <1, 3, -7> * " + s + " look_at <0, 0.5, 0> * " + s +
           " angle 45 }\n"
           "light_source { <-4, 8, -5> * " +
           s +
           ", rgb 1 }\n"
           "#declare Objects = union {\n"
           "  plane { y, 0 pigment { checker rgb 0.8, rgb 0.45 } }\n"
           "  sphere { <-1.5, 0.6, 0>, 0.6 pigment { rgb <1, 0.4, 0.2> } finish { phong 0.6 } "
           "}\n"
           "  box { <-0.4, 0, -0.4>, <0.4, 0.8, 0.4> rotate y * 30 translate <0, 0, 1.2> "
           "pigment { rgb <0.3, 0.6, 1> } }\n"
           "  cylinder { <1.2, 0, 0>, <1.2, 1.2, 0>, 0.3 pigment { rgb <0.4, 0.9, 0.4> } }\n"
           "  torus { 0.5, 0.15 translate <0, 0.15, -1.2> pigment { rgb 0.9 } }\n"
           "  triangle { <2, 0, 1>, <3, 0, 1>, <2.5, 1.2, 1.5> pigment { rgb <1, 1, 0.3> } }\n"
           "  sphere { 0, 0.3 translate <2 * clock - 1, 0.3, -2> pigment { rgb <0.9, 0.2, 0.9> "
           "} }\n"
           "}\n"
           "object { Objects scale " +
           s + " }\n";
}

}  // namespace

// A scene of every kind of object, one of them moving, with its camera and
// light, at world scales from 1e-6 to 1e9: each frame in each mode must
// match the scale-1 spacetime render. Tolerance as for the checker above
// (0.05 per channel, under 1% of pixels): rounding moves shading by about
// 1e-12 relative, while a lost surface, a false or lost shadow or a flipped
// checker changes a channel by 0.1 or more; only pixels whose sample lands
// within rounding of an outline or a cell edge may flip.
TEST_CASE("a scene renders alike at every world scale in every mode", "[robust]") {
    const auto unit = render_all(scaled_scene(1.0), tr::Mode::Spacetime, 2);
    for (const double sc : {1e-6, 1e-3, 1e3, 1e6, 1e9}) {
        for (const tr::Mode mode : {tr::Mode::Spacetime, tr::Mode::Frames, tr::Mode::Brute}) {
            const auto scaled = render_all(scaled_scene(sc), mode, 2);
            for (std::size_t k = 0; k < unit.size(); ++k) {
                INFO("Sc = " << sc << ", mode " << int(mode) << ", frame " << k + 1);
                CHECK(differing(unit[k], scaled[k], 0.05) <= unit[k].width * unit[k].height / 100);
            }
        }
    }
}

// The same scene scaled by powers of two, down to scales whose every length
// is below 1e-15 and up to 2^60: a power-of-two factor is exact in every
// coordinate, so a renderer with no absolute length in it (no epsilon, no
// fixed step off a surface) draws the same pixels bit for bit. A secondary
// ray's start once stepped a fixed 2^-45 off a surface near the origin:
// at 2^-50 the shadows were gone and spheres shadowed their own lower half.
// Tolerance zero, as the argument allows.
TEST_CASE("a scene scaled by a power of two renders the same pixels", "[robust]") {
    const auto unit = render_all(scaled_scene(1.0), tr::Mode::Spacetime, 2);
    for (const int e : {-100, -50, 40}) {
        for (const tr::Mode mode : {tr::Mode::Spacetime, tr::Mode::Brute}) {
            const auto scaled = render_all(scaled_scene(std::ldexp(1.0, e)), mode, 2);
            for (std::size_t k = 0; k < unit.size(); ++k) {
                INFO("scale 2^" << e << ", mode " << int(mode) << ", frame " << k + 1);
                CHECK(same_pixels(unit[k], scaled[k]));
            }
        }
    }
}

// A floor of one triangle whose vertices lie Half from the origin, a few
// units below the camera: at 1e15 it once drew nothing (the sign of a hit
// a few units away was lost in terms of 1e15), and at 1e16 its shading
// points were off by units, so shadow rays left from far off the floor.
// Beyond 1e12 the floor's part in view does not change, so every half
// must give the 1e12 image; tolerance 0.05 per channel, as above, with no
// pixel allowed over it (the rays and the shapes are the same to
// rounding; a missing floor or a false shadow differs by 0.5).
TEST_CASE("a floor of one triangle at 1e15 and beyond renders as at 1e12", "[robust]") {
    const auto scene = [](double half) {
        const std::string h = number(half);
        return "camera { location <0, 2, -5> look_at 0 }\n"
               "light_source { <3, 10, -5>, rgb 1 }\n"
               "triangle { <-" +
               h + ", -2, " + h + ">, <" + h + ", -2, " + h + ">, <0, -2, -" + h +
               "> pigment { rgb <0, 1, 0> } }\n"
               "sphere { 0, 1 pigment { rgb <1, 0, 0> } }\n"
               "background { rgb <1, 0, 1> }\n";
    };
    const tr::Image reference = render(scene(1e12), tr::Mode::Spacetime);
    for (const double half : {1e15, 1e16, 1e18}) {
        for (const tr::Mode mode : {tr::Mode::Spacetime, tr::Mode::Brute}) {
            INFO("Half = " << half << ", mode " << int(mode));
            CHECK(differing(reference, render(scene(half), mode), 0.05) == 0);
        }
    }
}
