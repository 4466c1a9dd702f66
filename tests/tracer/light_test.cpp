// A light as the shader reads it (tracer/light.hpp) against POV-Ray 3.7's
// rules written out by hand: the spotlight's cone and its smooth step, the
// cylinder's beam, fade, and the area light's grid: its rows' weights as
// POV-Ray's full subdivision gives them, jitter within cells, the circular
// grid's disc and orient's axes across the light's ray.
#include "tracer/light.hpp"

#include <cmath>
#include <map>
#include <numbers>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

namespace tr = hexant::tracer;
namespace rt = hexant::runtime;

namespace {

rt::LightRecord light_at(glm::dvec3 p) {
    rt::LightRecord r;
    r.position = rt::Vector3Function{{p.x, p.y, p.z}};
    r.colour.c = {1.0, 1.0, 1.0, 0.0, 0.0};
    return r;
}

double smooth_step(double low, double high, double x) {
    const double s = (x - low) / (high - low);
    return (3.0 - 2.0 * s) * s * s;
}

}  // namespace

TEST_CASE("a spotlight lights its cone, steps smoothly to its falloff and dims by tightness",
          "[tracer][light]") {
    rt::LightRecord r = light_at({0, 10, 0});
    r.kind = rt::LightKind::Spotlight;
    r.point_at = rt::Vector3Function{{0.0, 0.0, 0.0}};
    r.radius = 20.0;
    r.falloff = 40.0;
    r.tightness = 3.0;
    const tr::ShadedLight light(r);
    const auto at_angle = [&](double degrees) {
        const glm::dvec3 p(10.0 * std::tan(degrees * std::numbers::pi / 180.0), 0.0, 0.0);
        return light.attenuation(p, light.ray_from(p, 0.0), 0.0);
    };
    const auto rad = [](double d) { return std::cos(d * std::numbers::pi / 180.0); };
    CHECK(at_angle(0.0) == Approx(1.0));
    CHECK(at_angle(10.0) == Approx(std::pow(rad(10.0), 3.0)));
    CHECK(at_angle(30.0) ==
          Approx(std::pow(rad(30.0), 3.0) * smooth_step(rad(40.0), rad(20.0), rad(30.0))));
    CHECK(at_angle(45.0) == 0.0);
    // Behind the light: dark.
    CHECK(light.attenuation({0, 20, 0}, light.ray_from({0, 20, 0}, 0.0), 0.0) == 0.0);
}

TEST_CASE("a cylinder light is a beam along its axis, parallel, and dark behind",
          "[tracer][light]") {
    rt::LightRecord r = light_at({0, 10, 0});
    r.kind = rt::LightKind::Cylinder;
    r.parallel = true;
    r.point_at = rt::Vector3Function{{0.0, 0.0, 0.0}};
    r.radius = 1.0;
    r.falloff = 2.0;
    r.tightness = 2.0;
    const tr::ShadedLight light(r);
    for (const double off : {0.0, 0.5, 1.5, 2.5}) {
        const glm::dvec3 p(off, 0.0, 0.0);
        const tr::LightRay ray = light.ray_from(p, 0.0);
        CHECK(ray.direction.y == Approx(1.0));  // straight up the beam
        CHECK(ray.depth == Approx(10.0));       // to the plane through the light
        const double d = 1.0 - off / 2.0;
        const double expected = off >= 2.0  ? 0.0
                                : off > 1.0 ? d * d * smooth_step(0.0, 0.5, d)
                                            : d * d;
        CHECK(light.attenuation(p, ray, 0.0) == Approx(expected).margin(1e-12));
    }
    CHECK(light.attenuation({0, 11, 0}, light.ray_from({0, 11, 0}, 0.0), 0.0) == 0.0);
}

TEST_CASE("fade_distance and fade_power dim a light by 2 / (1 + (d / D)^P)", "[tracer][light]") {
    rt::LightRecord r = light_at({0, 0, 0});
    r.fade_distance = 2.0;
    r.fade_power = 2.0;
    const tr::ShadedLight light(r);
    for (const double d : {1.0, 2.0, 6.0}) {
        const glm::dvec3 p(d, 0.0, 0.0);
        CHECK(light.attenuation(p, light.ray_from(p, 0.0), 0.0) ==
              Approx(2.0 / (1.0 + (d / 2) * (d / 2))));
    }
    // A fade power of 0 (only a distance given) fades nothing, as POV-Ray.
    r.fade_power = 0.0;
    CHECK(tr::ShadedLight(r).attenuation({6, 0, 0}, tr::ShadedLight(r).ray_from({6, 0, 0}, 0.0),
                                         0.0) == 1.0);
}

