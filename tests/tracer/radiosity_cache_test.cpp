// The irradiance cache (tracer/radiosity_cache.hpp): POV-Ray 3.7's reuse
// rule (AverageNearBlock) record by record, and its index, which must find
// every record a point may reuse (its answer is the sum over all records).
#include "tracer/radiosity_cache.hpp"

#include <random>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

using hexant::tracer::RadiosityCache;
using hexant::tracer::RadiosityQuery;
using hexant::tracer::RadiosityRecord;
using hexant::tracer::RadiosityReuse;

namespace {

RadiosityRecord record_at(glm::dvec3 point, glm::dvec3 normal, double mean, int depth = 0) {
    RadiosityRecord r;
    r.point = point;
    r.normal = glm::normalize(normal);
    r.to_nearest = glm::normalize(normal);  // (along the normal: no effect on points beside)
    r.illuminance = glm::dvec3(0.25, 0.5, 0.75);
    r.harmonic_mean = mean;
    r.nearest = mean;
    r.depth = depth;
    return r;
}

double weight_of(const RadiosityRecord& r, const RadiosityQuery& q) {
    RadiosityReuse reuse;
    reuse.add(r, q);
    return reuse.weight;
}

}  // namespace

TEST_CASE("a record is reused by POV-Ray's rule", "[tracer][radiosity]") {
    const RadiosityRecord r = record_at({0, 0, 0}, {0, 1, 0}, 1.0);
    RadiosityQuery q{{0, 0, 0}, {0, 1, 0}, 1.0, 1.0, 0, false};
    // At the record, about its normal: the whole weight.
    CHECK(weight_of(r, q) == Approx(1.0));
    // Beside it, half its reach away: error 0.5 of the bound, weight 0.5
    // (linear), 0.5 too on the final trace's pseudo-sigmoid.
    q.point = {0.5, 0, 0};
    CHECK(weight_of(r, q) == Approx(0.5));
    q.smooth = true;
    CHECK(weight_of(r, q) == Approx(0.5));
    // A quarter away: linear 0.75, smooth 1 - 0.5^2 / 2 = 0.875.
    q.point = {0.25, 0, 0};
    CHECK(weight_of(r, q) == Approx(0.875));
    q.smooth = false;
    CHECK(weight_of(r, q) == Approx(0.75));
    // Beyond the bound: nothing; a wider bound reaches it.
    q.point = {1.2, 0, 0};
    CHECK(weight_of(r, q) == 0.0);
    q.error_bound = 2.0;
    CHECK(weight_of(r, q) == Approx(1.0 - 1.2 / 2.0));
    // The normals' difference counts: 2 sqrt(1 - cos) of the bound.
    q.point = {0, 0, 0};
    q.normal = glm::normalize(glm::dvec3(0, 1, 0.2));
    const double rotate = 2.0 * std::sqrt(1.0 - q.normal.y);
    CHECK(weight_of(r, q) == Approx(1.0 - rotate / 2.0));
    // A facing surface, another bounce, another brilliance: never.
    q.normal = {0, -1, 0};
    CHECK(weight_of(r, q) == 0.0);
    q.normal = {0, 1, 0};
    q.depth = 1;
    CHECK(weight_of(r, q) == 0.0);
    q.depth = 0;
    q.brilliance = 2.0;
    CHECK(weight_of(r, q) == 0.0);
    // An old point well in front of the new one (it may shadow it): not
    // reused; one just beside on the same surface is.
    q.brilliance = 1.0;
    q.error_bound = 1.0;
    const RadiosityRecord above = record_at({0, 0.5, 0}, {0, 1, 0}, 1.0);
    CHECK(weight_of(above, q) == 0.0);
    // (Its reach shrinks toward the nearest surface its rays met.)
    RadiosityRecord near_wall = record_at({0, 0, 0}, {0, 1, 0}, 1.0);
    near_wall.to_nearest = {1, 0, 0};
    near_wall.nearest = 0.2;
    q.point = {0.5, 0, 0};
    CHECK(weight_of(near_wall, q) == 0.0);
    q.point = {-0.5, 0, 0};
    CHECK(weight_of(near_wall, q) == Approx(0.5));
}

TEST_CASE("the cache's index finds every record a point may reuse", "[tracer][radiosity]") {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<RadiosityRecord> records;
    for (int i = 0; i < 3000; ++i) {
        // Points on a few planes and a sphere's worth of normals, reaches
        // from tiny to a tenth of the scene, two bounces.
        const glm::dvec3 p(u(random) * 10, std::floor(u(random) * 3), u(random) * 10);
        const glm::dvec3 n(u(random) * 0.3, 1.0, u(random) * 0.3);
        records.push_back(record_at(p, n, 0.01 + (u(random) + 1.0) * 0.5, i % 2));
        records.back().quality = 0.5 + 0.25 * (u(random) + 1.0);
    }
    // Reach: the most any query multiplies a harmonic mean by.
    RadiosityCache cache({2.0, 4.0});
    cache.add({records.data(), 1000});
    cache.add({records.data() + 1000, 2000});  // (a second pass, indexed again)
    REQUIRE(cache.size() == 3000);
    int reused = 0;
    for (int k = 0; k < 2000; ++k) {
        const RadiosityQuery q{{u(random) * 10, std::floor(u(random) * 3), u(random) * 10},
                               glm::normalize(glm::dvec3(u(random) * 0.3, 1.0, u(random) * 0.3)),
                               1.0,
                               1.0 + (u(random) + 1.0) * 0.5 * (k % 2 + 1),
                               k % 2,
                               k % 3 == 0};
        RadiosityReuse all, indexed;
        for (const RadiosityRecord& r : records) all.add(r, q);
        cache.gather(q, indexed);
        INFO("query " << k);
        CHECK(indexed.weight == Approx(all.weight).margin(1e-12));
        CHECK(indexed.weighted.y == Approx(all.weighted.y).margin(1e-12));
        reused += all.weight > 0.0;
    }
    // (The test means something: most queries reuse some record.)
    CHECK(reused > 500);
    cache.clear();
    RadiosityReuse none;
    cache.gather(RadiosityQuery{}, none);
    CHECK(none.weight == 0.0);
}
