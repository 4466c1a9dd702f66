// A compiled texture answers with its own finish: finishes of the same
// constants are shared between textures (one kept for a scene of many
// objects that differ in colour only), and sharing never hands a texture
// another's numbers, nor a time-dependent finish a frozen one.
#include "runtime/texture/texture_evaluator.hpp"

#include <memory>
#include <vector>

#include <catch2/catch.hpp>

namespace rt = hexant::runtime;

namespace {

rt::Texture texture_with(double phong, double red) {
    rt::Texture t;
    t.finish.phong = phong;
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
    timed.finish.phong = rt::TimeFunction::clock();
    const rt::TextureEvaluator moving(timed, none);
    CHECK(moving.depends_on_time());
    CHECK(moving.at({0, 0, 0}, {0, 0}, 0.25).phong == 0.25);
    CHECK(moving.at({0, 0, 0}, {0, 0}, 0.75).phong == 0.75);
}
