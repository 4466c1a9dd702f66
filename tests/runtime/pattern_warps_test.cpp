// The warps' point mappings (runtime/texture/pattern/warps/) at points
// whose images follow from POV-Ray 3.7's warps.cpp by hand, and the black
// hole's repeat and centre as its parser's Check_BH_Parameters leaves
// them, in the order they were written. The images against POV-Ray's own
// renders are tests/tracer/pov_reference/patterns/warps.pov.
#include <cmath>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "runtime/texture/pattern/warps/black_hole_warp.hpp"
#include "runtime/texture/pattern/warps/cubic_warp.hpp"
#include "runtime/texture/pattern/warps/cylindrical_warp.hpp"
#include "runtime/texture/pattern/warps/planar_warp.hpp"
#include "runtime/texture/pattern/warps/point_warp.hpp"
#include "runtime/texture/pattern/warps/repeat_warp.hpp"
#include "runtime/texture/pattern/warps/spherical_warp.hpp"
#include "runtime/texture/pattern/warps/toroidal_warp.hpp"

namespace pt = hexant::runtime::pattern;
using glm::dvec3;

namespace {
dvec3 right_face() {
    return pt::cubic_point({2.0, 0.0, 0.0});
}
}  // namespace

TEST_CASE("a repeat warp copies its slab, offset and mirrored on odd copies",
          "[runtime][pattern][warp]") {
    const pt::RepeatAt r = pt::repeat_at(0, 2.0, {0.0, 0.5, 0.0}, {1.0, 0.0, 0.0});
    // Copy 0: unchanged.
    CHECK(pt::repeat_point(r, {1.5, 1.0, 1.0}) == dvec3(1.5, 1.0, 1.0));
    // Copy 1 (x in [2, 4)): mirrored in x within the slab, moved by one offset.
    CHECK(pt::repeat_point(r, {2.5, 1.0, 1.0}) == dvec3(1.5, 1.5, 1.0));
    // Copy -1: mirrored too, moved back by one offset.
    CHECK(pt::repeat_point(r, {-0.5, 1.0, 1.0}) == dvec3(0.5, 0.5, 1.0));
    // The width is kept in single precision, as POV-Ray's SNGL Width.
    CHECK(pt::repeat_at(1, 0.1, dvec3(0.0), dvec3(0.0)).width == 0.1f);
}

TEST_CASE("the mapping warps give POV-Ray's coordinates", "[runtime][pattern][warp]") {
    pt::MappingAt m;
    CHECK(pt::planar_point(m, {1.0, 2.0, 3.0}) == dvec3(1.0, 2.0, 0.0));
    // Around y from +x toward +z: an eighth of a turn at (1, 0, 1).
    const dvec3 c = pt::cylindrical_point(m, {1.0, 5.0, 1.0});
    CHECK(c.x == Approx(0.125));
    CHECK(c.y == 5.0);
    CHECK(c.z == Approx(std::sqrt(2.0)));
    // On the axis: left where it is.
    CHECK(pt::cylindrical_point(m, {0.0, 5.0, 0.0}) == dvec3(0.0, 5.0, 0.0));
    // The north pole: longitude 0, latitude 1, distance 2.
    CHECK(pt::spherical_point(m, {0.0, 2.0, 0.0}) == dvec3(0.0, 1.0, 2.0));
    // dist_exp 1 scales the angles by the distance.
    m.dist_exp = 1.0;
    CHECK(pt::spherical_point(m, {0.0, 2.0, 0.0}) == dvec3(0.0, 2.0, 2.0));
    m.dist_exp = 0.0;
    // Outside a tube of major radius 1, on +x: no turn around y, half a
    // turn around the tube, 0.5 from its centre.
    m.major_radius = 1.0;
    CHECK(pt::toroidal_point(m, {1.5, 0.0, 0.0}) == dvec3(0.0, 0.5, 0.5));
    // The +x face's centre: the cross's right middle square.
    const dvec3 right = pt::cubic_point({2.0, 0.0, 0.0});
    CHECK(right.x == 0.625);
    CHECK(right.y == Approx(0.5));
    CHECK(right.z == 2.0);
    const dvec3 back = pt::cubic_point({0.0, 0.0, -2.0});
    CHECK(back.x == 0.875);
    CHECK(back.y == Approx(0.5));
    CHECK(back.z == 2.0);
    // A normal along y: the plane's point (x, y, distance) turned to
    // (x, -distance, y), POV-Ray's sum.
    m.orientation = pt::unit_orientation({0.0, 3.0, 0.0});
    CHECK(pt::planar_point(m, {1.0, 2.0, 3.0}) == dvec3(1.0, -0.0, 2.0));
}

TEST_CASE("a black hole's repeat is widened as POV-Ray's parser widens it, in order",
          "[runtime][pattern][warp]") {
    pt::BlackHoleWarp w;
    w.center = {{0.0, 0.0, 0.0}};
    w.radius = 0.5;
    w.placements.push_back({true, {{0.5, 0.0, 0.0}}});
    w.placements.push_back({false, {{0.25, 0.0, 0.0}}});
    const auto numbers = [](const pt::BlackHoleWarp& hole) {
        std::vector<double> n;
        for (const auto& f : pt::black_hole_numbers(hole)) n.push_back(f.constant());
        return n;
    };
    // Repeat then turbulence: the centre moved to the radius, the repeat
    // widened to centre + radius, then by the turbulence too.
    pt::BlackHoleAt h = pt::black_hole_at(w, numbers(w).data());
    CHECK(h.center.x == 0.5);
    CHECK(h.repeat.x == 1.25);
    CHECK(h.repeats);
    CHECK(h.uncertain);
    // A point at a copy's centre is left alone; one halfway to the rim is
    // read a quarter of its distance (0.5^2) further out, which draws the
    // pattern in.
    h.uncertain = false;
    CHECK(pt::black_hole_point(h, {0.5 + 1.25, 0.0, 0.0}) == dvec3(1.75, 0.0, 0.0));
    CHECK(pt::black_hole_point(h, {0.25, 0.0, 0.0}) == dvec3(0.1875, 0.0, 0.0));
    // A negative turbulence written after the repeat cannot narrow it.
    w.placements[1].amount = {{-0.5, 0.0, 0.0}};
    CHECK(pt::black_hole_at(w, numbers(w).data()).repeat.x == 1.0);
    // Written before the repeat it counts in full (the repeat is checked
    // only once it is written): 0.5 + 0.5 - 0.5 asks for no widening.
    std::swap(w.placements[0], w.placements[1]);
    CHECK(pt::black_hole_at(w, numbers(w).data()).repeat.x == 0.5);
}

TEST_CASE("a compiled warp whose numbers move reads them at the hit's time",
          "[runtime][pattern][warp]") {
    pt::RepeatWarp r;
    r.axis = 0;
    r.width = 1.0;
    r.offset = {{hexant::runtime::TimeFunction::clock(), 0.0, 0.0}};
    const pt::CompiledPointWarp moving(r);
    // Copy 2 moved by twice the offset: 2 clock.
    CHECK(moving.apply({2.5, 0.0, 0.0}, 0.0) == dvec3(0.5, 0.0, 0.0));
    CHECK(moving.apply({2.5, 0.0, 0.0}, 0.25) == dvec3(1.0, 0.0, 0.0));
    pt::MappingWarp cubic;
    cubic.shape = pt::MappingShape::Cubic;
    CHECK(pt::CompiledPointWarp(cubic).apply({2.0, 0.0, 0.0}, 0.0) == right_face());
}
