// The renderer: the three modes make the same image of a moving scene; the
// image does not depend on the thread count; frames are written whole
// (temporary name, then rename) where the pattern says.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "tracer/image_output.hpp"
#include "tracer/renderer.hpp"
#include "tracer/whole_file.hpp"

// The scenes use POV-Ray 3.7's rules (without #version, POV-Ray reads a
// scene with its legacy gamma rule).
constexpr const char* kVersion37 = "#version 3.7;\n";

namespace tr = hexant::tracer;
namespace fs = std::filesystem;

namespace {

// Fast spinners, a box crossing the view, a moving light and camera, a
// mirror and a glass sphere: every kind of ray the shader casts.
const char* kScene = R"(
camera { location <0, 3, -8> look_at <0, 0.5, 0> angle 45 translate <clock, 0, 0> }
light_source { <-4 + 8 * clock, 8, -6>, rgb 1 }
light_source { <5, 4, -3>, rgb 0.3 shadowless }
background { rgb <0.1, 0.1, 0.2> }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.3 } }
#declare I = 0;
#while (I < 12)
  sphere { <1.5 + 0.1 * I, 0.4 + 0.15 * I, 0>, 0.2 rotate y * (360 * (1 + I) * clock + 30 * I)
           pigment { rgb <0.9, 0.3 + 0.05 * I, 0.2> } finish { phong 0.5 } }
  #declare I = I + 1;
#end
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> translate <-4 + 8 * clock, 0, 1> pigment { rgb <0.2, 0.5, 0.9> } }
sphere { <0, 1, 2>, 0.8 pigment { rgb 0.2 } finish { reflection 0.6 } }
sphere { <-1.5, 0.6, -1>, 0.6 pigment { rgbf <0.9, 1, 0.9, 0.9> } interior { ior 1.5 } }
)";

hexant::runtime::SceneDescription parse_scene() {
    hexant::language::ParseOptions options;
    options.animation.width = 40;
    options.animation.height = 30;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 4;
    return hexant::language::parse_scene_text(std::string(kVersion37) + kScene, "render-test.pov",
                                              options);
}

double largest_difference(const tr::Image& a, const tr::Image& b) {
    REQUIRE(a.rgb.size() == b.rgb.size());
    double d = 0.0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i)
        d = std::max(d, double(std::fabs(a.rgb[i] - b.rgb[i])));
    return d;
}

tr::Image render(const hexant::runtime::SceneDescription& scene, tr::Mode mode, int frame,
                 int threads = 0) {
    tr::RenderSettings settings;
    settings.mode = mode;
    settings.samples_per_pixel = 4;
    settings.threads = threads;
    tr::Renderer renderer(scene, settings);
    return renderer.render_frame(frame);
}

// A still of POV-Ray 3.7 text, 8 by 6.
hexant::runtime::SceneDescription small_scene(const std::string& text, const std::string& name) {
    hexant::language::ParseOptions options;
    options.animation.width = 8;
    options.animation.height = 6;
    return hexant::language::parse_scene_text(std::string(kVersion37) + text, name, options);
}

}  // namespace

TEST_CASE("spacetime, frames and brute force render the same images", "[tracer][render]") {
    const auto scene = parse_scene();
    for (const int frame : {1, 3}) {
        const tr::Image brute = render(scene, tr::Mode::Brute, frame);
        // Equal hits give equal colours; a tie between equal distances could
        // pick another object, which this scene does not have.
        CHECK(largest_difference(render(scene, tr::Mode::Spacetime, frame), brute) == 0.0);
        CHECK(largest_difference(render(scene, tr::Mode::Frames, frame), brute) == 0.0);
        // Not a blank image: the comparison means something.
        double sum = 0.0;
        for (float v : brute.rgb) sum += v;
        CHECK(sum > 0.1 * brute.rgb.size());
    }
}

