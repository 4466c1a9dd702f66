// `hexant render` as a user meets it: frames where -o says, the stats rows,
// and clear errors (naming the flag or the place) with nothing half-written.
#include "app/render_command.hpp"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <catch2/catch.hpp>
#include <sys/stat.h>

namespace fs = std::filesystem;
using hexant::app::RenderArguments;
using hexant::app::run_render;

namespace {

// A folder per test case: ctest runs the cases as parallel processes, and
// cases sharing one scene file overwrote each other's scene mid-run.
fs::path scene_file(const std::string& text) {
    std::string name = Catch::getResultCapture().getCurrentTestName();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    const fs::path folder = fs::temp_directory_path() / "hexant_render_command_test" / name;
    fs::create_directories(folder);
    const fs::path path = folder / "scene.pov";
    std::ofstream(path) << text;
    return path;
}

// An empty output folder beside the test case's scene.
fs::path fresh_output(const fs::path& scene) {
    const fs::path out = scene.parent_path() / "out";
    fs::remove_all(out);
    return out;
}

// A sphere moving along x as the clock runs, lit and seen from the front.
std::string moving_sphere(const std::string& centre) {
    return "camera { location <0, 0, -5> look_at 0 }\nlight_source { <0, 5, -5>, rgb 1 }\n"
           "sphere { " +
           centre + ", 1 pigment { rgb 1 } }\n";
}

RenderArguments arguments_for(const fs::path& scene, const fs::path& out) {
    RenderArguments a;
    a.scene.files = {scene.string()};
    a.scene.width = 16;
    a.scene.height = 12;
    a.scene.frame_count = 3;
    a.output = (out / "f_##.png").string();
    a.samples_per_pixel = 1;  // (the default samples adaptively: a test below)
    return a;
}

}  // namespace

TEST_CASE("render writes the frames, the contact sheet and the table rows", "[app][render]") {
    const fs::path scene = scene_file(moving_sphere("<clock, 0, 0>"));
    const fs::path out = fresh_output(scene);
    RenderArguments a = arguments_for(scene, out);
    a.frames = "2:3";
    a.contact_sheet = (out / "sheet.png").string();
    a.compare = true;
    a.stats_json = (out / "stats.json").string();
    std::ostringstream stdout_text, stderr_text;
    REQUIRE(run_render(a, stdout_text, stderr_text) == 0);
    INFO(stderr_text.str());
    CHECK_FALSE(fs::exists(out / "f_01.png"));
    CHECK(fs::exists(out / "f_02.png"));
    CHECK(fs::exists(out / "f_03.png"));
    CHECK(fs::exists(out / "sheet.png"));
    const std::string text = stdout_text.str();
    CHECK(text.find("ray/object tests per ray") != std::string::npos);
    CHECK(text.find("spacetime") != std::string::npos);
    CHECK(text.find("ratio") != std::string::npos);
    // The same figures for tools: one object per mode, the rows as keys.
    std::ifstream json(out / "stats.json");
    const std::string stats((std::istreambuf_iterator<char>(json)),
                            std::istreambuf_iterator<char>());
    CHECK(stats.find("\"frames\": {") != std::string::npos);
    CHECK(stats.find("\"spacetime\": {") != std::string::npos);
    CHECK(stats.find("\"primary rays\": 384") != std::string::npos);  // 2 frames of 16 x 12
}

TEST_CASE("render counts a full build's cells only with --stats-full or --compare",
          "[app][render]") {
    const fs::path scene = scene_file(moving_sphere("<clock, 0, 0>"));
    const fs::path out = fresh_output(scene);
    for (const bool full : {false, true}) {
        RenderArguments a = arguments_for(scene, out);
        a.stats = true;
        a.stats_full = full;
        a.stats_json = (out / "stats.json").string();
        std::ostringstream o, e;
        REQUIRE(run_render(a, o, e) == 0);
        INFO(o.str() << e.str());
        // (The count after the render costs about as much as the render on
        // a large scene: "-" in the table, null in the JSON, without it.)
        const std::string text = o.str();
        const auto row = text.find("cells of a full build");
        REQUIRE(row != std::string::npos);
        const std::string line = text.substr(row, text.find('\n', row) - row);
        CHECK((line.find('-') != std::string::npos) == !full);
        std::ifstream json(out / "stats.json");
        const std::string stats((std::istreambuf_iterator<char>(json)),
                                std::istreambuf_iterator<char>());
        CHECK((stats.find("\"cells of a full build\": null") != std::string::npos) == !full);
    }
}

