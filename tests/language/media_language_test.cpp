// Reading media { } and density { } as POV-Ray 3.7's Parse_Media reads
// them: 3.5's defaults and the older ones, each setting and its checks,
// densities moved by the transforms written after them and by the
// object's, declared media and densities, the atmosphere.
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "scene_text.hpp"

using hexant::test::check_error_at;
using hexant::test::scene_of;
namespace rt = hexant::runtime;

namespace {

const rt::Media& first_media(const rt::SceneDescription& scene) {
    return scene.objects.at(0)->interior.value().media.at(0);
}

}  // namespace

TEST_CASE("media's defaults are POV-Ray 3.5's, or older below #version 3.5", "[language][media]") {
    const auto now = scene_of("sphere { 0, 1 hollow interior { media { emission 1 } } }");
    const rt::Media& m = first_media(now);
    CHECK(m.method == 3);
    CHECK(m.intervals == 1);
    CHECK(m.min_samples == 10);
    CHECK(m.max_samples == 10);
    CHECK(m.aa_level == 3);
    CHECK(m.aa_threshold == Approx(0.1));
    CHECK(m.emission.c[1].constant() == 1.0);
    const auto old = scene_of("#version 3.1;\nsphere { 0, 1 hollow interior { media { } } }");
    CHECK(first_media(old).method == 1);
    CHECK(first_media(old).intervals == 10);
    CHECK(first_media(old).min_samples == 1);
}

TEST_CASE("media's settings, scattering and densities are read", "[language][media]") {
    const auto scene = scene_of(R"(
#declare D = density { spherical density_map { [0 rgb 0] [1 bozo] } }
#declare M = media {
  method 2 intervals 4 samples 3, 7 jitter 0.5 ratio 0.8 confidence 0.95 variance 0.01
  absorption <1, 2, 3>
  scattering { 5, rgb 0.5 eccentricity 0.3 extinction 0.7 }
  density { D translate x }
  translate y
  density { rgb 0.5 }
}
box { 0, 1 hollow interior { media { M } media { emission 2 } } translate z }
media { scattering { 1, 0.1 } }
)");
    const auto& interior = scene.objects.at(0)->interior.value();
    REQUIRE(interior.media.size() == 2);
    const rt::Media& m = interior.media[0];
    CHECK(m.method == 2);
    CHECK(m.intervals == 4);
    CHECK(m.min_samples == 3);
    CHECK(m.max_samples == 7);
    CHECK(m.jitter == Approx(0.5));
    CHECK(m.ratio == Approx(0.8));
    CHECK(m.absorption.c[2].constant() == 3.0);
    CHECK(m.type == rt::Media::Scattering::HenyeyGreenstein);
    CHECK(m.eccentricity.constant() == Approx(0.3));
    CHECK(m.extinction.constant() == Approx(0.7));
    REQUIRE(m.density.size() == 2);
    // The first density: its own translate, the media's, the object's;
    // the second, written after the media's translate: the object's only.
    CHECK(m.density[0].transform.matrix_at(0.0)[3] == glm::dvec4(1.0, 1.0, 1.0, 1.0));
    CHECK(m.density[1].transform.matrix_at(0.0)[3] == glm::dvec4(0.0, 0.0, 1.0, 1.0));
    CHECK(m.density[0].pigment_map.size() == 2);
    REQUIRE(scene.atmosphere.size() == 1);
    CHECK(scene.atmosphere[0].scattering.c[0].constant() == Approx(0.1));
}

TEST_CASE("media's checks are POV-Ray's, at their place", "[language][media]") {
    check_error_at("sphere { 0, 1 interior {\n media { method 4 } } }", "method is 1, 2 or 3", 2);
    check_error_at("sphere { 0, 1 interior {\n media { intervals 0 } } }", "at least one interval",
                   2);
    check_error_at("sphere { 0, 1 interior {\n media { samples 3, 2 } } }", "below its minimum", 2);
    check_error_at("sphere { 0, 1 interior {\n media { aa_level 0 } } }", "at least one", 2);
    check_error_at("sphere { 0, 1 interior {\n media { aa_threshold 0 } } }", "greater than zero",
                   2);
    check_error_at("sphere { 0, 1 interior { media {\n scattering { 1, 1 eccentricity 0.5 } } } }",
                   "eccentricity goes only with scattering type 5", 2);
    check_error_at("sphere { 0, 1 interior { media {\n density { density_file \"none.df3\" } } } }",
                   "df3", 2);
}

TEST_CASE("methods 1 and 2 with more samples than the minimum say they take the minimum",
          "[language][media]") {
    hexant::language::ParseOptions options;
    std::ostringstream messages;
    options.messages = &messages;
    const auto scene = hexant::language::parse_scene_text(
        "sphere { 0, 1 hollow interior {\n media { method 1 samples 2, 8 } } }", "test.pov",
        options);
    bool said = false;
    for (const auto& w : scene.warnings)
        said = said || (w.rfind("test.pov:2:", 0) == 0 &&
                        w.find("'samples' is read but not rendered") != std::string::npos);
    CHECK(said);
}