TEST_CASE("a clock that runs backwards renders the same in the three modes", "[tracer][render]") {
    // --clock 1:0: the frames' shutters run from each clock down to the
    // next; the hierarchy spans the same time the other way (it spanned
    // none, and spacetime and frames modes drew nothing).
    hexant::language::ParseOptions options;
    options.animation.width = 40;
    options.animation.height = 30;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 4;
    options.animation.initial_clock = 1.0;
    options.animation.final_clock = 0.0;
    const auto scene = hexant::language::parse_scene_text(std::string(kVersion37) + kScene,
                                                          "render-test.pov", options);
    const tr::Image brute = render(scene, tr::Mode::Brute, 2);
    CHECK(largest_difference(render(scene, tr::Mode::Spacetime, 2), brute) == 0.0);
    CHECK(largest_difference(render(scene, tr::Mode::Frames, 2), brute) == 0.0);
    double sum = 0.0;
    for (float v : brute.rgb) sum += v;
    CHECK(sum > 0.1 * brute.rgb.size());
}

TEST_CASE("the image does not depend on the thread count", "[tracer][render]") {
    const auto scene = parse_scene();
    const tr::Image one = render(scene, tr::Mode::Spacetime, 2, 1);
    const tr::Image two = render(scene, tr::Mode::Spacetime, 2, 2);
    const tr::Image eight = render(scene, tr::Mode::Spacetime, 2, 8);
    CHECK(largest_difference(one, two) == 0.0);
    CHECK(largest_difference(one, eight) == 0.0);
}

TEST_CASE(
    "area lights, focal blur, a shaped rolling shutter and finite light: images independent of the "
    "thread count, "
    "the three modes agreeing",
    "[tracer][render]") {
    // Every dimension a sample draws (pixel, time, lens, each light's grid
    // point per depth) is a function of (frame, pixel, sample), and every
    // mode answers the same rays.
    hexant::language::ParseOptions options;
    options.animation.width = 32;
    options.animation.height = 24;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 3;
    options.animation.shutter_curve = hexant::runtime::ShutterCurve::parse("trapezoid");
    options.animation.rolling_shutter = 0.3;
    const auto scene = hexant::language::parse_scene_text(std::string(kVersion37) + R"(
camera { fisheye location <0, 2, -5> look_at <0, 0.5, 0> angle 120 aperture 0.6 blur_samples 10 focal_point <0, 0.5, 0> }
light_source { <-2 + 4 * clock, 5, -2>, rgb 1 area_light x, z, 4, 4 circular orient jitter }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.3 } }
sphere { <0, 0.6, 0>, 0.6 pigment { rgbf <0.9, 0.5, 0.3, 0.7> } interior { ior 1.3 } translate x * clock }
box { <-1.5, 0, 0.5>, <-0.8, 1, 1> rotate y * 90 * clock pigment { rgb <0.2, 0.5, 0.9> } finish { reflection 0.3 } }
)",
                                                          "joint-dimensions.pov", options);
    const auto image = [&](tr::Mode mode, int threads) {
        tr::RenderSettings settings;
        settings.mode = mode;
        settings.samples_per_pixel = 8;
        settings.threads = threads;
        settings.light_speed = 40.0;
        tr::Renderer renderer(scene, settings);
        return renderer.render_frame(2);
    };
    const tr::Image one = image(tr::Mode::Spacetime, 1);
    CHECK(largest_difference(one, image(tr::Mode::Spacetime, 2)) == 0.0);
    CHECK(largest_difference(one, image(tr::Mode::Spacetime, 8)) == 0.0);
    // (The modes: the same image, as above.)
    CHECK(largest_difference(one, image(tr::Mode::Frames, 2)) == 0.0);
    CHECK(largest_difference(one, image(tr::Mode::Brute, 2)) == 0.0);
}

TEST_CASE("motion blur: a sample's time is its own, within the frame's shutter",
          "[tracer][render]") {
    // A sphere crossing the whole view during frame 1's shutter leaves a
    // streak: many pixels partly covered; at shutter 0 it is a sharp disc.
    hexant::language::ParseOptions options;
    options.animation.width = 48;
    options.animation.height = 16;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 2;
    const char* text =
        "camera { location <0, 0, -10> look_at 0 }\n"
        "light_source { <0, 0, -10>, rgb 1 }\n"
        "sphere { <-4 + 8 * clock, 0, 0>, 0.8 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n";
    auto scene =
        hexant::language::parse_scene_text(std::string(kVersion37) + text, "blur.pov", options);
    const auto partial_pixels = [&](double shutter) {
        scene.animation.shutter = shutter;
        tr::RenderSettings settings;
        settings.samples_per_pixel = 16;
        tr::Renderer renderer(scene, settings);
        const tr::Image image = renderer.render_frame(1);
        int partial = 0;
        for (int x = 0; x < image.width; ++x) {
            const double v = image.at(x, image.height / 2).x;
            if (v > 0.05 && v < 0.95) ++partial;
        }
        return partial;
    };
    CHECK(partial_pixels(0.0) <= 4);   // the disc's two edges, antialiased
    CHECK(partial_pixels(1.0) >= 20);  // a streak over half the width
}