TEST_CASE("render takes a list of frames", "[app][render]") {
    const fs::path scene = scene_file(moving_sphere("<clock, 0, 0>"));
    const fs::path out = fresh_output(scene);
    RenderArguments a = arguments_for(scene, out);
    a.scene.frame_count = 5;
    a.frames = "4,1,4:5";
    std::ostringstream o, e;
    REQUIRE(run_render(a, o, e) == 0);
    CHECK(fs::exists(out / "f_01.png"));
    CHECK_FALSE(fs::exists(out / "f_02.png"));
    CHECK_FALSE(fs::exists(out / "f_03.png"));
    CHECK(fs::exists(out / "f_04.png"));
    CHECK(fs::exists(out / "f_05.png"));
    CHECK(o.str().find("frames 1, 4, 5:") != std::string::npos);
    for (const char* bad : {"1,", "1;3", "2:x", "3:1", "1,9", ":2"}) {
        a.frames = bad;
        e.str("");
        CHECK(run_render(a, o, e) != 0);
        CHECK(e.str().find("--frames") != std::string::npos);
    }
    a.frames = "3:1";
    e.str("");
    CHECK(run_render(a, o, e) != 0);
    CHECK(e.str().find("3:1 runs backwards") != std::string::npos);
}

TEST_CASE("render reports bad requests clearly and writes nothing", "[app][render]") {
    const fs::path scene = scene_file("sphere { 0, 1 }\n");
    const fs::path out = fresh_output(scene);
    // A request changed from the defaults fails, its error saying `says`.
    const auto refused = [&](const fs::path& file, const auto& change, const std::string& says) {
        RenderArguments a = arguments_for(file, out);
        change(a);
        std::ostringstream o, e;
        CHECK(run_render(a, o, e) != 0);
        INFO(e.str());
        CHECK(e.str().find(says) != std::string::npos);
    };
    refused(
        scene, [](RenderArguments& a) { a.frames = "2:9"; }, "--frames 2:9");
    refused(
        scene, [&](RenderArguments& a) { a.output = (out / "same_name.png").string(); }, "####");
    refused(
        scene, [&](RenderArguments& a) { a.output = (out / "a_##_b_####.png").string(); },
        "one run of # is the frame number");
    refused(
        scene, [](RenderArguments& a) { a.mode = "fast"; }, "fast");
    // A name of no image format is refused before the first frame.
    refused(
        scene, [&](RenderArguments& a) { a.output = (out / "f_##.webp").string(); },
        "f_##.webp: no image format");
    refused(
        scene, [&](RenderArguments& a) { a.animation = (out / "movie.mp4").string(); },
        "movie.mp4: an animation is written as .gif");
    // Outputs that would overwrite each other, and a GIF too wide for its
    // 16-bit sides, are refused before the first frame too.
    refused(
        scene,
        [&](RenderArguments& a) {
            a.output = (out / "f_##.png").string();
            a.contact_sheet = (out / "f_01.png").string();
        },
        "f_01.png: --contact-sheet names frame 1's file");
    refused(
        scene,
        [&](RenderArguments& a) {
            a.scene.width = 70000;
            a.scene.height = 1;
            a.animation = (out / "wide.gif").string();
        },
        "a GIF is at most 65535 pixels a side");
    // A scene error names its place.
    refused(
        scene_file("sphere { 0, 1 \n"), [](RenderArguments&) {}, "scene.pov:");
    CHECK_FALSE(fs::exists(out));
}

