// The photon map's kd-tree and gather (tracer/photon_map.hpp) against a
// brute-force search over the same photons: the nearest gather_max within
// the radius, the flattened distance, the radius the estimate divides by,
// POV-Ray's adaptive widening, and the radius chosen from the density.
#include "tracer/photon_map.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

namespace tr = hexant::tracer;
namespace rt = hexant::runtime;

namespace {

// `n` photons spread evenly at random over the unit square of the plane
// z = 0 (a floor lit evenly), plus `lift` of them on z = 0.5.
std::vector<tr::Photon> floor_photons(int n, std::uint32_t seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<tr::Photon> out(static_cast<std::size_t>(n));
    for (auto& p : out) {
        p.position = {u(random), u(random), 0.0f};
        p.colour = {1.0f, 1.0f, 1.0f};
        p.from = {0.0f, 0.0f, 1.0f};
    }
    return out;
}

// The squared distances of the `most` nearest photons to `point` within
// `reach`, stretched as the map's disc stretches them, by brute force.
std::vector<double> nearest(const std::vector<tr::Photon>& photons, const glm::dvec3& point,
                            const glm::dvec3& normal, double reach, int most) {
    std::vector<double> d;
    for (const auto& p : photons) {
        const glm::dvec3 offset = glm::dvec3(p.position) - point;
        double d2 = glm::dot(offset, offset);
        d2 += std::fabs(glm::dot(normal, offset)) * d2 * 16.0;
        if (d2 < reach * reach) d.push_back(d2);
    }
    std::sort(d.begin(), d.end());
    if (static_cast<int>(d.size()) > most) d.resize(static_cast<std::size_t>(most));
    return d;
}

}  // namespace

TEST_CASE("a photon gather finds the nearest photons a full search finds", "[tracer][photons]") {
    const auto photons = floor_photons(20000, 7);
    rt::PhotonSettings settings;
    settings.radius = 0.05;   // fixed: the gather alone is tested
    settings.gather_min = 0;  // (no widening)
    settings.gather_max = 100;
    const tr::PhotonMap map(photons, settings);
    REQUIRE(map.size() == photons.size());
    std::mt19937 random(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<const tr::Photon*> found;
    for (int k = 0; k < 200; ++k) {
        const glm::dvec3 point(u(random), u(random), 0.0);
        const glm::dvec3 normal(0.0, 0.0, 1.0);
        const double r = map.gather(point, normal, found);
        const auto expected = nearest(photons, point, normal, 0.05, 100);
        INFO("point " << point.x << ", " << point.y);
        REQUIRE(found.size() == expected.size());
        std::vector<double> got;
        for (const tr::Photon* p : found) {
            const glm::dvec3 offset = glm::dvec3(p->position) - point;
            got.push_back(glm::dot(offset, offset));
        }
        std::sort(got.begin(), got.end());
        for (std::size_t i = 0; i < got.size(); ++i) CHECK(got[i] == Approx(expected[i]));
        // The radius: the farthest kept where 100 were kept and more were
        // near, else the search radius (POV-Ray's gatherPhotons).
        if (expected.size() == 100 && nearest(photons, point, normal, 0.05, 101).size() == 101)
            CHECK(r == Approx(std::sqrt(expected.back())));
        else
            CHECK(r == Approx(0.05));
    }
}

TEST_CASE("a photon gather keeps to the surface's disc", "[tracer][photons]") {
    // A photon a little above the floor counts as much farther (POV-Ray's
    // flattening): gathering on the floor, the lifted ones are left out.
    auto photons = floor_photons(2000, 11);
    for (int i = 0; i < 200; ++i) {
        tr::Photon lifted = photons[static_cast<std::size_t>(i)];
        lifted.position.z = 0.03f;
        photons.push_back(lifted);
    }
    rt::PhotonSettings settings;
    settings.radius = 0.1;
    settings.gather_min = 0;
    settings.gather_max = 10000;
    const tr::PhotonMap map(photons, settings);
    std::vector<const tr::Photon*> found;
    map.gather({0.5, 0.5, 0.0}, {0.0, 0.0, 1.0}, found);
    int lifted = 0, flat = 0;
    for (const tr::Photon* p : found) (p->position.z > 0.0f ? lifted : flat)++;
    CHECK(flat > 0);
    // (Lifted ones within about 0.1 / sqrt(1 + 16 * 0.03) = 0.082 remain.)
    CHECK(lifted < flat / 2);
}

TEST_CASE("a sparse gather widens once, as POV-Ray's adaptive gather", "[tracer][photons]") {
    // 400 photons over the unit square: about 3 within 0.05 of a point,
    // fewer than gather_min 20; three times as wide holds about 28 at the
    // same density, so the wider gather is kept.
    const auto photons = floor_photons(400, 5);
    rt::PhotonSettings settings;
    settings.radius = 0.05;
    const tr::PhotonMap map(photons, settings);
    std::vector<const tr::Photon*> found;
    const double r = map.gather({0.5, 0.5, 0.0}, {0.0, 0.0, 1.0}, found);
    CHECK(r == Approx(0.15));
    CHECK(found.size() >= 15);
    // With expand_thresholds 0, 0 a density change of any size refuses it.
    settings.expand_tolerance = -1.0;
    settings.expand_min = 0;
    const tr::PhotonMap strict(photons, settings);
    CHECK(strict.gather({0.5, 0.5, 0.0}, {0.0, 0.0, 1.0}, found) == Approx(0.05));
}

TEST_CASE("the gather radius follows the map's density", "[tracer][photons]") {
    // Evenly spread, the radius holding gather_max photons at the mean
    // density, sqrt(100 / (pi n)) over the unit square, then widened by
    // POV-Ray's rule for sparse centres (here those near the square's
    // edges: about 2.3 times when written); four times the photons, half
    // the radius.
    const tr::PhotonMap coarse(floor_photons(5000, 13), rt::PhotonSettings{});
    const tr::PhotonMap fine(floor_photons(20000, 13), rt::PhotonSettings{});
    const double even = std::sqrt(100.0 / (3.14159265 * 5000));
    INFO("radius at 5000 photons " << coarse.radius() << " (even " << even << "), at 20000 "
                                   << fine.radius());
    CHECK(coarse.radius() >= even);
    CHECK(coarse.radius() <= even * 3.0);
    CHECK(fine.radius() / coarse.radius() == Approx(0.5).epsilon(0.25));
    // radius and its factor, when given, are taken as written.
    rt::PhotonSettings given;
    given.radius = 0.2;
    given.radius_factor = 1.5;
    CHECK(tr::PhotonMap(floor_photons(100, 1), given).radius() == Approx(0.3));
    // An empty map gathers nothing.
    const tr::PhotonMap empty({}, rt::PhotonSettings{});
    std::vector<const tr::Photon*> found;
    CHECK(empty.gather({0, 0, 0}, {0, 0, 1}, found) == 0.0);
    CHECK(found.empty());
}