TEST_CASE("frames are written whole where the pattern says", "[tracer][render]") {
    CHECK(tr::frame_path("out/a/frame_####.png", 7) == "out/a/frame_0007.png");
    CHECK(tr::frame_path("f##.exr", 123) == "f123.exr");
    CHECK(tr::frame_path("still.png", 3) == "still.png");
    const fs::path folder = fs::temp_directory_path() / "hexant_render_test";
    fs::remove_all(folder);
    tr::Image image(8, 4);
    image.set(1, 1, {1.0, 0.5, 0.25});
    tr::write_image(image, folder / "deep/er/f.png");
    tr::write_image(image, folder / "f.exr");
    CHECK(fs::exists(folder / "deep/er/f.png"));
    CHECK(fs::exists(folder / "f.exr"));
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        CHECK(entry.path().string().find(".partial") == std::string::npos);
    // A name no format knows is an error naming the file, and leaves nothing.
    CHECK_THROWS_WITH(tr::write_image(image, folder / "f.unknown"), Catch::Contains("f.unknown"));
    CHECK_FALSE(fs::exists(folder / "f.unknown"));
    // Contact sheets read like a book.
    tr::Image a(2, 2), b(2, 2), c(2, 2);
    b.set(0, 0, {1, 0, 0});
    c.set(0, 0, {0, 1, 0});
    const tr::Image sheet = tr::contact_sheet({a, b, c}, 2);
    CHECK(sheet.width == 4);
    CHECK(sheet.height == 4);
    CHECK(sheet.at(2, 0).x == 1.0);  // second frame: top right
    CHECK(sheet.at(0, 2).y == 1.0);  // third frame: next row, left
    // The default grid is full when a nearly square one exists, else square.
    const auto grid = [](int n) {
        const tr::Image s = tr::contact_sheet(std::vector<tr::Image>(n, tr::Image(1, 1)));
        return std::pair{s.width, s.height};
    };
    CHECK(grid(64) == std::pair{8, 8});
    CHECK(grid(32) == std::pair{8, 4});
    CHECK(grid(16) == std::pair{4, 4});
    CHECK(grid(3) == std::pair{3, 1});
    CHECK(grid(7) == std::pair{3, 3});
    CHECK(tr::to_srgb8(0.0) == 0);
    CHECK(tr::to_srgb8(1.0) == 255);
    CHECK(tr::to_srgb8(0.5) == 188);
    fs::remove_all(folder);
}

TEST_CASE("text files are written whole or not at all", "[tracer][render]") {
    const fs::path folder = fs::temp_directory_path() / "hexant_whole_file_test";
    fs::remove_all(folder);
    tr::write_text_file(folder / "a/table.csv", "x,y\n1,2\n");
    std::ifstream in(folder / "a/table.csv");
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    CHECK(text == "x,y\n1,2\n");
    // Replacing a file replaces it whole.
    tr::write_text_file(folder / "a/table.csv", "z\n");
    std::ifstream again(folder / "a/table.csv");
    CHECK(std::string{std::istreambuf_iterator<char>(again), std::istreambuf_iterator<char>()} ==
          "z\n");
    // A place that cannot take the file (a folder of that name) is an error
    // naming it, and leaves no partial file behind.
    fs::create_directories(folder / "taken");
    fs::create_directories(folder / "taken/inside");
    CHECK_THROWS_WITH(tr::write_text_file(folder / "taken", "x"), Catch::Contains("taken"));
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        CHECK(entry.path().string().find(".partial") == std::string::npos);
}