TEST_CASE("render --seed gives an independent estimate of the same frame", "[app][render]") {
    const fs::path scene = scene_file(moving_sphere("<2 * clock, 0, 0>"));
    const fs::path out = fresh_output(scene);
    const auto render = [&](unsigned seed, const std::string& name) {
        RenderArguments a = arguments_for(scene, out);
        a.frames = "2";
        a.samples_per_pixel = 2;
        a.seed = seed;
        a.output = (out / name).string();
        std::ostringstream o, e;
        REQUIRE(run_render(a, o, e) == 0);
        std::ifstream in(out / name, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    const std::string first = render(0, "a.png"), again = render(0, "b.png");
    const std::string other = render(7, "c.png");
    CHECK(first == again);  // deterministic
    CHECK(first != other);  // other samples where the sphere blurs
}

TEST_CASE("MegaPOV's motion_blur sets the defaults of --spp and --shutter, and says so",
          "[app][render]") {
    // real-animation case 17: global_settings { motion_blur SAMPLES, TIME }.
    // Three frames over clock 0 to 1 step by 0.5: TIME 0.1 is a shutter
    // of 0.2 of the step; the flags given win.
    const fs::path scene =
        scene_file("global_settings { motion_blur 8, 0.1 }\n" + moving_sphere("<2 * clock, 0, 0>"));
    const fs::path out = fresh_output(scene);
    RenderArguments a = arguments_for(scene, out);
    a.frames = "1";
    a.samples_per_pixel.reset();
    std::ostringstream o, e;
    REQUIRE(run_render(a, o, e) == 0);
    CHECK(e.str().find("MegaPOV's motion_blur 8, 0.1") != std::string::npos);
    CHECK(e.str().find("--spp 8 --shutter 0.2 by default") != std::string::npos);
    // The same frame with those flags given is the same image.
    RenderArguments b = arguments_for(scene, out);
    b.frames = "1";
    b.samples_per_pixel = 8;
    b.scene.shutter = 0.2;
    b.output = (out / "g_##.png").string();
    std::ostringstream o2, e2;
    REQUIRE(run_render(b, o2, e2) == 0);
    const auto bytes = [](const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    CHECK(bytes(out / "f_01.png") == bytes(out / "g_01.png"));
    CHECK(e2.str().find("--spp") == std::string::npos);
}

TEST_CASE("render estimates each frame's error and writes its error image",
          "[app][render][estimate]") {
    const fs::path scene = scene_file(moving_sphere("<2 * clock - 1, 0, 0>"));
    const fs::path out = fresh_output(scene);
    RenderArguments a = arguments_for(scene, out);
    a.samples_per_pixel = 4;
    a.error_image = (out / "err_##.png").string();
    std::ostringstream stdout_text, stderr_text;
    REQUIRE(run_render(a, stdout_text, stderr_text) == 0);
    const std::string said = stderr_text.str();
    INFO(said);
    CHECK(said.find("frame 1: ") != std::string::npos);
    CHECK(said.find("frame 3: ") != std::string::npos);
    CHECK(said.find("estimated RMSE") != std::string::npos);
    CHECK(fs::exists(out / "err_01.png"));
    CHECK(fs::exists(out / "err_03.png"));
    // One sample has no blocks to compare: refused before anything is
    // written. (An odd count of 2 or more estimates as any other.)
    const fs::path none = fresh_output(scene);
    RenderArguments single = arguments_for(scene, none);
    single.samples_per_pixel = 1;
    single.error_estimate = true;
    std::ostringstream o, e;
    CHECK(run_render(single, o, e) != 0);
    CHECK(e.str().find("a --spp of 2 or more") != std::string::npos);
    CHECK_FALSE(fs::exists(none / "f_01.png"));
    // The error images may not take the frames' names, nor lack the number.
    RenderArguments same = arguments_for(scene, none);
    same.samples_per_pixel = 2;
    same.error_image = same.output;
    std::ostringstream o2, e2;
    CHECK(run_render(same, o2, e2) != 0);
    CHECK(e2.str().find("--error-image names frame 1") != std::string::npos);
    same.error_image = (none / "e.png").string();
    std::ostringstream o3, e3;
    CHECK(run_render(same, o3, e3) != 0);
    CHECK(e3.str().find("--error-image") != std::string::npos);
    CHECK_FALSE(fs::exists(none / "f_01.png"));
}

TEST_CASE("render samples adaptively to a target error, and by default",
          "[app][render][adaptive]") {
    const fs::path scene = scene_file(moving_sphere("<2 * clock - 1, 0, 0>"));
    const fs::path out = fresh_output(scene);
    RenderArguments a = arguments_for(scene, out);
    a.samples_per_pixel = 64;
    a.target_error = 0.02;
    a.samples_image = (out / "n_##.png").string();
    a.stats_json = (out / "stats.json").string();
    std::ostringstream stdout_text, stderr_text;
    REQUIRE(run_render(a, stdout_text, stderr_text) == 0);
    const std::string said = stderr_text.str();
    INFO(said);
    CHECK(said.find("frame 2: ") != std::string::npos);
    CHECK(said.find("samples per pixel, estimated RMSE") != std::string::npos);
    CHECK(fs::exists(out / "n_01.png"));
    CHECK(fs::exists(out / "n_03.png"));
    // Each frame in the JSON, under keys no row has.
    std::ifstream json(out / "stats.json");
    const std::string stats((std::istreambuf_iterator<char>(json)),
                            std::istreambuf_iterator<char>());
    CHECK(stats.find("\"per frame\": [") != std::string::npos);
    CHECK(stats.find("{\"frame\": 3, \"seconds\": ") != std::string::npos);
    CHECK(stats.find("\"estimated rmse\": ") != std::string::npos);
    CHECK(stats.find("\"worst tiles\": [{\"x\": 0, \"y\": 0, \"rmse\": ") != std::string::npos);

    // Without --spp: the default target under the default ceiling; with
    // --no-jitter, one sample at each pixel's centre as before.
    hexant::runtime::SceneDescription parsed;
    RenderArguments plain;
    const auto s = hexant::app::resolve_sampling(plain, parsed);
    CHECK(s.target_error == hexant::app::kDefaultTargetError);
    CHECK(s.samples == hexant::app::kDefaultCeiling);
    plain.no_jitter = true;
    CHECK(hexant::app::resolve_sampling(plain, parsed).samples == 1);
    CHECK(hexant::app::resolve_sampling(plain, parsed).target_error == 0.0);
    // A scene's own count (MegaPOV's motion_blur) is uniform sampling.
    plain.no_jitter = false;
    parsed.global.motion_blur_samples = 5;
    CHECK(hexant::app::resolve_sampling(plain, parsed).samples == 5);
    CHECK(hexant::app::resolve_sampling(plain, parsed).target_error == 0.0);

    // A target needs a ceiling of 2 or more and jitter: refused before
    // anything is written, naming the flag. An odd one is fine.
    const fs::path none = fresh_output(scene);
    RenderArguments single = arguments_for(scene, none);
    single.samples_per_pixel = 1;
    single.target_error = 0.01;
    std::ostringstream o, e;
    CHECK(run_render(single, o, e) != 0);
    CHECK(e.str().find("--target-error needs a --spp of 2 or more") != std::string::npos);
    single.samples_per_pixel = 9;
    CHECK(hexant::app::resolve_sampling(single, parsed).target_error == 0.01);
    // The samples image may not take the error image's names.
    RenderArguments clash = arguments_for(scene, none);
    clash.samples_per_pixel = 4;
    clash.error_image = (none / "e_##.png").string();
    clash.samples_image = clash.error_image;
    std::ostringstream o2, e2;
    CHECK(run_render(clash, o2, e2) != 0);
    CHECK(e2.str().find("--samples-image names --error-image's file for frame 1") !=
          std::string::npos);
    CHECK_FALSE(fs::exists(none / "f_01.png"));
}

TEST_CASE("render's adaptive flags refuse what makes no sense, naming the flag",
          "[app][render][adaptive]") {
    using hexant::app::parse_target_error;
    CHECK(parse_target_error("0.01") == 0.01);
    CHECK(parse_target_error("1/128") == 1.0 / 128.0);
    for (const char* bad :
         {"nan", "-nan", "inf", "0", "-1", "abc", "1/0", "0.01x", "", "1/", "0x10"})
        CHECK_THROWS_WITH(parse_target_error(bad), Catch::Contains("--target-error"));

    const fs::path scene = scene_file(moving_sphere("<2 * clock - 1, 0, 0>"));
    const fs::path out = fresh_output(scene);
    const auto refused = [&](const std::function<void(RenderArguments&)>& change,
                             const std::string& says) {
        RenderArguments a = arguments_for(scene, out);
        a.samples_per_pixel = 4;
        change(a);
        std::ostringstream o, e;
        CHECK(run_render(a, o, e) != 0);
        INFO(e.str());
        CHECK(e.str().find(says) != std::string::npos);
        CHECK_FALSE(fs::exists(out / "f_01.png"));
    };
    // No output may take another's file, whatever its kind.
    refused(
        [&](RenderArguments& a) {
            a.frames = "1";
            a.samples_image = (out / "sheet.png").string();
            a.contact_sheet = (out / "sheet.png").string();
        },
        "--contact-sheet names --samples-image's file for frame 1");
    refused([&](RenderArguments& a) { a.stats_json = (out / "f_02.png").string(); },
            "--stats-json names frame 2's file");
    refused(
        [&](RenderArguments& a) {
            a.error_image = (out / "e_##.png").string();
            a.stats_json = (out / "e_03.png").string();
        },
        "--stats-json names --error-image's file for frame 3");
    // A name of no format or an empty one says which flag it was.
    refused([&](RenderArguments& a) { a.samples_image = (out / "s_##.jpg").string(); },
            "--samples-image ");
    refused([&](RenderArguments& a) { a.stats_json = ""; }, "--stats-json: an empty file name");
    // A folder that cannot be made fails before the first frame.
    const fs::path plain = scene.parent_path() / "plain.txt";
    std::ofstream(plain) << "a file, not a folder\n";
    refused([&](RenderArguments& a) { a.samples_image = (plain / "s_##.png").string(); },
            "cannot write in");
    CHECK_FALSE(fs::exists(out));  // (and nothing made on the way)
    // A frame taller than its format allows is refused before it is
    // rendered, not after (issue 45: libpng refused the IHDR of a 1 by 10^8
    // frame once it was done); a contact sheet by its grid's size.
    refused(
        [&](RenderArguments& a) {
            a.scene.width = 1;
            a.scene.height = 2000000;
        },
        "a PNG is at most 1000000 pixels a side; the image is 1 by 2000000");
    refused(
        [&](RenderArguments& a) {
            a.scene.width = 600000;
            a.scene.height = 1;
            a.frames = "1:3";
            a.contact_sheet = (out / "sheet.png").string();
        },
        "sheet.png: a PNG is at most 1000000 pixels a side; the image is 1800000 by 1");
    // An output in the place of a link or a device is refused before the
    // first frame, and the link is left as it was (issue 45).
    const fs::path victim = scene.parent_path() / "victim.json";
    std::ofstream(victim) << "not yours";
    const fs::path link = scene.parent_path() / "link.json";
    fs::remove(link);
    fs::create_symlink(victim, link);
    refused([&](RenderArguments& a) { a.stats_json = link.string(); }, "a symbolic link");
    // (A FIFO stands for a device: a test that went wrong must not replace
    // the machine's /dev/null.)
    const fs::path fifo = scene.parent_path() / "fifo.json";
    fs::remove(fifo);
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    refused([&](RenderArguments& a) { a.stats_json = fifo.string(); }, "a FIFO");
    CHECK(fs::is_fifo(fifo));
    CHECK(fs::is_symlink(link));
    std::ifstream back(victim);
    CHECK(std::string((std::istreambuf_iterator<char>(back)), std::istreambuf_iterator<char>()) ==
          "not yours");
    // The default ceiling is named as such.
    refused(
        [&](RenderArguments& a) {
            a.samples_per_pixel.reset();
            a.no_jitter = true;
            a.target_error = 0.01;
        },
        "the default ceiling is 256, with --no-jitter");
}

TEST_CASE("no output replaces one of the scene's own inputs", "[app][render]") {
    // (issue 45) -o, --contact-sheet, --animation or --stats-json naming
    // the scene's image_map, an include or the scene itself overwrote it.
    const fs::path scene = scene_file(
        "#include \"parts.inc\"\ncamera { location <0, 0, -5> look_at 0 }\n"
        "light_source { <0, 5, -5>, rgb 1 }\nsphere { 0, 1 pigment { image_map { "
        "png \"tex.png\" } } }\n");
    const fs::path folder = scene.parent_path();
    std::ofstream(folder / "parts.inc") << "#declare Parts = 1;\n";
    {
        // A 1 by 1 PNG, written by a render of its own.
        const fs::path plain = folder / "plain.pov";
        std::ofstream(plain) << moving_sphere("0");
        RenderArguments a;
        a.scene.files = {plain.string()};
        a.scene.width = a.scene.height = 1;
        a.samples_per_pixel = 1;
        a.output = (folder / "tex.png").string();
        std::ostringstream o, e;
        REQUIRE(run_render(a, o, e) == 0);
    }
    const auto bytes = [](const fs::path& file) {
        std::ifstream in(file, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    const std::string texture = bytes(folder / "tex.png"), include = bytes(folder / "parts.inc"),
                      text = bytes(scene);
    const fs::path ini = folder / "scene.ini";
    std::ofstream(ini) << "Width=16\n";
    const auto refused = [&](const std::function<void(RenderArguments&)>& change,
                             const std::string& input) {
        RenderArguments a = arguments_for(scene, fresh_output(scene));
        a.scene.files.push_back(ini.string());
        a.frames = "1";
        change(a);
        std::ostringstream o, e;
        CHECK(run_render(a, o, e) == 1);
        INFO(e.str());
        CHECK(e.str().find("is one of the scene's inputs (" + fs::canonical(input).string()) !=
              std::string::npos);
    };
    refused([&](RenderArguments& a) { a.output = (folder / "tex.png").string(); },
            folder / "tex.png");
    refused([&](RenderArguments& a) { a.contact_sheet = (folder / "." / "tex.png").string(); },
            folder / "tex.png");
    refused([&](RenderArguments& a) { a.stats_json = (folder / "parts.inc").string(); },
            folder / "parts.inc");
    refused([&](RenderArguments& a) { a.stats_json = scene.string(); }, scene);
    refused([&](RenderArguments& a) { a.stats_json = ini.string(); }, ini);
    // The same file by another name (a hard link) is the same input.
    fs::remove(folder / "hard.png");
    fs::create_hard_link(folder / "tex.png", folder / "hard.png");
    refused([&](RenderArguments& a) { a.contact_sheet = (folder / "hard.png").string(); },
            folder / "tex.png");
    CHECK(bytes(folder / "tex.png") == texture);
    CHECK(bytes(folder / "parts.inc") == include);
    CHECK(bytes(scene) == text);
}

TEST_CASE(
    "render says when tiles reach the ceiling above the target, and its JSON holds no infinity",
    "[app][render][adaptive]") {
    // Colours that overflow the estimate: JSON has no inf, so null.
    const fs::path scene = scene_file(
        "camera { location <0, 0, -5> look_at 0 }\nbackground { rgb 1e300 }\n"
        "sphere { <2 * clock - 1, 0, 0>, 1 pigment { rgb 0 } }\n");
    const fs::path out = fresh_output(scene);
    RenderArguments a = arguments_for(scene, out);
    a.frames = "2";
    a.samples_per_pixel = 8;
    a.target_error = 1e-9;
    a.stats_json = (out / "stats.json").string();
    std::ostringstream o, e;
    REQUIRE(run_render(a, o, e) == 0);
    INFO(e.str());
    CHECK(e.str().find("tiles reached --spp 8 above the target") != std::string::npos);
    std::ifstream json(out / "stats.json");
    const std::string stats((std::istreambuf_iterator<char>(json)),
                            std::istreambuf_iterator<char>());
    CHECK(stats.find("inf") == std::string::npos);
    CHECK(stats.find("\"estimated rmse\": null") != std::string::npos);
    CHECK(stats.find("\"tiles over target\": ") != std::string::npos);
}
