// mesh_camera { } as POV-Ray 3.7 reads it (Parse_Mesh_Camera): its rules,
// its meshes (an object keyword around a declared object, POV-Ray's
// Parse_Object_Id), and what the demo scenes' macros need beside it:
// `function { transform { } }` (transforms.inc's vtransform) and
// no_shadow followed by a macro's transform.
#include <memory>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <glm/mat4x4.hpp>

#include "language/interpreter.hpp"
#include "scene_text.hpp"

using hexant::test::check_error_at;
using hexant::test::scene_of;

namespace rt = hexant::runtime;

namespace {

// A mesh2 of `n` triangles in a row, declared as M.
std::string film(int n) {
    std::string s = "#declare M = mesh2 { vertex_vectors { " + std::to_string(3 * n);
    for (int i = 0; i < n; ++i)
        s += ", <" + std::to_string(i) + ", 0, 0>, <" + std::to_string(i + 1) + ", 0, 0>, <" +
             std::to_string(i) + ", -1, 0>";
    s += " } face_indices { " + std::to_string(n);
    for (int i = 0; i < n; ++i)
        s += ", <" + std::to_string(3 * i) + ", " + std::to_string(3 * i + 1) + ", " +
             std::to_string(3 * i + 2) + ">";
    return s + " } }\n";
}

}  // namespace

TEST_CASE("mesh_camera's rules are POV-Ray's, each an error at the camera", "[language][camera]") {
    const std::string m = film(4);
    check_error_at(m + "camera { mesh_camera { 0 0 mesh { M } } }", "rays per pixel may not be 0",
                   2);
    check_error_at(m + "camera { mesh_camera { 1 4 mesh { M } } }",
                   "unrecognized distribution method", 2);
    check_error_at(m + "camera { mesh_camera { 2 2 mesh { M } mesh { M } } }",
                   "must be 1 for distribution method #2 or #3", 2);
    check_error_at(m + "camera { mesh_camera { 1 0 mesh { M } smooth } }",
                   "smooth can only be used with distribution method #3", 2);
    check_error_at(m + "camera { mesh_camera { 2 0 mesh { M } } }",
                   "must be <= number of meshes for distribution method #0", 2);
    check_error_at("camera { mesh_camera { 1 0 } }", "needs a mesh", 1);
    check_error_at("#declare S = sphere { 0, 1 }\ncamera { mesh_camera { 1 0 sphere { S } } }",
                   "mesh and mesh2 objects only", 2);
    check_error_at(m + "camera { mesh_camera { 1 0 10 mesh { M } } }", "max distance", 2);
    check_error_at(m + "camera { location 0 mesh_camera { 1 0 mesh { M } } }", "must come first",
                   2);
}

TEST_CASE("a mesh camera keeps its meshes' faces in the order read, and their transforms",
          "[language][camera]") {
    const auto scene = scene_of(film(40) +
                                    "camera { mesh_camera { 2 1 mesh { M translate x * clock } "
                                    "mesh { M } } location <0, 0, 0.5> }",
                                hexant::test::animation());
    const rt::CameraFrame camera = scene.camera.evaluate(0.0);
    REQUIRE(camera.type == rt::CameraType::Mesh);
    REQUIRE(camera.mesh);
    CHECK(camera.mesh->meshes().size() == 2);
    // Distribution 1: ray 0 of pixel (5, 2) of a 10-pixel-wide image is
    // face 25, the first mesh's 25th: its centre x is 25 + 1/3; ray 1 is
    // face 25 + 80 (all the faces), past them: none.
    const auto ray = camera.mesh->ray(5.5, 2.0, 10, 10, 0, 0.5, false, 0.0);
    REQUIRE(ray);
    CHECK(ray->origin.x == Approx(25.0 + 1.0 / 3.0));
    CHECK(ray->origin.z == Approx(0.5));  // the normal (P3-P1)x(P2-P1) is +z here
    CHECK(ray->direction.z == Approx(1.0));
    CHECK_FALSE(camera.mesh->ray(5.5, 2.0, 10, 10, 1, 0.5, false, 0.0));
    // Face 45 is the second mesh's 5th, unmoved; the first mesh moves
    // with clock.
    CHECK(camera.mesh->ray(5.5, 4.0, 10, 10, 0, 0.0, false, 0.0)->origin.x ==
          Approx(5.0 + 1.0 / 3.0));
    CHECK(camera.mesh->ray(5.5, 2.0, 10, 10, 0, 0.0, false, 0.5)->origin.x ==
          Approx(25.5 + 1.0 / 3.0));
}

TEST_CASE("an object keyword around a declared object reads as object { }", "[language]") {
    const auto scene = scene_of(
        "#declare S = sphere { <1, 2, 3>, 1 }\nsphere { S translate x }\nunion { S scale 2 }");
    REQUIRE(scene.objects.size() == 2);
    CHECK(std::holds_alternative<rt::Sphere>(scene.objects[0]->shape));
    CHECK(scene.objects[0]->transform.matrix_at(0.0)[3][0] == 1.0);
    CHECK(scene.objects[1]->transform.matrix_at(0.0)[0][0] == 2.0);
}

TEST_CASE("function { transform { } } maps a point as POV-Ray's vtransform does", "[language]") {
    // POV-Ray 3.7 printed 5.769996111,1.427464455,5.588672647 and the
    // inverse's 1,-2,0.5 (transforms.inc's vtransform and vinv_transform).
    std::ostringstream said;
    hexant::language::ParseOptions options;
    options.messages = &said;
    (void)hexant::language::parse_scene_text(R"(
#declare T = transform { rotate <10, 20, 30> translate <1, 2, 3> scale 2 }
#declare F = function { transform { T } }
#declare G = function { transform { T inverse } }
#declare P = F(1, -2, 0.5);
#declare Q = G(P.x, P.y, P.z);
#debug concat(vstr(3, P, ",", 0, 9), " ", vstr(3, Q, ",", 0, 9))
)",
                                             "test.pov", options);
    CHECK(said.str() == "5.769996111,1.427464455,5.588672647 1.000000000,-2.000000000,0.500000000");
}

TEST_CASE("no_shadow takes no value: a macro's transform after it applies", "[language]") {
    const auto scene = scene_of(
        "#macro Place() transform { translate <0, 5, 0> } #end\n"
        "sphere { 0, 1 no_shadow Place() }\nsphere { 0, 1 hollow 0 }");
    REQUIRE(scene.objects.size() == 2);
    CHECK(scene.objects[0]->no_shadow);
    CHECK(scene.objects[0]->transform.matrix_at(0.0)[3][1] == 5.0);
}
