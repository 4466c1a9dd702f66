// The 12-slab bound and the ray/slab-bound test: bounds hold what was added
// (exactly, whatever the magnitudes), and a ray that meets a bound anywhere
// along its segment is never reported as a miss (brute-force sampling of the
// segment against point containment), including rays lying in a slab's face,
// parallel to slabs, from far away and travelling in time.
#include <cmath>
#include <random>

#include <catch2/catch.hpp>

#include "runtime/bounds/slab_bound.hpp"
#include "runtime/bounds/slab_ray.hpp"
#include "runtime/geometry/spacetime.hpp"

using hexant::runtime::Box4;
using hexant::runtime::Event;
using hexant::runtime::kSlabCount;
using hexant::runtime::Ray4;
using hexant::runtime::slab_normals;
using hexant::runtime::SlabBound;
using hexant::runtime::SlabRay;

namespace {

struct Random {
    std::mt19937_64 engine;
    explicit Random(unsigned seed) : engine(seed) {}
    double uniform(double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(engine);
    }
    Event event(double half) {
        return {uniform(-half, half), uniform(-half, half), uniform(-half, half),
                uniform(-half, half)};
    }
    // A scale spread over decades, 1e-6 .. 1e6.
    double scale() { return std::pow(10.0, uniform(-6.0, 6.0)); }
};

}  // namespace

TEST_CASE("slab normals: four principal, eight auxiliary of unit length", "[slab]") {
    const auto& n = slab_normals();
    for (int k = 0; k < kSlabCount; ++k) {
        const double length =
            std::sqrt(n[k].x * n[k].x + n[k].y * n[k].y + n[k].z * n[k].z + n[k].w * n[k].w);
        CHECK(length == 1.0);
        if (k >= 4) CHECK(n[k].x == 0.5);
    }
    for (int a = 0; a < kSlabCount; ++a)
        for (int b = a + 1; b < kSlabCount; ++b) CHECK(n[a] != n[b]);
}

TEST_CASE("slab bounds hold every event and box added, at every scale", "[slab]") {
    Random random(7);
    for (int trial = 0; trial < 2000; ++trial) {
        const double scale = random.scale();
        const Event offset = random.event(1e6);
        SlabBound bound = SlabBound::empty();
        CHECK(bound.is_empty());
        std::vector<Event> events;
        for (int i = 0; i < 5; ++i) {
            events.push_back(offset + random.event(scale));
            bound.add(events.back());
        }
        Box4 box;
        box.lo = offset + random.event(scale);
        box.hi = box.lo + Event(random.uniform(0, scale), random.uniform(0, scale),
                                random.uniform(0, scale), random.uniform(0, scale));
        bound.add(box);
        REQUIRE_FALSE(bound.is_empty());
        for (const Event& e : events) REQUIRE(bound.contains(e));
        for (int i = 0; i < 16; ++i) {
            const Box4 corner = box.child(i);
            REQUIRE(bound.contains((i & 1) ? corner.hi : corner.lo));
            const Event inside(
                random.uniform(box.lo.x, box.hi.x), random.uniform(box.lo.y, box.hi.y),
                random.uniform(box.lo.z, box.hi.z), random.uniform(box.lo.w, box.hi.w));
            REQUIRE(bound.contains(inside));
        }
        // A point well outside the principal box is outside.
        const Box4 b = bound.box();
        REQUIRE_FALSE(bound.contains(b.hi + Event(b.hi - b.lo) + Event(scale)));
    }
}

TEST_CASE("auxiliary slabs cut the corners of a diagonal motion", "[slab]") {
    // A point moving from (0,0,0) at t = 0 to (1,1,1) at t = 1: its box is the
    // unit 4D cube, but the event (1, 0, 0, 0) is never reached, and the
    // slab with normal (.5, -.5, -.5, -.5)... cuts it away.
    SlabBound bound = SlabBound::empty();
    for (int i = 0; i <= 8; ++i) {
        const double u = i / 8.0;
        bound.add(Event(u, u, u, u));
    }
    CHECK(bound.contains(Event(0.5, 0.5, 0.5, 0.5)));
    CHECK_FALSE(bound.contains(Event(1.0, 0.0, 0.0, 0.0)));
    CHECK_FALSE(bound.contains(Event(0.0, 0.0, 0.0, 1.0)));
    // clip keeps only what lies in the box.
    Box4 half;
    half.lo = Event(0.0);
    half.hi = Event(0.5);
    bound.clip(half);
    CHECK(bound.contains(Event(0.25)));
    CHECK_FALSE(bound.contains(Event(0.75)));
}

