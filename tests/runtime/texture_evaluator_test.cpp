// A compiled texture answers with its own finish: finishes of the same
// constants are shared between textures (one kept for a scene of many
// objects that differ in colour only), and sharing never hands a texture
// another's numbers, nor a time-dependent finish a frozen one.
#include "runtime/texture/texture_evaluator.hpp"

#include <memory>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

namespace rt = hexant::runtime;

namespace {

rt::Texture texture_with(double phong, double red) {
    rt::Texture t;
    t.finish.edit().phong = phong;
    t.pigment.colours[0].c[0] = red;
    return t;
}

}  // namespace

TEST_CASE("textures answer with their own finish, shared or not", "[runtime][texture]") {
    const std::optional<rt::Interior> none;
    std::vector<std::unique_ptr<rt::TextureEvaluator>> made;
    // Interleaved: a shared finish must not leak into a texture with other numbers.
    for (int k = 0; k < 200; ++k)
        made.push_back(std::make_unique<rt::TextureEvaluator>(
            texture_with(k % 3 == 0 ? 0.6 : 0.2 + 0.001 * k, 0.01 * k), none));
    for (int k = 0; k < 200; ++k) {
        const rt::MaterialSample m = made[k]->at({0, 0, 0}, {0, 0}, 0.5);
        REQUIRE(m.phong == (k % 3 == 0 ? 0.6 : 0.2 + 0.001 * k));
        REQUIRE(m.colour.x == 0.01 * k);
        REQUIRE(m.ior == 1.0);
    }
    // Freed and made again: the table forgets, the numbers stay right.
    made.clear();
    rt::Interior glass;
    glass.ior = 1.5;
    const rt::TextureEvaluator again(texture_with(0.6, 1.0), glass);
    CHECK(again.at({0, 0, 0}, {0, 0}, 0.0).phong == 0.6);
    CHECK(again.at({0, 0, 0}, {0, 0}, 0.0).ior == 1.5);
    const rt::TextureEvaluator plain(texture_with(0.6, 1.0), none);
    CHECK(plain.at({0, 0, 0}, {0, 0}, 0.0).ior == 1.0);

    rt::Texture timed = texture_with(0.6, 1.0);
    timed.finish.edit().phong = rt::TimeFunction::clock();
    const rt::TextureEvaluator moving(timed, none);
    CHECK(moving.depends_on_time());
    CHECK(moving.at({0, 0, 0}, {0, 0}, 0.25).phong == 0.25);
    CHECK(moving.at({0, 0, 0}, {0, 0}, 0.75).phong == 0.75);
}

TEST_CASE("a colour moving with clock and an interior's parts survive the compact form",
          "[runtime][texture]") {
    // A colour is kept as five numbers or one tape for the five, and an
    // interior's parts (fading, ior, caustics, media, key) in one box that
    // only an interior makes: each channel still moves on its own, and a
    // copy keeps every part.
    const std::optional<rt::Interior> none;
    rt::Texture timed;
    timed.pigment.colours[0].c[0] = rt::TimeFunction::clock();
    timed.pigment.colours[0].c[1] = 0.5;
    timed.pigment.colours[0].c[3] = 1.0 - rt::TimeFunction::clock();
    const rt::TextureEvaluator moving(timed, none);
    CHECK(moving.depends_on_time());
    for (const double t : {0.0, 0.25, 0.75}) {
        const rt::MaterialSample m = moving.at({0, 0, 0}, {0, 0}, t);
        CHECK(m.colour.x == t);
        CHECK(m.colour.y == 0.5);
        CHECK(m.colour.z == 0.0);
        CHECK(m.filter == 1.0 - t);
    }

    rt::TextureEvaluator plain(rt::Texture{}, none);
    plain.set_media(nullptr);
    plain.set_interior_key(nullptr);
    CHECK(plain.media() == nullptr);
    CHECK(plain.interior_key() == nullptr);
    CHECK_FALSE(plain.fade_at(0.0));
    CHECK(plain.ior_at(0.0) == 1.0);
    CHECK(plain.caustics_at(0.0) == 0.0);

    rt::Interior glass;
    glass.ior = 1.5;
    glass.caustics = 0.5;
    glass.fade_distance = 2.0;
    glass.fade_power = 1.0;
    rt::TextureEvaluator inside(rt::Texture{}, glass);
    const auto key = std::make_shared<int>(7);
    inside.set_interior_key(key);
    inside.set_interior_texture(rt::Texture{}, glass);
    const rt::TextureEvaluator copy = inside;
    for (const rt::TextureEvaluator* e : {&std::as_const(inside), &copy}) {
        CHECK(e->ior_at(0.0) == 1.5);
        CHECK(e->caustics_at(0.0) == 0.5 * 45.0);
        REQUIRE(e->fade_at(0.0));
        CHECK(e->fade_at(0.0)->distance == 2.0);
        CHECK(e->interior_key() == key.get());
        REQUIRE(e->interior_texture() != nullptr);
        CHECK(e->interior_texture()->interior_key() == key.get());
        CHECK(e->interior_texture()->ior_at(0.0) == 1.5);
    }
    // A key set back to none is none again.
    inside.set_interior_key(nullptr);
    CHECK(inside.interior_key() == nullptr);
    CHECK(copy.interior_key() == key.get());
}
