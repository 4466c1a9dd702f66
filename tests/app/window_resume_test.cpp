// An animation rendered as time windows (render --window I/N), each with a
// hierarchy over its own time, writes the very bytes one run over all
// frames writes; --resume after a SIGKILL at any moment loses no frame,
// renders none twice and leaves no temporary.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <unistd.h>

#include "app/render_command.hpp"

namespace fs = std::filesystem;
using hexant::app::RenderArguments;
using hexant::app::run_render;
using hexant::app::window_frames;

namespace {

// Moving spheres, a moving light, a mirror: motion blur and secondary
// rays in every frame, adaptive sampling (the default) deciding per tile.
const char* kScene = R"(
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <-3 + 6 * clock, 5, -4>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.3 } }
#declare I = 0;
#while (I < 6)
  sphere { <-2.5 + I, 0.4 + 0.3 * sin(2 * pi * (clock + I / 6)), 0>, 0.35
           pigment { rgb <0.9, 0.2 + 0.1 * I, 0.3> } translate z * clock }
  #declare I = I + 1;
#end
sphere { <0, 1, 2>, 0.8 pigment { rgb 0.2 } finish { reflection 0.5 } }
)";

fs::path folder_for(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / "hexant_window_resume_test" / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ofstream(folder / "scene.pov") << kScene;
    return folder;
}

RenderArguments arguments(const fs::path& folder, const std::string& out) {
    RenderArguments a;
    a.scene.files = {(folder / "scene.pov").string()};
    a.scene.width = 40;
    a.scene.height = 30;
    a.scene.frame_count = 12;
    a.output = (folder / out / "f_####.png").string();
    return a;
}

std::string bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int render(const RenderArguments& a) {
    std::ostringstream out, err;
    const int rc = run_render(a, out, err);
    INFO(out.str() << err.str());
    return rc;
}

// Every frame of `a_dir` equals the same frame of `b_dir`, byte for byte,
// and neither holds anything else (no temporary) than the frames and their
// records (.hexant/NAME.json, app/frame_record.hpp).
void check_same_frames(const fs::path& a_dir, const fs::path& b_dir, int frames) {
    for (int k = 1; k <= frames; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "f_%04d.png", k);
        INFO("frame " << k);
        REQUIRE(fs::exists(a_dir / name));
        REQUIRE(fs::exists(b_dir / name));
        CHECK(bytes(a_dir / name) == bytes(b_dir / name));
        CHECK(fs::exists(b_dir / ".hexant" / (std::string(name) + ".json")));
    }
    CHECK(std::distance(fs::directory_iterator(b_dir), fs::directory_iterator()) == frames + 1);
    CHECK(std::distance(fs::directory_iterator(b_dir / ".hexant"), fs::directory_iterator()) ==
          frames);
}

}  // namespace

