// render --resume keeps only frames this very render would write (issue
// 46): each frame's record (app/frame_record.hpp) says what made it, and a
// frame made at another size, with other settings, from an edited scene or
// include file, or changed by hand since, is rendered again, saying why;
// --resume=keep keeps any readable frame of the right size, as POV-Ray's +C.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "app/frame_record.hpp"
#include "app/render_command.hpp"
#include "app/sha256.hpp"

namespace fs = std::filesystem;
using hexant::app::frame_record_path;
using hexant::app::RenderArguments;
using hexant::app::run_render;

namespace {

const char* kScene = R"(
#include "part.inc"
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <-3 + 6 * clock, 5, -4>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.3 } }
sphere { <-2 + 4 * clock, 0.5, 0>, 0.5 pigment { rgb Tint } }
)";

fs::path folder_for(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / "hexant_resume_check_test" / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ofstream(folder / "scene.pov") << kScene;
    std::ofstream(folder / "part.inc") << "#declare Tint = <0.9, 0.3, 0.2>;\n";
    return folder;
}

RenderArguments arguments(const fs::path& folder) {
    RenderArguments a;
    a.scene.files = {(folder / "scene.pov").string()};
    a.scene.width = 32;
    a.scene.height = 24;
    a.scene.frame_count = 3;
    a.samples_per_pixel = 2;
    a.output = (folder / "out" / "f_####.png").string();
    return a;
}

fs::path frame(const fs::path& folder, int k) {
    return folder / "out" / ("f_000" + std::to_string(k) + ".png");
}

std::string bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Run {
    int status;
    std::string out, err;
};

Run render(const RenderArguments& a) {
    std::ostringstream out, err;
    const int status = run_render(a, out, err);
    return {status, out.str(), err.str()};
}

RenderArguments resumed(RenderArguments a, bool keep = false) {
    a.resume = true;
    a.resume_keep = keep;
    return a;
}

}  // namespace

