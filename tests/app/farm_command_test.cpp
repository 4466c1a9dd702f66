// `hexant farm`: the Slurm scripts it writes, run here as Slurm would run
// them (each array task with its SLURM_ARRAY_TASK_ID, then the join),
// give the frames, contact sheet, animation and video one run gives, byte for
// byte. (Submitting to a real Slurm: the `cluster` test, not here.)
#include "app/farm_command.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <sys/stat.h>

#include "app/merge_stats.hpp"

namespace fs = std::filesystem;
using hexant::app::run_farm;
using hexant::app::split_farm_arguments;

namespace {

std::string bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const char* kScene = R"(
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <-3 + 6 * clock, 5, -4>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.3 } }
sphere { <-2 + 4 * clock, 0.5, 0>, 0.5 pigment { rgb <0.9, 0.3, 0.2> } }
)";

}  // namespace

TEST_CASE("farm's flags are its own, the rest passes to render as written", "[app][farm]") {
    const auto a =
        split_farm_arguments({"s.pov", "--windows", "4", "--spp=8", "--partition=short", "--time",
                              "00:10:00", "--contact-sheet", "sheet.png", "-W", "64", "--submit"});
    CHECK(a.windows == 4);
    CHECK(a.partition == "short");
    CHECK(a.time_limit == "00:10:00");
    CHECK(a.contact_sheet == "sheet.png");
    CHECK(a.submit);
    CHECK(a.render == std::vector<std::string>{"s.pov", "--spp=8", "-W", "64"});
    CHECK_THROWS_WITH(split_farm_arguments({"s.pov"}), Catch::Contains("--windows"));
    CHECK_THROWS_WITH(split_farm_arguments({"s.pov", "--windows", "0"}),
                      Catch::Contains("at least 1"));
    CHECK_THROWS_WITH(split_farm_arguments({"s.pov", "--windows", "2", "--window", "0/2"}),
                      Catch::Contains("--window"));
    CHECK_THROWS_WITH(split_farm_arguments({"s.pov", "--windows", "2", "--time"}),
                      Catch::Contains("needs a value"));
    CHECK(hexant::app::shell_quote("it's a 'b'") == "'it'\\''s a '\\''b'\\'''");
    // (Found by a fresh user: a newline in a value became a command of the
    // script; sbatch's own lines split at blanks.)
    CHECK_THROWS_WITH(split_farm_arguments({"s.pov", "--windows", "2", "--time", "1:00\necho x"}),
                      Catch::Contains("control character"));
    CHECK_THROWS_WITH(split_farm_arguments({"s.pov\necho x", "--windows", "2"}),
                      Catch::Contains("control character"));
    CHECK_THROWS_WITH(split_farm_arguments({"s.pov", "--windows", "2", "--partition", "a #b"}),
                      Catch::Contains("#SBATCH"));
    CHECK_THROWS_WITH(split_farm_arguments({"s.pov", "--windows", "2", "--windows", "3"}),
                      Catch::Contains("twice"));
    CHECK_THROWS_WITH(split_farm_arguments({"s.pov", "--windows", "2", "--compare"}),
                      Catch::Contains("--compare"));
}

