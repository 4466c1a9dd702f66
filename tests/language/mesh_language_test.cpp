// mesh { } and mesh2 { } as the language reads them (language/mesh_reading.*):
// POV-Ray 3.7's rules for sections, indices and normals, and the refusals.
#include <string>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/objects/shapes.hpp"
#include "tests/language/scene_text.hpp"

namespace rt = hexant::runtime;
using hexant::test::error_of;

namespace {

const rt::objects::MeshData& mesh_of(const std::string& text) {
    static rt::SceneDescription scene;
    scene = hexant::language::parse_scene_text(text, "t.pov", {});
    REQUIRE(scene.objects.size() == 1);
    return *std::get<rt::Mesh>(scene.objects[0]->shape).data;
}

bool says(const std::string& scene, const std::string& part) {
    const std::string message = error_of(scene).what();
    INFO(message);
    return message.find(part) != std::string::npos;
}

const char* kQuad = "vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> } ";

}  // namespace

TEST_CASE("mesh2 reads its sections by POV-Ray's rules", "[language][mesh]") {
    // Normals without normal_indices go by the vertex indices when there is
    // one per vertex; a face of three equal normals is flat.
    const auto& m = mesh_of(std::string("mesh2 { ") + kQuad +
                            "normal_vectors { 4, <0,0,-1>, <0,0,-1>, <0,0,-1>, <0.3,0,-1> } "
                            "face_indices { 2, <0,1,2>, <0,2,3> } }");
    REQUIRE(m.faces.size() == 2);
    int smooth = 0;
    for (const auto& f : m.faces) smooth += f.smooth();
    CHECK(smooth == 1);               // <0,2,3> has the odd normal; <0,1,2> is flat
    CHECK(m.hierarchy.depth() == 0);  // one leaf

    // Sections written by loops, texture indices after faces.
    const auto& looped = mesh_of(
        "mesh2 { vertex_vectors { 9, #for (I, 0, 8) <mod(I, 3), div(I, 3), 0>, #end } "
        "texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb x } } } "
        "face_indices { 8, #for (R, 0, 1) #for (C, 0, 1) #local A = R * 3 + C; "
        "<A, A + 1, A + 3>, 0, <A + 1, A + 4, A + 3>, 1, #end #end } }");
    CHECK(looped.faces.size() == 8);
    CHECK(looped.textures.size() == 2);
    int second = 0;
    for (const auto& f : looped.faces) second += f.texture == 1;
    CHECK(second == 4);
}

TEST_CASE("a mesh's refusals name what is wrong", "[language][mesh]") {
    CHECK(says("mesh { sphere { 0, 1 } }",
               "a mesh holds triangles and smooth_triangles, not a sphere"));
    CHECK(says("mesh { triangle { 0, x, y translate x } }", "cannot be transformed"));
    CHECK(says("mesh { }", "mesh has no triangles"));
    CHECK(says(std::string("mesh2 { ") + kQuad + "face_indices { 1, <0, 1, 5> } }",
               "face 0's vertex index 5 is beyond the 4 vertex_vectors"));
    CHECK(says("mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> } }",
               "vertex_vectors says it has 3 but lists 4"));
    CHECK(says(std::string("mesh2 { ") + kQuad +
                   "normal_vectors { 2, y, y } face_indices { 1, <0, 1, 2> } }",
               "no normal_indices section"));
    CHECK(says(std::string("mesh2 { ") + kQuad + "normal_indices { 1, <0, 1, 2> } }",
               "normal_indices must come after face_indices"));
    CHECK(says(std::string("mesh2 { ") + kQuad + "face_indices { 1, <0, 1, 2>, 0 } }",
               "face 0's texture index 0 is beyond the 0 textures"));
    const auto timed = error_of("mesh { triangle { 0, x * clock, y } }", hexant::test::animation());
    CHECK(std::string(timed.what()).find("depends on clock") != std::string::npos);
}
