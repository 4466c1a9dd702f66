// The three modes answer every ray alike: the spacetime hierarchy and the
// per-frame hierarchies against brute force, on moving scenes (fast
// rotation, objects crossing cell walls, objects spanning many cells, a
// plane), for rays in general position, rays lying in cell walls and rays at
// the instants where the time splits fall; shadow queries too.
#include "tracer/ray_query.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "../runtime/object_test_support.hpp"

using namespace object_test;
namespace tr = hexant::tracer;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Thirty-odd objects: a crowd of small spheres on fast circles (several
// turns per unit of time), boxes sliding across the root, a long thin
// cylinder spanning many cells, triangles, a twisted box, a torus, a
// union, and a floor plane.
std::string moving_scene() {
    std::string sdl =
        "#declare Path = spline { cubic_spline -0.5, <0, 0, 0> 0, <1, 0, 0> 0.5, <1, 2, 0> "
        "1, <-1, 1, 1> 1.5, <0, 0, 0> }\n";
    for (int i = 0; i < 16; ++i) {
        char line[256];
        std::snprintf(line, sizeof line,
                      "sphere { <%g, %g, 0>, %g rotate <0, %g * clock, 0> translate <0, 0, %g> }\n",
                      1.0 + 0.2 * i, -2.0 + 0.25 * i, 0.1 + 0.02 * (i % 5), 360.0 * (1 + i % 7),
                      -1.0 + 0.15 * i);
        sdl += line;
    }
    for (int i = 0; i < 6; ++i) {
        char line[256];
        std::snprintf(line, sizeof line,
                      "box { <-0.3, -0.3, -0.3>, <0.3, 0.3, 0.3> rotate <%d, %d, 0> "
                      "translate <-4 + 8 * clock, %g, %g> }\n",
                      10 * i, 25 * i, -2.0 + 0.8 * i, 2.0 - 0.7 * i);
        sdl += line;
    }
    sdl +=
        "cylinder { <-3.5, 0.1, -3>, <3.5, 0.3, 3>, 0.05 }\n"
        "triangle { <-1, 2, -1>, <1, 2.5, -1>, <0, 3, 1> translate <0, -clock, 0> }\n"
        "triangle { <2, -2, 2>, <3, -1, 2>, <2.5, -2, 3> }\n"
        "box { <-0.3, -1, -0.3>, <0.3, 1, 0.3> twist <0, 1, 0>, 180 * clock translate <-2, 0, 2> "
        "}\n"
        "torus { 0.6, 0.15 rotate <90, 0, 0> translate Path(clock) }\n"
        "union { sphere { <0, 0, 0>, 0.3 } sphere { <0.5, 0, 0>, 0.2 } translate <2, 2, -2> "
        "rotate <0, 0, 720 * clock> }\n"
        "plane { <0, 1, 0>, -3.2 }\n";
    return sdl;
}

// The root: the objects' own extent over [0, 1].
hexant::runtime::Box4 root_box(const tr::ObjectSet& set) {
    return tr::enclosing_box(set, 0.0, 1.0);
}

void require_same(const std::optional<hexant::runtime::ObjectHit>& got,
                  const std::optional<hexant::runtime::ObjectHit>& expected) {
    INFO("got " << (got ? got->s : -1.0) << " expected " << (expected ? expected->s : -1.0));
    REQUIRE(bool(got) == bool(expected));
    if (got) REQUIRE(std::fabs(got->s - expected->s) <= 1e-12 * (1.0 + std::fabs(expected->s)));
}

}  // namespace

// The hierarchy's settings the modes must agree under: both criteria, lazy
// and eager builds, every style of bound.
std::vector<std::pair<std::string, tr::BuildOptions>> build_settings() {
    std::vector<std::pair<std::string, tr::BuildOptions>> all;
    for (const auto criterion : {tr::Criterion::Cost, tr::Criterion::Paper})
        for (const auto build : {tr::BuildKind::Lazy, tr::BuildKind::Eager})
            for (const auto bounds : {tr::BoundStyle::Auto, tr::BoundStyle::Box,
                                      tr::BoundStyle::Linear, tr::BoundStyle::Slabs}) {
                tr::BuildOptions o;
                o.criterion = criterion;
                o.build = build;
                o.bounds = bounds;
                const std::string name =
                    std::string(criterion == tr::Criterion::Cost ? "cost" : "paper") + "/" +
                    (build == tr::BuildKind::Lazy ? "lazy" : "eager") + "/" +
                    std::to_string(int(bounds));
                all.emplace_back(name, o);
            }
    return all;
}

