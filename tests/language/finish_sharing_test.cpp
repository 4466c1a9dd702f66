// Equal finishes are one block (runtime/texture/finish_pool.hpp): a scene
// of 10^5 spheres written with the same finish holds it once (issue 43's
// memory), while each object still reads, and may change, its own.
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/shared_value.hpp"
#include "runtime/texture/finish_pool.hpp"

namespace rt = hexant::runtime;

namespace {

// An animation of two frames, so that `clock` is a function of time.
rt::SceneDescription read(const std::string& text) {
    hexant::language::ParseOptions options;
    options.animation.initial_frame = 1;
    options.animation.final_frame = 2;
    std::ostringstream messages;
    options.messages = &messages;
    return hexant::language::parse_scene_text(text, "test.pov", options);
}

const rt::Finish* block_of(const rt::SceneDescription& scene, std::size_t i) {
    REQUIRE(scene.objects.at(i)->texture);
    return scene.objects[i]->texture->finish.block();
}

}  // namespace

TEST_CASE("objects written with equal finishes share one", "[language][texture][memory]") {
    const auto scene = read(R"(
#declare I = 0;
#while (I < 3)
  sphere { <I, 0, 0>, 0.3 pigment { rgb I / 3 } finish { phong 0.6 phong_size 40 } }
  #declare I = I + 1;
#end
sphere { 0, 1 pigment { rgb 1 } finish { phong 0.6 phong_size 41 } }
sphere { 0, 1 pigment { rgb 1 } finish { phong 0.6 * clock } }
sphere { 0, 1 pigment { rgb 1 } finish { phong 0.6 * clock } }
sphere { 0, 1 pigment { rgb 1 } finish { phong 0.6 phong_size 40 reflection { 0.1 } } }
)");
    REQUIRE(scene.objects.size() == 7);
    const rt::Finish* shared = block_of(scene, 0);
    REQUIRE(shared != nullptr);
    CHECK(block_of(scene, 1) == shared);
    CHECK(block_of(scene, 2) == shared);
    CHECK(shared->phong.constant() == 0.6);
    CHECK(shared->phong_size.constant() == 40.0);
    // A number apart, a function of time, a reflection: each its own.
    CHECK(block_of(scene, 3) != shared);
    CHECK(scene.objects[3]->texture->finish->phong_size.constant() == 41.0);
    REQUIRE(scene.objects[4]->texture->finish->phong.depends_on_time());
    CHECK(block_of(scene, 4) != block_of(scene, 5));
    CHECK(block_of(scene, 6) != shared);
    CHECK(scene.objects[6]->texture->finish->reflection.c[0].constant() == 0.1);
}

TEST_CASE("a finish modified on one object leaves the others' alone",
          "[language][texture][memory]") {
    const auto scene = read(R"(
#declare T = texture { pigment { rgb 1 } finish { diffuse 0.3 phong 1 } }
sphere { 0, 1 texture { T } }
sphere { 0, 1 texture { T finish { phong 0.5 } } }
sphere { 0, 1 texture { T } }
)");
    REQUIRE(scene.objects.size() == 3);
    CHECK(block_of(scene, 0) == block_of(scene, 2));
    const rt::Finish& changed = scene.objects[1]->texture->finish;
    CHECK(changed.phong.constant() == 0.5);
    CHECK(changed.diffuse.constant() == 0.3);  // kept from T (POV-Ray's Parse_Finish)
    const rt::Finish& kept = scene.objects[0]->texture->finish;
    CHECK(kept.phong.constant() == 1.0);
    CHECK(kept.diffuse.constant() == 0.3);
}

TEST_CASE("SharedValue copies share until one is edited", "[runtime][memory]") {
    rt::SharedValue<rt::Finish> a;
    CHECK(a.block() == nullptr);          // the default, no block
    CHECK(a->diffuse.constant() == 0.6);  // POV-Ray's default
    a.edit().phong = 0.25;
    rt::SharedValue<rt::Finish> b = a;
    CHECK(b.block() == a.block());
    b.edit().phong = 0.75;  // b's own block now
    CHECK(b.block() != a.block());
    CHECK(a->phong.constant() == 0.25);
    CHECK(b->phong.constant() == 0.75);
    const rt::Finish* before = b.block();
    b.edit().diffuse = 0.5;  // b alone holds it: written in place
    CHECK(b.block() == before);
}

TEST_CASE("the finish pool keeps apart what differs in any amount or flag", "[runtime][memory]") {
    rt::FinishPool pool;
    const auto plain = pool.share(rt::Finish{});
    CHECK(pool.share(rt::Finish{}) == plain);
    rt::Finish negative_zero;
    negative_zero.phong = -0.0;  // differs from 0 in its bits only
    CHECK(pool.share(std::move(negative_zero)) != plain);
    rt::Finish fresnel;
    fresnel.reflection_fresnel = true;
    CHECK(pool.share(std::move(fresnel)) != plain);
    rt::Finish irid;
    irid.irid_turbulence = 0.1;  // the last amount of all
    CHECK(pool.share(std::move(irid)) != plain);
    rt::Finish emission;
    emission.emission[2] = 1.0;
    CHECK(pool.share(std::move(emission)) != plain);
    rt::Finish reflection_max;
    reflection_max.reflection_max = rt::ColourFunction{};
    CHECK(pool.share(std::move(reflection_max)) != plain);
    rt::Finish noted;
    noted.unrendered.push_back({});
    const auto noted_block = pool.share(rt::Finish(noted));
    CHECK(noted_block != plain);
    CHECK(pool.share(std::move(noted)) != noted_block);  // not pooled
    CHECK(pool.size() == 6);
}
