// POV-Ray 3.7's noise (runtime/texture/pattern/noise.hpp) against what POV-Ray
// itself printed (tests/tracer/pov_reference/noise/, README there): at
// lattice points, where each value is one table entry, and at 200 random
// points for each noise generator, through the scalar noise, the vector
// noise (a gradient pattern warped by one octave of turbulence reads one
// component back), four octaves of turbulence with their own omega and
// lambda, and marble's own turbulence. POV-Ray printed 20 decimals; the
// tolerance, 1e-13, is a few ulps of the coordinates (up to 30 in size,
// 3.6e-15 each) carried through the gradient's sum: the same operations in
// the same order agree to rounding, a wrong table entry or corner order is
// off by 1e-3 or more.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "runtime/texture/pattern/noise.hpp"
#include "runtime/texture/pattern/pattern.hpp"

namespace fs = std::filesystem;
namespace pt = hexant::runtime::pattern;

namespace {

const fs::path kFolder = fs::path(HEXANT_SOURCE_DIR) / "tests/tracer/pov_reference/noise";

std::vector<std::vector<double>> rows(const std::string& name) {
    std::ifstream in(kFolder / name);
    REQUIRE(in);
    std::vector<std::vector<double>> out;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::vector<double> row;
        double v;
        while (words >> v) row.push_back(v);
        out.push_back(row);
    }
    return out;
}

// A gradient pattern along `axis`, its point moved by turbulence along
// that axis only, as POV-Ray's `gradient x warp { turbulence <1, 0, 0> }`.
double warped_gradient(const glm::dvec3& p, int axis, const pt::Octaves& o) {
    glm::dvec3 amount(0.0), direction(0.0);
    amount[axis] = 1.0;
    direction[axis] = 1.0;
    pt::Values v;
    v.vector = direction;
    const glm::dvec3 q = pt::apply_turbulence(p, amount, o);
    return pt::evaluate(*pt::find_kind("gradient"), q, v, pt::Wave::Ramp, 1.0);
}

constexpr double kTolerance = 1e-13;

}  // namespace

TEST_CASE("noise at lattice points is POV-Ray's, entry by entry", "[pattern][noise]") {
    for (const auto& r : rows("lattice_noise.txt")) {
        INFO(r[0] << " " << r[1] << " " << r[2]);
        CHECK(std::fabs(pt::noise({r[0], r[1], r[2]}, 2) - r[3]) < kTolerance);
    }
    const pt::Octaves one{1, 0.5, 2.0};
    for (const auto& r : rows("lattice_dnoise.txt")) {
        INFO(r[0] << " " << r[1] << " " << r[2]);
        for (int axis = 0; axis < 3; ++axis)
            CHECK(std::fabs(warped_gradient({r[0], r[1], r[2]}, axis, one) - r[3 + axis]) <
                  kTolerance);
    }
}

TEST_CASE("noise, vector noise and turbulence off the lattice match POV-Ray", "[pattern][noise]") {
    for (int generator = 1; generator <= 3; ++generator) {
        INFO("noise_generator " << generator);
        for (const auto& r : rows("verify_" + std::to_string(generator) + ".txt")) {
            const glm::dvec3 p(r[0], r[1], r[2]);
            INFO(r[0] << " " << r[1] << " " << r[2]);
            CHECK(std::fabs(pt::noise(p, generator) - r[3]) < kTolerance);
            const pt::Octaves one{1, 0.5, 2.0};
            for (int axis = 0; axis < 3; ++axis)
                CHECK(std::fabs(warped_gradient(p, axis, one) - r[4 + axis]) < kTolerance);
            CHECK(std::fabs(warped_gradient(p, 0, pt::octaves_of(4, 0.6, 2.5)) - r[7]) <
                  kTolerance);
            // marble turbulence 0.7 octaves 5: its own turbulence, then the
            // triangle wave.
            pt::Values m;
            m.has_turbulence = true;
            m.turbulence = {0.7, 0.7, 0.7};
            m.octaves = {5, 0.5, 2.0};
            m.noise_generator = generator;
            CHECK(std::fabs(pt::evaluate(*pt::find_kind("marble"), p, m, pt::Wave::Triangle, 1.0) -
                            r[8]) < kTolerance);
        }
    }
}

TEST_CASE("the waves' shapes: cycloidal and the triangle wave", "[pattern][noise]") {
    CHECK(pt::cycloidal(0.25) == Approx(1.0));
    CHECK(pt::cycloidal(-0.25) == Approx(-1.0));
    CHECK(pt::cycloidal(1.0) == 0.0);
    CHECK(pt::triangle_wave(0.25) == 0.5);
    CHECK(pt::triangle_wave(0.5) == 1.0);
    CHECK(pt::triangle_wave(-0.25) == 0.5);
    CHECK(pt::triangle_wave(3.0) == 0.0);
}