TEST_CASE("spacetime, frames and brute force find the same first hits on a moving scene",
          "[tracer]") {
    const Parsed parsed = parse(moving_scene());
    const auto set = tr::ObjectSet::of(parsed.objects);
    REQUIRE(set.unbounded.size() == 1);
    const hexant::runtime::Box4 root = root_box(set);
    for (const auto& [name, options] : build_settings()) {
        INFO("build " << name);
        tr::Counters counters;
        auto brute = tr::make_ray_query(tr::Mode::Brute, set, root, options, counters);
        auto spacetime = tr::make_ray_query(tr::Mode::Spacetime, set, root, options, counters);
        auto frames = tr::make_ray_query(tr::Mode::Frames, set, root, options, counters);
        if (options.build == tr::BuildKind::Eager)
            CHECK(counters.cells > 100);  // the hierarchy really subdivides
        tr::ThreadState a{tr::Mailbox(set.size()), {}}, b{tr::Mailbox(set.size()), {}},
            c{tr::Mailbox(set.size()), {}};
        Random random(77);
        int hits = 0;
        const int frame_count = 8;
        for (int frame = 0; frame < frame_count; ++frame) {
            const double t0 = double(frame) / frame_count, t1 = double(frame + 1) / frame_count;
            frames->prepare_frame(t0, t1, counters);
            for (int i = 0; i < 600; ++i) {
                // Rays in general position; every fifth lies in a cell wall of
                // the first three levels (x, y or z at an eighth of the root);
                // every seventh is at an instant where the time splits fall.
                double t = random.uniform(t0, t1);
                if (i % 7 == 0) t = t0;
                glm::dvec3 origin = 6.0 * random.unit_vector();
                glm::dvec3 aim(random.uniform(-4, 4), random.uniform(-4, 4), random.uniform(-4, 4));
                glm::dvec3 d = glm::normalize(aim - origin);
                if (i % 5 == 0) {
                    const int axis = i % 3;
                    const double wall = root.lo[axis] + (root.hi[axis] - root.lo[axis]) *
                                                            random.integer(1, 7) / 8.0;
                    origin[axis] = wall;
                    d[axis] = 0.0;
                    if (glm::length(d) == 0.0) continue;
                    d = glm::normalize(d);
                }
                const hexant::runtime::Ray4 ray{hexant::runtime::Event(origin, t),
                                                hexant::runtime::Event(d, 0.0)};
                INFO("frame " << frame << " ray " << i);
                const auto expected = brute->first_hit(ray, 0.0, kInf, a);
                INFO("origin " << origin.x << ' ' << origin.y << ' ' << origin.z << " d " << d.x
                               << ' ' << d.y << ' ' << d.z << " t " << t);
                {
                    INFO("spacetime");
                    require_same(spacetime->first_hit(ray, 0.0, kInf, b), expected);
                }
                {
                    INFO("frames");
                    require_same(frames->first_hit(ray, 0.0, kInf, c), expected);
                }
                if (expected) {
                    ++hits;
                    // Shadow queries up to just before the hit, and past it.
                    const double before = expected->s * 0.5;
                    const bool blocked = brute->occluded(ray, 0.0, before, a);
                    REQUIRE(spacetime->occluded(ray, 0.0, before, b) == blocked);
                    REQUIRE(frames->occluded(ray, 0.0, before, c) == blocked);
                    REQUIRE(spacetime->occluded(ray, 0.0, expected->s * 1.01 + 1e-9, b));
                }
            }
        }
        CHECK(hits > 1000);
        // The hierarchies test far fewer objects per ray than brute force.
        CHECK(b.counters.object_tests * 3 < a.counters.object_tests);
    }
}