TEST_CASE("a farm's array tasks and join, run as Slurm runs them, give one run's bytes",
          "[app][farm]") {
    const fs::path folder = fs::temp_directory_path() / "hexant_farm_test";
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ofstream(folder / "scene.pov") << kScene;
    const std::string hexant = HEXANT_BINARY;
    const std::string common =
        (folder / "scene.pov").string() + " -W 32 -H 24 --frame-count 10 --spp 4";
    REQUIRE(
        std::system((hexant + " render " + common + " -o " + (folder / "one/f_####.png").string() +
                     " --contact-sheet " + (folder / "one.png").string() + " --animation " +
                     (folder / "one.gif").string() + " --video " + (folder / "one.mp4").string() +
                     " --stats-json " + (folder / "one.json").string() + " > /dev/null 2>&1")
                        .c_str()) == 0);

    auto args = split_farm_arguments({(folder / "scene.pov").string(),
                                      "-W",
                                      "32",
                                      "-H",
                                      "24",
                                      "--frame-count",
                                      "10",
                                      "--spp",
                                      "4",
                                      "-o",
                                      (folder / "farm/f_####.png").string(),
                                      "--windows",
                                      "4",
                                      "--partition",
                                      "debug",
                                      "--contact-sheet",
                                      (folder / "farm.png").string(),
                                      "--animation",
                                      (folder / "farm.gif").string(),
                                      "--video",
                                      (folder / "farm.mp4").string(),
                                      "--farm-dir",
                                      (folder / "scripts").string()});
    args.hexant = hexant;
    std::ostringstream out, err;
    REQUIRE(run_farm(args, out, err) == 0);
    INFO(out.str() << err.str());
    const std::string array = bytes(folder / "scripts/array.sbatch");
    CHECK(array.find("#SBATCH --array=0-3\n") != std::string::npos);
    CHECK(array.find("#SBATCH --partition=debug\n") != std::string::npos);
    CHECK(array.find("--window \"${SLURM_ARRAY_TASK_ID}/4\" --resume") != std::string::npos);
    CHECK(bytes(folder / "scripts/submit.sh").find("--dependency=afterok:$array") !=
          std::string::npos);

    for (int task = 0; task < 4; ++task)
        REQUIRE(std::system(("SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " bash " +
                             (folder / "scripts/array.sbatch").string() + " > /dev/null 2>&1")
                                .c_str()) == 0);
    // Each window wrote its statistics.
    for (int task = 0; task < 4; ++task)
        CHECK(fs::exists(folder / ("scripts/window_" + std::to_string(task) + ".json")));
    REQUIRE(std::system(("bash " + (folder / "scripts/join.sbatch").string() + " > " +
                         (folder / "join.txt").string() + " 2>&1")
                            .c_str()) == 0);
    // The join keeps every window's frame: their records say this same
    // render made them (a window changes no pixel).
    CHECK(bytes(folder / "join.txt").find("--resume: 10 of 10 frames already written") !=
          std::string::npos);
    CHECK(bytes(folder / "join.txt").find("rendered again") == std::string::npos);
    for (int k = 1; k <= 10; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "f_%04d.png", k);
        INFO(name);
        CHECK(bytes(folder / "one" / name) == bytes(folder / "farm" / name));
    }
    CHECK(bytes(folder / "one.png") == bytes(folder / "farm.png"));
    CHECK(bytes(folder / "one.gif") == bytes(folder / "farm.gif"));
    // The join's video, from the frames on disk, is the one run's, which
    // added each frame as it finished (the same bytes in, one encoder).
    CHECK(!bytes(folder / "farm.mp4").empty());
    CHECK(bytes(folder / "one.mp4") == bytes(folder / "farm.mp4"));
    // The merged statistics: the windows' sums, which for the rays are one
    // run's (the same samples); each window's build listed.
    const auto one = nlohmann::json::parse(bytes(folder / "one.json"))["spacetime"];
    const auto merged = nlohmann::json::parse(bytes(folder / "scripts/stats.json"))["spacetime"];
    for (const char* row : {"primary rays", "shadow rays", "reflected rays", "refracted rays"})
        CHECK(merged[row].get<double>() == one[row].get<double>());
    double builds = 0.0;
    for (int task = 0; task < 4; ++task) {
        const auto w = nlohmann::json::parse(
            bytes(folder / ("scripts/window_" + std::to_string(task) + ".json")))["spacetime"];
        builds += w["build time (s)"].get<double>();
    }
    CHECK(merged["build time (s)"].get<double>() == Approx(builds).epsilon(1e-12));
    REQUIRE(merged["per window"].size() == 4);
    CHECK(merged["per window"][3]["frames"].size() == 3);  // (frames 8 to 10 of 10 in 4 windows)
    CHECK(merged["per frame"].size() == 10);

    // A mistake in the render flags shows at once, not in every task (nor
    // in the join, after all the rendering): flags, output names, too many
    // windows.
    const std::string scene = (folder / "scene.pov").string();
    for (const auto& [words, said] : std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{scene, "--spp", "0"}, "--spp"},
             {{scene, "--frame-count", "10", "-o", (folder / "x/f.png").string()}, "####"},
             {{scene, "--frame-count", "10", "--animation", (folder / "a.png").string()}, "a.png"},
             {{scene, "--frame-count", "3"}, "at most that many windows"},
             {{"--spp", "2"}, "needs the scene"}}) {
        std::vector<std::string> all = words;
        for (const std::string w : {"--windows", "4", "--farm-dir"}) all.push_back(w);
        all.push_back((folder / "bad").string());
        auto bad = split_farm_arguments(all);
        bad.hexant = hexant;
        std::ostringstream bad_out, bad_err;
        INFO(said);
        CHECK(run_farm(bad, bad_out, bad_err) != 0);
        CHECK(bad_err.str().find(said) != std::string::npos);
        CHECK_FALSE(fs::exists(folder / "bad"));
    }
    // Run by hand from elsewhere, the scripts still find the scene (cd).
    CHECK(array.find("cd '") != std::string::npos);
}

