// Property tests of bound(region): for every object kind, static, moving
// (translation, a fast rotation of ten turns per unit of time, a spline
// path, moving parameters) and deformed (twist, taper and bend with moving
// amounts, and a stiff twist of 30 turns per unit length), random surface
// events at random times inside random 4D regions must lie inside the
// bounds the object returns for that region.
//
// The surface events come from the independent reference in
// object_test_support.hpp. Each variant checks property_samples() events
// that fall inside their region: 10^5 in the suite; run
//   HEXANT_PROPERTY_SAMPLES=10000000 build/tests/hexant_tests "[property]"
// for 10^7 per variant.
#include <cstdio>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "object_test_support.hpp"
#include "runtime/bounds/slab_bound.hpp"

using namespace object_test;

namespace {

// The reference reaches a surface event by other roundings than the code
// under test (at most some tens of operations on numbers no larger than the
// event's coordinates, each within 2^-53 of its result; a stiff twist's
// angle of ~200 radians adds its own relative 1e-16). Their difference stays
// below 1e-13 of the event's magnitude; 1e-12 leaves a factor of ten, while
// a real hole in a bound is many orders larger.
constexpr double kRelativeSlack = 1e-12;

bool inside_some(const std::vector<rt::SlabBound>& bounds, const rt::Event& e) {
    const double magnitude =
        std::max({std::fabs(e.x), std::fabs(e.y), std::fabs(e.z), std::fabs(e.w), 1.0});
    const double slack = kRelativeSlack * magnitude;
    const auto& normals = rt::slab_normals();
    for (const auto& b : bounds) {
        bool in = true;
        for (int k = 0; k < rt::kSlabCount && in; ++k) {
            const double d = glm::dot(normals[k], e);
            in = d >= b.lo[k] - slack && d <= b.hi[k] + slack;
        }
        if (in) return true;
    }
    return false;
}

// Runs every variant of one kind.
void check_kind(const KindScene& kind) {
    const std::string& keyword = kind.keyword;
    const long wanted = property_samples();
    Random random(std::hash<std::string>{}(keyword));
    for (const Variant& variant : variants()) {
        const std::string sdl = std::string(kPath) + keyword + " { " +
                                (variant.moving_parameters ? kind.moving : kind.fixed) + " " +
                                variant.transform + " }\n";
        INFO(keyword << ", " << variant.name << ": " << sdl);
        const Parsed parsed = parse(sdl);
        REQUIRE(parsed.objects.size() == 1);
        const rt::IntelligentObject& object = *parsed.objects.front();
        const rt::ObjectRecord& record = *parsed.scene.objects.front();
        REQUIRE(object.bounded());
        // The variant is what it says: moving unless static, deformed when so named.
        const std::string name = variant.name;
        CHECK(object.moves() == (name != "static"));
        CHECK(object.deformed() ==
              (name.find("twist") != std::string::npos || name == "taper" || name == "bend"));

        // The root region: the object's own bound over [0, 1], widened a little.
        rt::Box4 everywhere;
        everywhere.lo = rt::Event(-1e3, -1e3, -1e3, 0.0);
        everywhere.hi = rt::Event(1e3, 1e3, 1e3, 1.0);
        std::vector<rt::SlabBound> all;
        object.bound(everywhere, all);
        REQUIRE_FALSE(all.empty());
        rt::Box4 root;
        for (const auto& b : all) root.extend(b.box());
        const rt::Event margin = 0.01 * root.extent();
        root.lo -= rt::Event(glm::dvec3(margin), 0.0);
        root.hi += rt::Event(glm::dvec3(margin), 0.0);

        long checked = 0, attempts = 0;
        std::vector<rt::SlabBound> bounds;
        while (checked < wanted && attempts < 200 * wanted) {
            // A random cell of the root's 16-way subdivision, 0 to 3 levels
            // down, or a random box inside the root.
            rt::Box4 region = root;
            if (random.integer(0, 3) == 0) {
                for (int i = 0; i < 4; ++i) {
                    const double a = random.uniform(root.lo[i], root.hi[i]);
                    const double b = random.uniform(root.lo[i], root.hi[i]);
                    region.lo[i] = std::min(a, b);
                    region.hi[i] = std::max(a, b);
                }
            } else {
                const int depth = random.integer(0, 3);
                for (int d = 0; d < depth; ++d) region = region.child(random.integer(0, 15));
            }
            bounds.clear();
            object.bound(region, bounds);
            for (int k = 0; k < 2000; ++k, ++attempts) {
                const double t = random.uniform(region.lo.w, region.hi.w);
                const rt::Event e = sample_surface_event(record, t, random);
                if (!region.contains(e)) continue;
                ++checked;
                if (!inside_some(bounds, e)) {
                    INFO("event " << e.x << ' ' << e.y << ' ' << e.z << ' ' << e.w << " region "
                                  << region.lo.x << ' ' << region.lo.y << ' ' << region.lo.z << ' '
                                  << region.lo.w << " .. " << region.hi.x << ' ' << region.hi.y
                                  << ' ' << region.hi.z << ' ' << region.hi.w << ", "
                                  << bounds.size() << " bounds");
                    FAIL("a surface event outside the bounds");
                }
            }
        }
        CHECK(checked >= wanted);
    }
}

}  // namespace