TEST_CASE("SHA-256 of bytes and files is FIPS 180-4's, as sha256sum prints it", "[app][resume]") {
    hexant::app::Sha256 abc;
    abc.add("abc");
    CHECK(abc.hex() == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    // Two blocks, fed in pieces across the block's edge.
    const std::string text = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
    hexant::app::Sha256 pieces;
    pieces.add(text.substr(0, 7));
    pieces.add(text.substr(7));
    CHECK(pieces.hex() == "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    const fs::path file = fs::temp_directory_path() / "hexant_sha256_test.txt";
    std::ofstream(file, std::ios::binary) << "";
    const hexant::app::FileHash empty = hexant::app::hash_file(file);
    CHECK(empty.bytes == 0);
    CHECK(empty.sha256 == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    fs::remove(file);
    CHECK_THROWS_WITH(hexant::app::hash_file(file), Catch::Contains(file.string()));
}

TEST_CASE("each frame's record says what made it, its file's hash and its scene's files",
          "[app][resume]") {
    const fs::path folder = folder_for("record");
    REQUIRE(render(arguments(folder)).status == 0);
    const fs::path record_file = frame_record_path(frame(folder, 2));
    CHECK(record_file == folder / "out" / ".hexant" / "f_0002.png.json");
    const auto record = nlohmann::json::parse(bytes(record_file));
    CHECK(record["frame"] == 2);
    CHECK(record["file"]["sha256"] == hexant::app::hash_file(frame(folder, 2)).sha256);
    CHECK(record["made with"]["size"] == "32x24");
    CHECK(record["made with"]["clock"] == "0.5");
    CHECK(record["made with"]["samples per pixel"] == "2");
    CHECK(record["made with"]["hexant"] == hexant::app::hexant_version());
    // The scene first, then what it read, named inside the scene's folder
    // relative to it; POV-Ray's or hexant's include files by their path.
    REQUIRE(record["inputs"].size() >= 2);
    CHECK(record["inputs"][0]["file"] == "scene.pov");
    CHECK(record["inputs"][1]["file"] == "part.inc");
    CHECK(record["inputs"][1]["sha256"] == hexant::app::hash_file(folder / "part.inc").sha256);
    // Nothing half-written is left beside the records.
    for (const auto& entry : fs::directory_iterator(folder / "out" / ".hexant"))
        CHECK(entry.path().extension() == ".json");
}

TEST_CASE(
    "a resume at another size renders every frame again and says so, and keep keeps "
    "frames of other settings",
    "[app][resume]") {
    const fs::path folder = folder_for("size");
    RenderArguments large = arguments(folder);
    large.scene.width = 64;
    large.scene.height = 48;
    REQUIRE(render(large).status == 0);
    const Run again = render(resumed(arguments(folder)));
    INFO(again.out << again.err);
    REQUIRE(again.status == 0);
    CHECK(again.out.find("--resume: 0 of 3 frames already written") != std::string::npos);
    for (int k = 1; k <= 3; ++k)
        CHECK(again.err.find("frame " + std::to_string(k) + " (" + frame(folder, k).string() +
                             ") rendered again: it was made at 64x48, this render is 32x24") !=
              std::string::npos);
    // Now rendered as asked: a second resume keeps them all.
    const Run done = render(resumed(arguments(folder)));
    CHECK(done.out.find("--resume: 3 of 3 frames already written") != std::string::npos);
    CHECK(done.err.find("rendered again") == std::string::npos);

    // Other samples and a --declare: rendered again by the checked
    // resume, each difference named; kept as they are by --resume=keep,
    // with a note.
    RenderArguments other = arguments(folder);
    other.samples_per_pixel = 4;
    other.scene.declares = {"Extra=1"};
    const std::string before = bytes(frame(folder, 2));
    const Run kept = render(resumed(other, true));
    INFO(kept.out << kept.err);
    REQUIRE(kept.status == 0);
    CHECK(kept.out.find("--resume: 3 of 3 frames already written") != std::string::npos);
    CHECK(bytes(frame(folder, 2)) == before);
    CHECK(kept.err.find("kept (--resume=keep), though its samples per pixel was 2, this "
                        "render's is 4") != std::string::npos);
    CHECK(kept.err.find("may mix two renders") != std::string::npos);
    const Run checked = render(resumed(other));
    CHECK(checked.out.find("--resume: 0 of 3 frames already written") != std::string::npos);
    CHECK(checked.err.find("its samples per pixel was 2, this render's is 4; it was made with "
                           "--declare none, this render with Extra=1") != std::string::npos);
    CHECK(bytes(frame(folder, 2)) != before);
    // Even keep renders again a frame of another size: it cannot join the others.
    const Run small = render(resumed(large, true));
    CHECK(small.out.find("--resume: 0 of 3 frames already written") != std::string::npos);
    CHECK(small.err.find("it is 32 by 24 pixels, not 64 by 48") != std::string::npos);
}

TEST_CASE("a frame changed by hand, an edited scene or include file is rendered again",
          "[app][resume]") {
    const fs::path folder = folder_for("edits");
    REQUIRE(render(arguments(folder)).status == 0);
    // Frame 1's file copied over frame 2's: a whole PNG of the right size,
    // which POV-Ray's +C would keep.
    fs::copy_file(frame(folder, 1), frame(folder, 2), fs::copy_options::overwrite_existing);
    Run run = render(resumed(arguments(folder)));
    INFO(run.out << run.err);
    CHECK(run.out.find("--resume: 2 of 3 frames already written") != std::string::npos);
    CHECK(run.err.find("frame 2 (" + frame(folder, 2).string() +
                       ") rendered again: the file was changed after it was rendered") !=
          std::string::npos);
    CHECK(bytes(frame(folder, 1)) != bytes(frame(folder, 2)));

    // The scene edited (a comment changes no pixel, but hexant cannot know).
    std::ofstream(folder / "scene.pov", std::ios::app) << "// edited\n";
    run = render(resumed(arguments(folder)));
    CHECK(run.out.find("--resume: 0 of 3 frames already written") != std::string::npos);
    CHECK(run.err.find("rendered again: the scene scene.pov has changed since") !=
          std::string::npos);

    // The include file edited.
    std::ofstream(folder / "part.inc", std::ios::app) << "#declare Unused = 1;\n";
    run = render(resumed(arguments(folder)));
    CHECK(run.out.find("--resume: 0 of 3 frames already written") != std::string::npos);
    CHECK(run.err.find("rendered again: part.inc, which its scene read, has changed since") !=
          std::string::npos);
}

TEST_CASE("a flag that changes no pixel keeps the frames", "[app][resume]") {
    const fs::path folder = folder_for("threads");
    RenderArguments one = arguments(folder);
    one.threads = 1;
    REQUIRE(render(one).status == 0);
    const std::string before = bytes(frame(folder, 3));
    RenderArguments two = resumed(arguments(folder));
    two.threads = 2;
    two.mode = "frames";
    two.stats = true;
    const Run run = render(two);
    INFO(run.out << run.err);
    CHECK(run.out.find("--resume: 3 of 3 frames already written") != std::string::npos);
    CHECK(run.err.find("rendered again") == std::string::npos);
    CHECK(bytes(frame(folder, 3)) == before);
}

TEST_CASE("a kept frame without its error or samples image is rendered again for it",
          "[app][resume]") {
    // (A user found --resume with --error-image writing none and saying
    // nothing when every frame was on disk.)
    const fs::path folder = folder_for("side_images");
    REQUIRE(render(arguments(folder)).status == 0);
    const std::string before = bytes(frame(folder, 2));
    RenderArguments again = resumed(arguments(folder));
    again.error_image = (folder / "out" / "e_####.png").string();
    again.error_estimate = true;
    const Run run = render(again);
    INFO(run.out << run.err);
    REQUIRE(run.status == 0);
    for (const int k : {1, 2, 3}) {
        CHECK(fs::exists(folder / "out" / ("e_000" + std::to_string(k) + ".png")));
        const std::string named = "frame " + std::to_string(k) + " (" + frame(folder, k).string() +
                                  ") rendered again: its --error-image";
        CHECK(run.err.find(named) != std::string::npos);
    }
    // The same samples: the same frame.
    CHECK(bytes(frame(folder, 2)) == before);
    // With them all on disk, kept; the estimate's absence said.
    RenderArguments kept = resumed(arguments(folder));
    kept.error_image = again.error_image;
    kept.error_estimate = true;
    const Run second = render(kept);
    INFO(second.out << second.err);
    CHECK(second.out.find("--resume: 3 of 3 frames already written") != std::string::npos);
    CHECK(second.err.find("rendered again") == std::string::npos);
    CHECK(second.err.find("the frames kept print no estimate") != std::string::npos);
}

TEST_CASE("a damaged, foreign or missing record renders the frame again, saying so",
          "[app][resume]") {
    const fs::path folder = folder_for("damaged");
    REQUIRE(render(arguments(folder)).status == 0);
    std::ofstream(frame_record_path(frame(folder, 1)), std::ios::trunc) << "{\"hexant frame rec";
    std::ofstream(frame_record_path(frame(folder, 2)), std::ios::trunc) << "{\"a\": [1, 2]}";
    fs::remove(frame_record_path(frame(folder, 3)));
    Run run = render(resumed(arguments(folder)));
    INFO(run.out << run.err);
    REQUIRE(run.status == 0);
    CHECK(run.out.find("--resume: 0 of 3 frames already written") != std::string::npos);
    CHECK(run.err.find("frame 1 (" + frame(folder, 1).string() + ") rendered again: its record " +
                       frame_record_path(frame(folder, 1)).string() + " is damaged") !=
          std::string::npos);
    CHECK(run.err.find("is not a hexant frame record hexant can read") != std::string::npos);
    CHECK(run.err.find("frame 3 (" + frame(folder, 3).string() +
                       ") rendered again: it has no record of what made it") != std::string::npos);
    // Rendered again, each has its record anew.
    run = render(resumed(arguments(folder)));
    CHECK(run.out.find("--resume: 3 of 3 frames already written") != std::string::npos);
    // A record of the right format whose fields are of the wrong kinds, or
    // of a newer format: the same.
    for (const char* text : {R"({"hexant frame record": 1, "frame": "x", "made with": 5})",
                             R"({"hexant frame record": 1, "frame": 2, "made with": {"size": 7},
                                 "inputs": {}, "file": []})",
                             R"({"hexant frame record": 99})", "[]", "null"}) {
        INFO(text);
        std::ofstream(frame_record_path(frame(folder, 2)), std::ios::trunc) << text;
        run = render(resumed(arguments(folder)));
        REQUIRE(run.status == 0);
        CHECK(run.out.find("--resume: 2 of 3 frames already written") != std::string::npos);
        CHECK(run.err.find("frame 2 (" + frame(folder, 2).string() +
                           ") rendered again: its record") != std::string::npos);
    }
}

TEST_CASE("windows rendered at once by two processes leave every record whole for the join",
          "[app][resume]") {
    const fs::path folder = folder_for("concurrent");
    const std::string command =
        std::string(HEXANT_BINARY) + " render " + (folder / "scene.pov").string() +
        " -W 32 -H 24 --frame-count 8 --spp 2 -o " + (folder / "out" / "f_####.png").string();
    REQUIRE(std::system(("( " + command + " --window 0/2 > /dev/null 2>&1 & " + command +
                         " --window 1/2 > /dev/null 2>&1; wait )")
                            .c_str()) == 0);
    RenderArguments join = resumed(arguments(folder));
    join.scene.frame_count = 8;
    join.contact_sheet = (folder / "sheet.png").string();
    const Run run = render(join);
    INFO(run.out << run.err);
    REQUIRE(run.status == 0);
    CHECK(run.out.find("--resume: 8 of 8 frames already written") != std::string::npos);
    CHECK(run.err.find("rendered again") == std::string::npos);
    CHECK(fs::exists(folder / "sheet.png"));
}

TEST_CASE("a scene read frame by frame: each frame's record holds the files its reading read",
          "[app][resume]") {
    const fs::path folder = folder_for("frame_by_frame");
    // Stepped per frame (read frame by frame, app/scene_reading.hpp), and
    // frame 3 alone includes a file.
    std::ofstream(folder / "scene.pov", std::ios::trunc) << R"(
#declare A = array[1] { 0 }
#declare I = 0;
#while (I < frame_number)
  #declare A[0] = A[0] + 1;
  #declare I = I + 1;
#end
#declare Tint = <0.9, 0.3, 0.2>;
#if (frame_number = 3) #include "three.inc" #end
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <-3, 5, -4>, rgb 1 }
sphere { <A[0] - 2, 0.5, 0>, 0.5 pigment { rgb Tint } }
)";
    std::ofstream(folder / "three.inc") << "#declare Tint = <0.2, 0.3, 0.9>;\n";
    Run run = render(arguments(folder));
    INFO(run.err);
    REQUIRE(run.status == 0);
    REQUIRE(run.err.find("is read frame by frame") != std::string::npos);
    const auto three = nlohmann::json::parse(bytes(frame_record_path(frame(folder, 3))));
    REQUIRE(three["inputs"].size() == 2);
    CHECK(three["inputs"][1]["file"] == "three.inc");
    CHECK(nlohmann::json::parse(bytes(frame_record_path(frame(folder, 2))))["inputs"].size() == 1);
    // Only the frame that read the edited file is rendered again.
    std::ofstream(folder / "three.inc", std::ios::app) << "// edited\n";
    run = render(resumed(arguments(folder)));
    CHECK(run.out.find("--resume: 2 of 3 frames already written") != std::string::npos);
    CHECK(run.err.find("frame 3 (" + frame(folder, 3).string() +
                       ") rendered again: three.inc, which its scene read, has changed since") !=
          std::string::npos);
    run = render(resumed(arguments(folder)));
    CHECK(run.out.find("--resume: 3 of 3 frames already written") != std::string::npos);
}

TEST_CASE("many frames rendered again: the first ten named, the rest counted", "[app][resume]") {
    const fs::path folder = folder_for("many");
    RenderArguments a = arguments(folder);
    a.scene.width = 8;
    a.scene.height = 6;
    a.scene.frame_count = 14;
    a.samples_per_pixel = 1;
    a.output = (folder / "out" / "f_##.png").string();
    REQUIRE(render(a).status == 0);
    a.seed = 7;
    const Run run = render(resumed(a));
    INFO(run.err);
    CHECK(run.out.find("--resume: 0 of 14 frames already written") != std::string::npos);
    CHECK(run.err.find("frame 10 (") != std::string::npos);
    CHECK(run.err.find("its seed was 0, this render's is 7") != std::string::npos);
    CHECK(run.err.find("frame 11 (") == std::string::npos);
    CHECK(run.err.find("--resume: 4 more frames rendered again") != std::string::npos);
}