TEST_CASE("merge-stats refuses what is not one mode's statistics, naming the file", "[app][farm]") {
    const fs::path folder = fs::temp_directory_path() / "hexant_merge_stats_test";
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ofstream(folder / "a.json")
        << R"({"spacetime": {"primary rays": 10, "per frame": [{"frame": 1}]}})";
    std::ofstream(folder / "b.json") << R"({"frames": {"primary rays": 5}})";
    std::ofstream(folder / "c.json") << "not json";
    const std::string out = (folder / "m.json").string();
    using hexant::app::merge_stats;
    CHECK_THROWS_WITH(
        merge_stats({(folder / "a.json").string(), (folder / "b.json").string()}, out),
        Catch::Contains("b.json") && Catch::Contains("frames render"));
    CHECK_THROWS_WITH(merge_stats({(folder / "c.json").string()}, out), Catch::Contains("c.json"));
    CHECK_THROWS_WITH(merge_stats({(folder / "none.json").string()}, out),
                      Catch::Contains("none.json"));
    // A FIFO is refused, not waited on forever (issue 45).
    REQUIRE(mkfifo((folder / "fifo.json").c_str(), 0600) == 0);
    CHECK_THROWS_WITH(merge_stats({(folder / "fifo.json").string()}, out),
                      Catch::Contains("fifo.json") && Catch::Contains("not a regular file"));
    CHECK_FALSE(fs::exists(out));
    // (Found by a fresh user: a file named twice was counted twice, the
    // output could overwrite a window's file, a row of text merged to
    // nothing, and the objects were summed.)
    CHECK_THROWS_WITH(
        merge_stats({(folder / "a.json").string(), (folder / "a.json").string()}, out),
        Catch::Contains("named twice"));
    CHECK_THROWS_WITH(merge_stats({(folder / "a.json").string()}, (folder / "a.json").string()),
                      Catch::Contains("one of the windows"));
    std::ofstream(folder / "d.json") << R"({"spacetime": {"objects": "eight"}})";
    CHECK_THROWS_WITH(merge_stats({(folder / "d.json").string()}, out),
                      Catch::Contains("not a number"));
    std::ofstream(folder / "a2.json")
        << R"({"spacetime": {"primary rays": 10, "objects": 8, "per frame": [{"frame": 2}]}})";
    std::ofstream(folder / "a3.json")
        << R"({"spacetime": {"primary rays": 7, "objects": 8, "per frame": [{"frame": 3}]}})";
    merge_stats({(folder / "a2.json").string(), (folder / "a3.json").string()}, out);
    const auto merged = nlohmann::json::parse(bytes(out))["spacetime"];
    CHECK(merged["primary rays"] == 17);  // (a whole number, as render writes counts)
    CHECK(merged["objects"] == 8);
    CHECK(merged["per frame"].size() == 2);
}