TEST_CASE("bound holds the surface: sphere", "[object][property]") {
    check_kind(kind_scene("sphere"));
}

TEST_CASE("bound holds the surface: box", "[object][property]") {
    check_kind(kind_scene("box"));
}

TEST_CASE("bound holds the surface: polygon", "[object][property]") {
    check_kind(kind_scene("polygon"));
}

TEST_CASE("bound holds the surface: triangle and smooth_triangle", "[object][property]") {
    check_kind(kind_scene("triangle"));
    check_kind(kind_scene("smooth_triangle"));
}

TEST_CASE("bound holds the surface: disc", "[object][property]") {
    check_kind(kind_scene("disc"));
}

TEST_CASE("bound holds the surface: cylinder and cone", "[object][property]") {
    check_kind(kind_scene("cylinder"));
    check_kind(kind_scene("cone"));
}

TEST_CASE("bound holds the surface: torus", "[object][property]") {
    check_kind(kind_scene("torus"));
}

TEST_CASE("bound holds the surface: prism", "[object][property]") {
    check_kind(kind_scene("prism"));
}

TEST_CASE("bound holds the surface: text", "[object][property]") {
    check_kind(kind_scene("text"));
}

TEST_CASE("bound holds the surface: lathe and sor", "[object][property]") {
    check_kind(kind_scene("lathe"));
    check_kind(kind_scene("sor"));
}

TEST_CASE("bound holds the surface: mesh", "[object][property]") {
    check_kind(kind_scene("mesh"));
}

TEST_CASE("bound holds the surface: superellipsoid", "[object][property]") {
    check_kind(kind_scene("superellipsoid"));
}

TEST_CASE("bound holds the surface: isosurface", "[object][property]") {
    check_kind(kind_scene("isosurface"));
}

TEST_CASE("bound holds the surface: julia_fractal", "[object][property]") {
    check_kind(kind_scene("julia_fractal"));
}

TEST_CASE("bound holds the surface: bicubic_patch", "[object][property]") {
    check_kind(kind_scene("bicubic_patch"));
}

TEST_CASE("bound holds the surface: height_field", "[object][property]") {
    check_kind(kind_scene("height_field"));
}

TEST_CASE("bound holds the surface: blob", "[object][property]") {
    check_kind(kind_scene("blob"));
}

TEST_CASE("bound holds the surface: sphere_sweep", "[object][property]") {
    check_kind(kind_scene("sphere_sweep"));
}