TEST_CASE("a parallel light pointed at itself lights nothing, as in POV-Ray", "[tracer][render]") {
    // Its direction (point_at - location) is zero: no surface faces it.
    // (With point_at elsewhere the same ball is lit: the check is not
    // blind.)
    const auto lit = [](const std::string& point_at) {
        const auto scene = small_scene(
            "camera { location <0, 2, -4> look_at 0 }\n"
            "light_source { <0, 5, 0>, rgb 1 parallel point_at " +
                point_at +
                " }\n"
                "sphere { 0, 1 pigment { rgb 1 } finish { ambient 0 } }\n",
            "parallel.pov");
        double sum = 0.0;
        for (float v : render(scene, tr::Mode::Spacetime, 1).rgb) sum += v;
        return sum;
    };
    CHECK(lit("<0, 5, 0>") == 0.0);
    CHECK(lit("<0, 0, 0>") > 1.0);
}

TEST_CASE("crand takes a random fraction of each light's diffuse intensity, as in POV-Ray",
          "[tracer][render]") {
    // A white wall facing the camera and a parallel light along the view:
    // diffuse 0.8 at full cosine, less u * crand with u uniform on [0, 1)
    // per sample and light (POV-Ray's ComputeDiffuseColour): 0.6 on
    // average. Without jitter the draw is the middle, exactly the mean.
    const auto image = [](const std::string& finish, int spp, bool jitter) {
        const auto scene = small_scene(
            "camera { orthographic location <0, 0, -4> look_at 0 }\n"
            "light_source { <0, 0, -10>, rgb 1 parallel point_at 0 }\n"
            "plane { -z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.8 " +
                finish + " } }\n",
            "crand.pov");
        tr::RenderSettings settings;
        settings.samples_per_pixel = spp;
        settings.jitter = jitter;
        tr::Renderer renderer(scene, settings);
        return renderer.render_frame(1);
    };
    const auto range = [](const tr::Image& im) {
        const auto [lo, hi] = std::minmax_element(im.rgb.begin(), im.rgb.end());
        double sum = 0.0;
        for (float v : im.rgb) sum += v;
        return std::array<double, 3>{*lo, *hi, sum / double(im.rgb.size())};
    };
    const auto plain = range(image("", 1, false));
    CHECK(plain[0] == Approx(0.8));
    CHECK(plain[1] == Approx(0.8));
    const auto middle = range(image("crand 0.4", 1, false));
    CHECK(middle[0] == Approx(0.6));
    CHECK(middle[1] == Approx(0.6));
    // Jittered, each pixel averages its own draws: grainy, 0.6 on average.
    const auto grainy = range(image("crand 0.4", 16, true));
    CHECK(grainy[1] - grainy[0] > 0.005);
    CHECK(grainy[2] == Approx(0.6).margin(0.01));
}

TEST_CASE("a surface through the light itself casts no shadow from it, as in POV-Ray",
          "[tracer][render]") {
    // A light set exactly on a ceiling (radiosity/cornell.pov's: its lights
    // at the ceiling's height) lights the floor below: POV-Ray counts a
    // blocker only short of the light. Before, the ceiling's hit at the
    // light's own distance shadowed part of each light's rays, by its
    // rounding (cornell's walls 1.46 x darker than POV-Ray's). The image
    // with the ceiling is the image with a ceiling that casts no shadow;
    // a ceiling a little below the light darkens the floor (not blind).
    const auto image = [](double ceiling, const char* flags) {
        const std::string y = std::to_string(ceiling);
        const auto scene = small_scene(
            "camera { location <0, 1, -4> look_at 0 }\n"
            "light_source { <0.3, 3, 0.7>, rgb 1 }\n"
            "triangle { <-20, " +
                y + ", -20>, <20, " + y + ", -20>, <0, " + y + ", 20> pigment { rgb 1 } " + flags +
                " }\n"
                "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n",
            "ceiling.pov");
        return render(scene, tr::Mode::Spacetime, 1);
    };
    CHECK(largest_difference(image(3.0, ""), image(3.0, "no_shadow")) == 0.0);
    CHECK(largest_difference(image(2.999, ""), image(2.999, "no_shadow")) > 0.1);
}