TEST_CASE("ray against slab bound never misses what brute-force sampling finds", "[slab]") {
    Random random(11);
    int hits = 0, misses = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const double scale = random.scale();
        const Event offset = random.event(scale * 10.0);
        SlabBound bound = SlabBound::empty();
        for (int i = 0; i < 3; ++i) bound.add(offset + random.event(scale));
        if (trial % 2 == 0) {  // a thick bound too, not only thin hulls of points
            Box4 box;
            box.lo = offset + random.event(scale);
            box.hi = box.lo + Event(scale * 0.5);
            bound.add(box);
        }
        // Aim at an event near the bound from a random distance, sometimes
        // far away (1e6 times the bound's size).
        const Event target = offset + random.event(scale * 1.5);
        const double distance = scale * (trial % 4 == 0 ? 1e6 : random.uniform(1.0, 20.0));
        Event direction = random.event(1.0);
        if (trial % 5 == 0) direction.w = 0.0;  // a ray at one instant
        if (trial % 7 == 0) direction.y = 0.0;  // parallel to a principal slab
        const double length = std::sqrt(direction.x * direction.x + direction.y * direction.y +
                                        direction.z * direction.z + direction.w * direction.w);
        if (!(length > 0.0)) continue;
        direction /= length;
        const Ray4 ray{target - distance * direction, direction};
        const SlabRay slab_ray(ray);
        const double s_max = 2.0 * distance;
        double enter = 0.0, exit = 0.0;
        const bool hit = slab_ray.intersect(bound, 0.0, s_max, &enter, &exit);
        // Sampling around the target's parameter, where any meeting is.
        bool sampled = false;
        for (int i = 0; i <= 400; ++i) {
            const double s = distance + (i - 200) / 100.0 * 3.0 * scale;
            if (s < 0.0 || s > s_max) continue;
            if (bound.contains(ray.at(s))) {
                sampled = true;
                REQUIRE(hit);
                REQUIRE(enter <= s);
                REQUIRE(s <= exit);
            }
        }
        (sampled ? hits : misses) += 1;
    }
    // Both outcomes must have occurred for the check to mean anything.
    CHECK(hits > 1000);
    CHECK(misses > 1000);
}

TEST_CASE("rays lying in a slab face or touching a corner are not lost", "[slab]") {
    Box4 box;
    box.lo = Event(0.0);
    box.hi = Event(1.0);
    const SlabBound bound = SlabBound::of_box(box);
    // In the face x = 1, parallel to x.
    CHECK(SlabRay(Ray4{{1.0, -1.0, 0.5, 0.5}, {0.0, 1.0, 0.0, 0.0}}).intersect(bound, 0.0, 10.0));
    // Just outside the face: a miss.
    CHECK_FALSE(SlabRay(Ray4{{std::nextafter(1.0, 2.0), -1.0, 0.5, 0.5}, {0.0, 1.0, 0.0, 0.0}})
                    .intersect(bound, 0.0, 10.0));
    // Touching the corner (1,1,1,1) only, along a direction in the
    // auxiliary slab (.5,.5,.5,.5)'s face: n · d = 0.
    CHECK(SlabRay(Ray4{{2.0, 0.0, 1.0, 1.0}, {-1.0, 1.0, 0.0, 0.0}}).intersect(bound, 0.0, 10.0));
    // Through the corner (0,0,0,0) diagonally in time and space.
    CHECK(
        SlabRay(Ray4{{-1.0, -1.0, -1.0, 1.0}, {1.0, 1.0, 1.0, -1.0}}).intersect(bound, 0.0, 10.0));
    // A segment that ends just before the box is a miss; one that ends at
    // its face is a hit.
    const Ray4 along_x{{-2.0, 0.5, 0.5, 0.5}, {1.0, 0.0, 0.0, 0.0}};
    CHECK_FALSE(SlabRay(along_x).intersect(bound, 0.0, 1.5));
    CHECK(SlabRay(along_x).intersect(bound, 0.0, 2.0));
    // An infinite segment still culls by the principal slabs.
    CHECK(SlabRay(along_x).intersect(bound, 0.0, std::numeric_limits<double>::infinity()));
    CHECK_FALSE(SlabRay(Ray4{{-2.0, 5.0, 0.5, 0.5}, {1.0, 0.0, 0.0, 0.0}})
                    .intersect(bound, 0.0, std::numeric_limits<double>::infinity()));
    // An empty bound is never met.
    CHECK_FALSE(SlabRay(along_x).intersect(SlabBound::empty(), 0.0, 10.0));
}

TEST_CASE("Box4 children tile the box", "[slab]") {
    Box4 box;
    box.lo = Event(-1.0, 0.0, 2.0, 0.0);
    box.hi = Event(1.0, 4.0, 3.0, 1.0);
    double volume = 0.0;
    for (int i = 0; i < 16; ++i) {
        const Box4 c = box.child(i);
        volume += c.volume();
        CHECK(box.contains(c.lo));
        CHECK(box.contains(c.hi));
        CHECK((c.lo.w == 0.5) == bool(i & 8));
    }
    CHECK(volume == Approx(box.volume()).epsilon(1e-15));
    CHECK(box.time().lo == 0.0);
    CHECK(box.time().hi == 1.0);
    CHECK(Box4::empty().is_empty());
    CHECK(Box4::empty().volume() == 0.0);
}
