// `hexant dump --clock C` against POV-Ray 3.7: the program itself is run on a
// scene whose parameters and transforms depend on clock, with an animation so
// that clock is symbolic, and its output compared with what POV-Ray printed at
// the same clock (dump_reference/README.md).
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include <catch2/catch.hpp>

namespace {

const std::string kFolder = std::string(HEXANT_SOURCE_DIR) + "/tests/app/dump_reference/";

std::string run(const std::string& command) {
    std::string output;
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe != nullptr);
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), buffer.size(), pipe)) output += buffer.data();
    REQUIRE(pclose(pipe) == 0);
    return output;
}

std::vector<double> numbers(const std::string& text) {
    std::vector<double> out;
    const std::regex number(R"([-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), number);
         it != std::sregex_iterator(); ++it)
        out.push_back(std::stod(it->str()));
    return out;
}

// The values after `key=` on a dump line, e.g. center=<1, 2, 3>.
std::vector<double> field(const std::string& line, const std::string& key) {
    const auto at = line.find(" " + key + "=");
    REQUIRE(at != std::string::npos);
    const auto begin = at + key.size() + 2;
    const auto end = line.find_first_of(">]", begin);
    const auto stop = (line[begin] == '<' || line[begin] == '[') ? end : line.find(' ', begin);
    return numbers(line.substr(begin, stop - begin));
}

std::map<std::string, std::vector<double>> expected(const std::string& clock) {
    std::ifstream in(kFolder + "motion_objects.clock" + clock + ".expected");
    REQUIRE(in.good());
    std::map<std::string, std::vector<double>> values;
    std::string line;
    while (std::getline(in, line)) {
        const auto eq = line.find(" = ");
        if (eq != std::string::npos) values[line.substr(0, eq)] = numbers(line.substr(eq + 3));
    }
    return values;
}

// Where POV-Ray's 4x3 matrix (rows m0..m3, p' = p M) takes point p.
std::vector<double> apply(const std::vector<double>& m, double x, double y, double z) {
    return {x * m[0] + y * m[3] + z * m[6] + m[9], x * m[1] + y * m[4] + z * m[7] + m[10],
            x * m[2] + y * m[5] + z * m[8] + m[11]};
}

void near(const std::vector<double>& got, const std::vector<double>& want) {
    REQUIRE(got.size() == want.size());
    // POV-Ray printed 10 decimals; its clock is single precision (1e-7).
    for (std::size_t i = 0; i < got.size(); ++i) CHECK(std::fabs(got[i] - want[i]) < 1e-6);
}

}  // namespace

TEST_CASE("hexant dump --clock C agrees with POV-Ray on moving parameters and transforms",
          "[app][dump][povray]") {
    for (const char* clock : {"0", "0.25", "0.5", "1"}) {
        SECTION(clock) {
            const std::string output =
                run(std::string(HEXANT_BINARY) + " dump " + kFolder +
                    "motion_objects.pov --frame-count 5 --declare Hexant_Dump=1 --clock " + clock);
            std::istringstream lines(output);
            std::string line, sphere, cylinder;
            while (std::getline(lines, line)) {
                if (line.rfind("object[0] sphere", 0) == 0) sphere = line;
                if (line.rfind("object[1] cylinder", 0) == 0) cylinder = line;
            }
            REQUIRE(!sphere.empty());
            REQUIRE(!cylinder.empty());
            auto want = expected(clock);
            near(field(sphere, "center"), want["sphere.center"]);
            near(field(sphere, "radius"), want["sphere.radius"]);
            const auto m = field(sphere, "transform");
            REQUIRE(m.size() == 12);
            near(apply(m, 0, 0, 0), want["sphere.transform.origin"]);
            near(apply(m, 1, 0, 0), want["sphere.transform.x"]);
            near(apply(m, 0, 1, 0), want["sphere.transform.y"]);
            near(apply(m, 0, 0, 1), want["sphere.transform.z"]);
            near(field(cylinder, "base"), want["cylinder.base"]);
            near(field(cylinder, "cap"), want["cylinder.cap"]);
            near(field(cylinder, "radius"), want["cylinder.radius"]);
        }
    }
}