TEST_CASE("rays that travel in time take the double-precision walk and find the same hits",
          "[tracer]") {
    // A finite speed of light: each ray's time runs along it. No renderer
    // path makes these yet; the runtime answers them and so must the walk.
    const Parsed parsed = parse(moving_scene());
    const auto set = tr::ObjectSet::of(parsed.objects);
    const hexant::runtime::Box4 root = root_box(set);
    for (const auto& [name, options] : build_settings()) {
        INFO("build " << name);
        tr::Counters counters;
        auto brute = tr::make_ray_query(tr::Mode::Brute, set, root, options, counters);
        auto spacetime = tr::make_ray_query(tr::Mode::Spacetime, set, root, options, counters);
        tr::ThreadState a{tr::Mailbox(set.size()), {}}, b{tr::Mailbox(set.size()), {}};
        Random random(5);
        int hits = 0;
        for (int i = 0; i < 150; ++i) {
            const glm::dvec3 origin = 6.0 * random.unit_vector();
            const glm::dvec3 aim(random.uniform(-3, 3), random.uniform(-3, 3),
                                 random.uniform(-3, 3));
            const glm::dvec3 d = glm::normalize(aim - origin);
            const hexant::runtime::Ray4 ray{
                hexant::runtime::Event(origin, random.uniform(0.1, 0.5)),
                hexant::runtime::Event(d, 0.02)};
            INFO("ray " << i);
            // A finite segment: time stays inside the animation.
            const auto expected = brute->first_hit(ray, 0.0, 12.0, a);
            require_same(spacetime->first_hit(ray, 0.0, 12.0, b), expected);
            hits += expected ? 1 : 0;
        }
        CHECK(hits > 20);
    }
}

TEST_CASE("each object is tested at most once per ray however many cells hold it", "[tracer]") {
    // A long cylinder crosses many cells; a ray along it meets it in all.
    const Parsed parsed = parse(
        "cylinder { <-4.5, 0.01, 0.01>, <4.5, 0.01, 0.01>, 0.3 }\n"
        "sphere { <0, 3, 0>, 0.5 } sphere { <0, -3, 0>, 0.5 }\n"
        "sphere { <3, 3, 0>, 0.5 } sphere { <-3, -3, 0>, 0.5 }\n");
    tr::Counters counters;
    const auto set = tr::ObjectSet::of(parsed.objects);
    const hexant::runtime::Box4 root = root_box(set);
    // The paper's criterion cuts the long cylinder into many cells.
    tr::BuildOptions options;
    options.criterion = tr::Criterion::Paper;
    auto spacetime = tr::make_ray_query(tr::Mode::Spacetime, set, root, options, counters);
    tr::ThreadState state{tr::Mailbox(set.size()), {}};
    const hexant::runtime::Ray4 ray{hexant::runtime::Event(-4.4, 0.0, 0.0, 0.5),
                                    hexant::runtime::Event(1.0, 0.0, 0.0, 0.0)};
    // From inside the cylinder: the first hit is its far cap, many cells away.
    const auto hit = spacetime->first_hit(ray, 0.0, kInf, state);
    REQUIRE(hit);
    CHECK(hit->s == Approx(8.9));
    CHECK(state.counters.object_tests == 1);
    CHECK(state.counters.mailbox_hits > 0);
}

TEST_CASE("a static scene builds no time splits, a moving one does", "[tracer]") {
    const auto counts = [](const std::string& sdl, tr::Criterion criterion) {
        const Parsed parsed = parse(sdl);
        const auto set = tr::ObjectSet::of(parsed.objects);
        tr::Counters counters;
        tr::BuildOptions options;
        options.criterion = criterion;
        options.build = tr::BuildKind::Eager;
        tr::make_ray_query(tr::Mode::Spacetime, set, root_box(set), options, counters);
        return counters;
    };
    // Enough objects that separating them pays under either criterion. They
    // turn (a translation is followed exactly by linear-motion bounds, so
    // the cost criterion rightly cuts no time for it).
    std::string still, moving;
    for (int i = 0; i < 40; ++i) {
        char line[160];
        std::snprintf(line, sizeof line, "sphere { <%d, %d, %d>, 0.3 }\n", i % 8, i / 8, i % 3);
        still += line;
        std::snprintf(line, sizeof line,
                      "sphere { <%d, %d, %d>, 0.3 translate <8, 0, 0> rotate y * 360 * clock }\n",
                      i % 8, i / 8, i % 3);
        moving += line;
    }
    for (const auto criterion : {tr::Criterion::Cost, tr::Criterion::Paper}) {
        INFO("criterion " << int(criterion));
        const tr::Counters s = counts(still, criterion), m = counts(moving, criterion);
        // The paper's criterion subdivides space; the cost criterion may
        // keep 40 objects in one cell, whose leaf is an eight-wide SAH
        // hierarchy over them.
        if (criterion == tr::Criterion::Paper) CHECK(s.cells > 1);
        CHECK(s.object_refs >= 40);
        CHECK(s.time_splits == 0);
        CHECK(m.time_splits > 0);
    }
}