TEST_CASE("an area light's grid rows weigh as POV-Ray's full subdivision", "[tracer][light]") {
    // Rows of 5 along x (0.5 apart over axis <2, 0, 0>), 4 along z: with
    // 4,000 evenly spread samples, row i of 5 is drawn 1/8, 1/4, 1/4, 1/4,
    // 1/8 of the time (the middle rows shared by two quarters at each
    // subdivision), each of 4 a quarter.
    rt::LightRecord r = light_at({0, 5, 0});
    r.area = rt::AreaLight{rt::Vector3Function{{2.0, 0.0, 0.0}},
                           rt::Vector3Function{{0.0, 0.0, 3.0}}, 5, 4};
    const tr::ShadedLight light(r);
    const tr::LightRay centre = light.ray_from({0, 0, 0}, 0.0);
    std::map<double, int> along_x, along_z;
    const int n = 4000;
    for (int i = 0; i < n; ++i) {
        const glm::dvec3 o = light.area_offset(
            {(i + 0.5) / n, (i * 0.618034 - std::floor(i * 0.618034))}, centre, 0.0);
        CHECK(o.y == 0.0);
        ++along_x[o.x];
        ++along_z[o.z];
    }
    REQUIRE(along_x.size() == 5);
    CHECK(along_x.begin()->first == Approx(-1.0));
    CHECK(along_x.rbegin()->first == Approx(1.0));
    const double expected_x[] = {0.125, 0.25, 0.25, 0.25, 0.125};
    int k = 0;
    for (const auto& [x, count] : along_x)
        CHECK(double(count) / n == Approx(expected_x[k++]).margin(0.002));
    REQUIRE(along_z.size() == 4);
    for (const auto& [z, count] : along_z) CHECK(double(count) / n == Approx(0.25).margin(0.01));
}

TEST_CASE(
    "jitter spreads an area light's points over their cells, and circular maps them into a disc",
    "[tracer][light]") {
    rt::LightRecord r = light_at({0, 5, 0});
    r.area = rt::AreaLight{rt::Vector3Function{{2.0, 0.0, 0.0}},
                           rt::Vector3Function{{0.0, 0.0, 2.0}}, 3, 3};
    r.jitter = true;
    const tr::ShadedLight jittered(r);
    const tr::LightRay centre = jittered.ray_from({0, 0, 0}, 0.0);
    double lowest = 1e9, highest = -1e9;
    for (int i = 0; i < 1000; ++i) {
        const glm::dvec3 o = jittered.area_offset({(i + 0.5) / 1000, 0.5}, centre, 0.0);
        lowest = std::min(lowest, o.x);
        highest = std::max(highest, o.x);
    }
    // Rows at -1, 0, 1, each jittered by half a row (0.5) either way.
    CHECK(lowest == Approx(-1.5).margin(0.01));
    CHECK(highest == Approx(1.5).margin(0.01));

    r.jitter = false;
    r.circular = true;
    r.area->size1 = r.area->size2 = 5;
    const tr::ShadedLight circular(r);
    double farthest = 0.0;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) {
            const glm::dvec3 o = circular.area_offset({(i + 0.5) / 5, (j + 0.5) / 5}, centre, 0.0);
            farthest = std::max(farthest, glm::length(o));
        }
    // The corners of the square come in to the disc of radius 1 (half the
    // axis), within POV-Ray's 0.001 offset.
    CHECK(farthest == Approx(1.0).margin(0.01));
}

TEST_CASE("orient turns an area light's axes across the ray to the lit point", "[tracer][light]") {
    rt::LightRecord r = light_at({3, 4, 0});
    r.area = rt::AreaLight{rt::Vector3Function{{1.0, 0.0, 0.0}},
                           rt::Vector3Function{{0.0, 1.0, 0.0}}, 3, 3};
    r.orient = true;
    const tr::ShadedLight light(r);
    const tr::LightRay centre = light.ray_from({0, 0, 0}, 0.0);
    for (const double u : {0.1, 0.5, 0.9})
        for (const double v : {0.1, 0.9}) {
            const glm::dvec3 o = light.area_offset({u, v}, centre, 0.0);
            CHECK(glm::dot(o, centre.direction) == Approx(0.0).margin(1e-12));
            CHECK(glm::length(o) <= std::sqrt(0.5) + 1e-12);  // a square of side |axis1|
        }
}

TEST_CASE("orient alone makes an area light circular, as POV-Ray does", "[tracer][light]") {
    // POV-Ray warns "This area light is now circular" and renders orient
    // as circular orient.
    rt::LightRecord r = light_at({3, 4, 0});
    r.area = rt::AreaLight{rt::Vector3Function{{1.0, 0.0, 0.0}},
                           rt::Vector3Function{{0.0, 1.0, 0.0}}, 4, 4};
    r.orient = true;
    const tr::ShadedLight orient(r);
    r.circular = true;
    const tr::ShadedLight both(r);
    const tr::LightRay centre = orient.ray_from({0, 0, 0}, 0.0);
    for (const double u : {0.05, 0.3, 0.7, 0.95})
        for (const double v : {0.05, 0.6})
            CHECK(orient.area_offset({u, v}, centre, 0.0) == both.area_offset({u, v}, centre, 0.0));
}

TEST_CASE("a point_at within POV-Ray's 1e-10 of the light gives it no direction",
          "[tracer][light]") {
    rt::LightRecord r = light_at({0, 6, -2});
    r.kind = rt::LightKind::Spotlight;
    r.radius = 10.0;
    r.falloff = 20.0;
    r.point_at = rt::Vector3Function{{0.0, 6.0 - 1e-11, -2.0}};
    const tr::ShadedLight light(r);
    const glm::dvec3 below(0, 0, -2);
    CHECK(light.attenuation(below, light.ray_from(below, 0.0), 0.0) == 0.0);
}