TEST_CASE("a mesh answers a small region with several smaller bounds (the star cluster)",
          "[object]") {
    // A 40 x 40 grid of quads in the x-y plane from 0 to 4: its hierarchy's
    // nodes are its bound's pieces where the region is small against it.
    std::string sdl = "mesh {\n";
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j) {
            const double x = 0.1 * i, y = 0.1 * j, z = 0.02 * ((i * 7 + j * 3) % 5);
            char quad[256];
            std::snprintf(quad, sizeof quad,
                          "triangle { <%g, %g, %g>, <%g, %g, 0>, <%g, %g, 0> } "
                          "triangle { <%g, %g, 0>, <%g, %g, 0>, <%g, %g, %g> }\n",
                          x, y, z, x + 0.1, y, x, y + 0.1, x + 0.1, y, x + 0.1, y + 0.1, x, y + 0.1,
                          z);
            sdl += quad;
        }
    sdl += "}\n";
    const Parsed parsed = parse(sdl);
    const rt::IntelligentObject& object = *parsed.objects.front();
    rt::Box4 whole;
    whole.lo = rt::Event(-1.0, -1.0, -1.0, 0.0);
    whole.hi = rt::Event(5.0, 5.0, 1.0, 1.0);
    std::vector<rt::SlabBound> all;
    object.bound(whole, all);
    CHECK(all.size() == 1);  // the region holds it all: one bound
    // A region a tenth of its size, across its middle: several pieces, each
    // much smaller than the one bound the region would clip.
    rt::Box4 small;
    small.lo = rt::Event(1.75, 1.0, -1.0, 0.0);
    small.hi = rt::Event(2.25, 3.0, 1.0, 1.0);
    std::vector<rt::SlabBound> pieces;
    object.bound(small, pieces);
    CHECK(pieces.size() >= 2);
    double volume = 0.0;
    for (const auto& b : pieces) volume += b.box().volume();
    CHECK(volume < 0.5 * small.volume());
    // And every surface event in the region lies in one of them.
    Random random(5);
    const rt::ObjectRecord& record = *parsed.scene.objects.front();
    int checked = 0;
    for (int k = 0; k < 20000; ++k) {
        const rt::Event e = sample_surface_event(record, random.uniform(0.0, 1.0), random);
        if (!small.contains(e)) continue;
        ++checked;
        REQUIRE(inside_some(pieces, e));
    }
    CHECK(checked > 100);
}

TEST_CASE("a plane is unbounded and gives no bound", "[object]") {
    const Parsed parsed = parse("plane { <0, 1, 0>, -1 translate <0, clock, 0> }\n");
    REQUIRE(parsed.objects.size() == 1);
    CHECK_FALSE(parsed.objects.front()->bounded());
    std::vector<rt::SlabBound> bounds;
    rt::Box4 region;
    region.lo = rt::Event(-1.0);
    region.hi = rt::Event(1.0);
    parsed.objects.front()->bound(region, bounds);
    CHECK(bounds.empty());
}

TEST_CASE("bounds of a fast spinner over a short time are thin arcs, not the whole circle",
          "[object]") {
    const Parsed parsed = parse("sphere { <2, 0, 0>, 0.1 rotate <0, 3600 * clock, 0> }\n");
    const auto& object = *parsed.objects.front();
    rt::Box4 region;
    region.lo = rt::Event(-10, -10, -10, 0.25);
    region.hi = rt::Event(10, 10, 10, 0.25 + 1e-4);  // 0.36 degrees of the turn
    std::vector<rt::SlabBound> bounds;
    object.bound(region, bounds);
    REQUIRE_FALSE(bounds.empty());
    rt::Box4 box;
    for (const auto& b : bounds) box.extend(b.box());
    const rt::Event e = box.extent();
    // The sphere's diameter plus the arc (2 pi 2 / 1000 ~ 0.0126), with room
    // for rounding; the whole circle would be 4.2 wide.
    CHECK(e.x < 0.25);
    CHECK(e.z < 0.25);
    // Over a quarter turn, the swept bound splits into runs (arcs) that
    // together stay far below the quarter circle's box. (Over many turns
    // every run is a whole circle; there the hierarchy's time splits make
    // the regions short.)
    region.lo.w = 0.0;
    region.hi.w = 0.025;
    bounds.clear();
    object.bound(region, bounds);
    CHECK(bounds.size() > 1);
}
