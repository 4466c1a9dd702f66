// The refraction list a ray carries (tracer/inside.hpp): POV-Ray 3.7's
// rules for the iors a surface separates (ComputeRefraction) and for the
// relative ior Fresnel reflection sees there (ComputeRelativeIOR).
#include "tracer/inside.hpp"

#include <catch2/catch.hpp>

using hexant::tracer::Inside;

namespace {
// Three interiors, known by address as the shader knows them.
int interiors[3];
const void* const glass = &interiors[0];
const void* const water = &interiors[1];
const void* const ball = &interiors[2];
}  // namespace

TEST_CASE("a ray enters, nests and leaves interiors as POV-Ray's list says", "[tracer]") {
    Inside air, in_glass, in_water, back_in_glass, out;
    // From the atmosphere into glass (1.5): n1 / n2.
    CHECK(air.refract(glass, 1.5, false, in_glass) == Approx(1.0 / 1.5));
    REQUIRE(in_glass.passed_count == 1);
    // Into water held by the glass: glass's ior over water's.
    CHECK(in_glass.refract(water, 1.33, false, in_water) == Approx(1.5 / 1.33));
    REQUIRE(in_water.passed_count == 2);
    // Out of the innermost, into the glass around it.
    CHECK(in_water.refract(water, 1.33, false, back_in_glass) == Approx(1.33 / 1.5));
    CHECK(back_in_glass.passed_count == 1);
    CHECK(back_in_glass.holds(glass));
    CHECK_FALSE(back_in_glass.holds(water));
    // Out of the glass into the atmosphere.
    CHECK(back_in_glass.refract(glass, 1.5, false, out) == Approx(1.5));
    CHECK(out.passed_count == 0);
}

TEST_CASE("the overlap of two objects belongs to the one entered last", "[tracer]") {
    Inside in_a, in_both, in_b;
    Inside().refract(glass, 1.5, false, in_a);
    in_a.refract(ball, 1.2, false, in_both);
    // Leaving a (not the innermost): no bending, and the ray is in b alone.
    CHECK(in_both.refract(glass, 1.5, false, in_b) == 1.0);
    REQUIRE(in_b.passed_count == 1);
    CHECK(in_b.holds(ball));
}

TEST_CASE("a surface met from inside an object the list lacks is entered", "[tracer]") {
    // (a height field's open side let the ray in: POV-Ray enters where it
    // meets the surface), unless the ray is known to have started inside
    // (a camera in the object): then it leaves.
    Inside next;
    CHECK(Inside().refract(glass, 1.2, false, next) == Approx(1.0 / 1.2));
    CHECK(next.passed_count == 1);
    CHECK(Inside().refract(glass, 1.2, true, next) == Approx(1.2));
    CHECK(next.passed_count == 0);
}

TEST_CASE("Fresnel's relative ior follows ComputeRelativeIOR, quirk and all", "[tracer]") {
    const Inside air;
    const Inside in_glass = air.entered(glass, 1.5);
    const Inside dome_and_glass = air.entered(ball, 1.0).entered(glass, 1.5);
    CHECK(air.relative_ior(glass, 1.5, false) == Approx(1.5));
    CHECK(in_glass.relative_ior(glass, 1.5, false) == Approx(1.0 / 1.5));
    // Leaving the innermost of several: POV-Ray divides its ior by itself.
    CHECK(dome_and_glass.relative_ior(glass, 1.5, false) == 1.0);
    // Entering water from glass: water's over glass's.
    CHECK(in_glass.relative_ior(water, 1.33, false) == Approx(1.33 / 1.5));
    // entered() does not enter twice.
    CHECK(in_glass.entered(glass, 1.5).passed_count == 1);
}

TEST_CASE("dispersion's ratio and bands follow the iors' list", "[tracer][dispersion]") {
    // POV-Ray's ComputeRefraction: the dispersions' ratio is taken as the
    // iors' is (the atmosphere's is 1); leaving into another interior the
    // ray splits into the more bands of the two; an overlap left is none.
    const Inside::Index glass_index{1.5, 1.1, 4}, water_index{1.33, 1.3, 6};
    Inside in_glass, in_water, back_in_glass, out;
    Inside::Ratio r = Inside().refract(glass, glass_index, false, in_glass);
    CHECK(r.ior == Approx(1.0 / 1.5));
    CHECK(r.dispersion == Approx(1.0 / 1.1));
    CHECK(r.dispersion_samples == 4);
    r = in_glass.refract(water, water_index, false, in_water);
    CHECK(r.dispersion == Approx(1.1 / 1.3));
    CHECK(r.dispersion_samples == 6);
    r = in_water.refract(water, water_index, false, back_in_glass);
    CHECK(r.dispersion == Approx(1.3 / 1.1));
    CHECK(r.dispersion_samples == 6);  // the more of water's 6 and glass's 4
    r = back_in_glass.refract(glass, glass_index, false, out);
    CHECK(r.dispersion == Approx(1.1));
    CHECK(r.dispersion_samples == 4);
    Inside in_both, in_ball;
    in_glass.refract(ball, {1.2, 1.4, 7}, false, in_both);
    r = in_both.refract(glass, glass_index, false, in_ball);
    CHECK(r.ior == 1.0);
    CHECK(r.dispersion == 1.0);
}

TEST_CASE("a copy of the lists holds what they hold, over a longer list too", "[tracer]") {
    // Inside copies only the places in use (inside.hpp): a copy, and an
    // assignment over a list that held more, must still give every query's
    // answer of the original.
    int keys[2 * Inside::kMost];
    const auto* fog = reinterpret_cast<const hexant::runtime::MediaVolume*>(&keys[0]);
    Inside many;
    for (int k = 0; k < Inside::kMost; ++k)
        many = many.with({&keys[k], k % 2 ? fog : nullptr, k % 2 == 0})
                   .entered(&keys[Inside::kMost + k], 1.0 + 0.1 * k);
    Inside few = Inside{}.with({glass, nullptr, false}).entered(water, 1.33);
    Inside copy = many;
    copy = few;  // over eight places of another list
    const Inside constructed(few);
    for (const Inside* c : {static_cast<const Inside*>(&copy), &constructed}) {
        CHECK(c->count == 1);
        CHECK(c->passed_count == 1);
        CHECK(c->contains(glass));
        CHECK_FALSE(c->contains(water));
        CHECK_FALSE(c->hollow());
        CHECK_FALSE(c->has_media());
        CHECK(c->holds(water));
        CHECK_FALSE(c->holds(glass));
        CHECK(c->relative_ior(ball, 1.5, false) == Approx(1.5 / 1.33));
    }
    // And the long list copied whole.
    const Inside long_copy(many);
    CHECK(long_copy.passed_count == many.passed_count);
    CHECK(long_copy.count == many.count);
    for (int i = 0; i < many.passed_count; ++i)
        CHECK(long_copy.passed[std::size_t(i)].index.ior == many.passed[std::size_t(i)].index.ior);
    CHECK(long_copy.has_media());
}