TEST_CASE("windows split the frames evenly, in order, and refuse what is not I/N",
          "[app][window]") {
    const std::vector<int> frames{1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
    std::vector<int> joined;
    for (int i = 0; i < 3; ++i) {
        const auto w = window_frames(std::to_string(i) + "/3", frames);
        CHECK((w.size() == 3 || w.size() == 4));
        joined.insert(joined.end(), w.begin(), w.end());
    }
    CHECK(joined == frames);
    CHECK(window_frames("0/1", frames) == frames);
    // More windows than frames: some are empty, none overlaps.
    std::size_t total = 0;
    for (int i = 0; i < 16; ++i) total += window_frames(std::to_string(i) + "/16", frames).size();
    CHECK(total == frames.size());
    for (const char* bad :
         {"3/3", "-1/3", "1/0", "1", "a/b", "1/3x", "1/ 3/", " 1/3", "+1/3", "1/3 "})
        CHECK_THROWS_WITH(window_frames(bad, frames), Catch::Contains("--window"));
    // (Found by a fresh user: I K overflowed 64 bits, losing the last frame.)
    CHECK(window_frames("99999999999999998/99999999999999999", frames) == std::vector<int>{10});
}

TEST_CASE("frames rendered in windows are byte-identical to one run's", "[app][window]") {
    const fs::path folder = folder_for("windows");
    REQUIRE(render(arguments(folder, "one")) == 0);
    for (int i = 0; i < 4; ++i) {
        RenderArguments a = arguments(folder, "windows");
        a.window = std::to_string(i) + "/4";
        REQUIRE(render(a) == 0);
    }
    check_same_frames(folder / "one", folder / "windows", 12);
    // In every mode, with a fixed count too.
    for (const char* mode : {"frames", "brute"}) {
        RenderArguments one = arguments(folder, std::string("one_") + mode);
        one.mode = mode;
        one.samples_per_pixel = 4;
        REQUIRE(render(one) == 0);
        for (int i = 0; i < 3; ++i) {
            RenderArguments a = arguments(folder, std::string("windows_") + mode);
            a.mode = mode;
            a.samples_per_pixel = 4;
            a.window = std::to_string(i) + "/3";
            REQUIRE(render(a) == 0);
        }
        check_same_frames(folder / (std::string("one_") + mode),
                          folder / (std::string("windows_") + mode), 12);
    }
    // A window with nothing in it writes nothing and says so; outputs that
    // need every frame are refused with it.
    RenderArguments empty = arguments(folder, "empty");
    empty.window = "20/30";
    std::ostringstream out, err;
    CHECK(run_render(empty, out, err) == 0);
    CHECK(out.str().find("no frames") != std::string::npos);
    CHECK_FALSE(fs::exists(folder / "empty"));
    RenderArguments sheet = arguments(folder, "sheet");
    sheet.window = "0/2";
    sheet.contact_sheet = (folder / "sheet.png").string();
    CHECK(run_render(sheet, out, err) != 0);
    CHECK(err.str().find("--window") != std::string::npos);
}

TEST_CASE("resuming after SIGKILL at a random moment loses no frame and leaves no temporary",
          "[app][resume]") {
    const fs::path folder = folder_for("resume");
    REQUIRE(render(arguments(folder, "one")) == 0);
    // How long a whole run takes, to kill within it.
    const std::string command =
        std::string(HEXANT_BINARY) + " render " + (folder / "scene.pov").string() +
        " -W 40 -H 30 --frame-count 12 -o " + (folder / "killed" / "f_####.png").string();
    const auto start = std::chrono::steady_clock::now();
    REQUIRE(std::system((command + " > /dev/null 2>&1").c_str()) == 0);
    const double whole =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::mt19937 random(std::random_device{}());
    for (int attempt = 0; attempt < 3; ++attempt) {
        fs::remove_all(folder / "killed");
        const double delay = std::uniform_real_distribution<double>(0.0, whole)(random);
        INFO("killed after " << delay << " s of a " << whole << " s run");
        const std::string killed = "( " + command + " > /dev/null 2>&1 & pid=$!; sleep " +
                                   std::to_string(delay) +
                                   "; kill -9 $pid 2> /dev/null; wait $pid ) 2> /dev/null";
        std::system(killed.c_str());
        // What the kill left: whole frames, each with its record but
        // perhaps the last (a frame is written, then its record), perhaps
        // a temporary.
        int whole_frames = 0;
        if (fs::exists(folder / "killed"))
            for (const auto& entry : fs::directory_iterator(folder / "killed"))
                if (entry.path().extension() == ".png" &&
                    entry.path().filename().string()[0] != '.' &&
                    fs::exists(folder / "killed" / ".hexant" /
                               (entry.path().filename().string() + ".json")))
                    ++whole_frames;
        RenderArguments again = arguments(folder, "killed");
        again.resume = true;
        std::ostringstream out, err;
        REQUIRE(run_render(again, out, err) == 0);
        // Only the frames missing were rendered again.
        CHECK(out.str().find("--resume: " + std::to_string(whole_frames) +
                             " of 12 frames already written") != std::string::npos);
        check_same_frames(folder / "one", folder / "killed", 12);
    }
    // A frame cut short, a file that is no image, a frame of another size:
    // rendered again, not taken as written (found by a fresh user), even by
    // --resume=keep, which reads each frame as POV-Ray's +C would keep it.
    std::ofstream(folder / "killed/f_0002.png", std::ios::trunc) << "not a png";
    {
        const std::string written = bytes(folder / "killed/f_0003.png");
        std::ofstream(folder / "killed/f_0003.png", std::ios::binary | std::ios::trunc)
            << written.substr(0, 300);
    }
    RenderArguments other = arguments(folder, "small");
    other.scene.width = 20;
    other.scene.height = 15;
    REQUIRE(render(other) == 0);
    fs::copy_file(folder / "small/f_0004.png", folder / "killed/f_0004.png",
                  fs::copy_options::overwrite_existing);
    // A larger one is refused from its header, under the frame's own size
    // (not the 2^30 pixels of any image), before its pixels are decoded.
    RenderArguments large = arguments(folder, "large");
    large.scene.width = 80;
    large.scene.height = 60;
    large.frames = "5:5";
    REQUIRE(render(large) == 0);
    fs::copy_file(folder / "large/f_0005.png", folder / "killed/f_0005.png",
                  fs::copy_options::overwrite_existing);
    {
        RenderArguments again = arguments(folder, "killed");
        again.resume = true;
        again.resume_keep = true;
        std::ostringstream out, err;
        REQUIRE(run_render(again, out, err) == 0);
        CHECK(out.str().find("8 of 12 frames already written") != std::string::npos);
        CHECK(err.str().find("20 by 15") != std::string::npos);
        CHECK(err.str().find("80 by 60 pixels, more than the limit of 1200") != std::string::npos);
        check_same_frames(folder / "one", folder / "killed", 12);
    }
    // A run with every frame written renders nothing.
    RenderArguments done = arguments(folder, "killed");
    done.resume = true;
    std::ostringstream out, err;
    REQUIRE(run_render(done, out, err) == 0);
    CHECK(out.str().find("12 of 12 frames already written") != std::string::npos);
    CHECK(out.str().find("frames 1 to") == std::string::npos);
    // A temporary of a process still running is left to it.
    const std::string live = ".f_0005.png." + std::to_string(::getppid()) + ".partial";
    std::ofstream(folder / "killed" / live) << "x";
    std::ostringstream out2, err2;
    REQUIRE(run_render(done, out2, err2) == 0);
    CHECK(fs::exists(folder / "killed" / live));
    fs::remove(folder / "killed" / live);
}
