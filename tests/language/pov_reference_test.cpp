// The interpreter against POV-Ray 3.7's own evaluation: each scene in
// pov_reference/ #debugs values, and NAME.expected holds what povray printed
// (commands in pov_reference/README.md). hexant must print the same names and
// the same numbers.
#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"

namespace {

using hexant::language::ParseOptions;

const std::string kFolder = std::string(HEXANT_SOURCE_DIR) + "/tests/language/pov_reference/";

std::string read(const std::string& path) {
    std::ifstream in(path);
    REQUIRE(in.good());
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::pair<std::string, std::string>> lines_of(const std::string& text) {
    std::vector<std::pair<std::string, std::string>> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const auto eq = line.find(" = ");
        if (eq == std::string::npos) continue;
        out.emplace_back(line.substr(0, eq), line.substr(eq + 3));
    }
    return out;
}

// POV-Ray keeps colours in single precision, so 0.3 prints as 0.3000000119;
// 1e-7 relative covers that and nothing larger. Other values are printed to
// 10 decimals, so they agree far closer.
void compare(const std::string& scene, const std::string& actual, const std::string& expected) {
    const auto want = lines_of(expected);
    const auto got = lines_of(actual);
    REQUIRE(want.size() > 0);
    REQUIRE(got.size() == want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        INFO(scene << ": " << want[i].first);
        REQUIRE(got[i].first == want[i].first);
        char* end = nullptr;
        const double w = std::strtod(want[i].second.c_str(), &end);
        if (end == want[i].second.c_str()) {
            CHECK(got[i].second == want[i].second);  // a string
            continue;
        }
        const double g = std::strtod(got[i].second.c_str(), nullptr);
        CHECK(std::fabs(g - w) <= 1e-7 * std::max(1.0, std::fabs(w)));
    }
}

std::string run(const std::string& scene, ParseOptions options) {
    std::ostringstream messages;
    options.messages = &messages;
    hexant::language::parse_scene_file(kFolder + scene, options);
    return messages.str();
}

}  // namespace

TEST_CASE("expressions, functions, vectors, colours and control flow agree with POV-Ray",
          "[language][povray]") {
    for (const char* name :
         {"arithmetic", "functions", "vectors", "srgb", "control", "splines", "user_functions"}) {
        SECTION(name) {
            const std::string scene = std::string(name) + ".pov";
            compare(scene, run(scene, ParseOptions{}), read(kFolder + name + ".expected"));
        }
    }
}

TEST_CASE("expressions of clock agree with POV-Ray at a fixed clock", "[language][povray]") {
    for (const char* clock : {"0", "0.25", "0.5", "1"}) {
        SECTION(clock) {
            ParseOptions options;
            options.animation.initial_clock = std::stod(clock);  // one frame, at that clock
            compare("motion.pov", run("motion.pov", options),
                    read(kFolder + "motion.clock" + clock + ".expected"));
        }
    }
}

// The same expressions read once as functions of time, then evaluated at each
// clock: each `#debug ... str(EXPR, 0, 10)` becomes a sphere whose centre's x
// is EXPR, so the scene holds the symbolic time functions themselves.
TEST_CASE("time functions built from clock agree with POV-Ray at every clock",
          "[language][povray][time]") {
    const std::string source = read(kFolder + "motion.pov");
    const std::regex debug_line(R"re(#debug concat\("([^"]+) = ", str\((.*), 0, 10\), "\\n"\))re");
    std::string symbolic;
    std::vector<std::string> names;
    std::istringstream in(source);
    std::string line;
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_search(line, m, debug_line)) {
            names.push_back(m[1]);
            symbolic += "sphere { <" + m[2].str() + ", 0, 0>, 1 }\n";
        } else {
            symbolic += line + "\n";
        }
    }
    REQUIRE(names.size() >= 10);
    ParseOptions options;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 5;  // an animation: clock is symbolic
    const auto scene = hexant::language::parse_scene_text(symbolic, "motion-symbolic.pov", options);
    REQUIRE(scene.objects.size() == names.size());
    // POV-Ray's values at each clock; an expression whose values all agree
    // must be a constant (`y * 360 * clock` turning x keeps y at 0), any
    // other a function of time.
    std::vector<std::set<std::string>> values(names.size());
    for (const char* clock : {"0", "0.25", "0.5", "1"}) {
        const auto expected = lines_of(read(kFolder + "motion.clock" + clock + ".expected"));
        REQUIRE(expected.size() == names.size());
        for (std::size_t i = 0; i < names.size(); ++i) {
            INFO("clock " << clock << ": " << names[i]);
            REQUIRE(expected[i].first == names[i]);
            const auto& sphere = std::get<hexant::runtime::Sphere>(scene.objects[i]->shape);
            const double got = sphere.center.c[0](std::stod(clock));
            const double want = std::stod(expected[i].second);
            CHECK(std::fabs(got - want) <= 1e-7 * std::max(1.0, std::fabs(want)));
            values[i].insert(expected[i].second);
        }
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
        INFO(names[i]);
        const auto& sphere = std::get<hexant::runtime::Sphere>(scene.objects[i]->shape);
        CHECK(sphere.center.c[0].depends_on_time() == (values[i].size() > 1));
    }
}
