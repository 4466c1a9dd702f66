// The `hexant dump` format, line by line, on scene records built by hand.
#include "app/scene_dump.hpp"

#include <algorithm>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

namespace rt = hexant::runtime;

namespace {

rt::TimeFunction symbolic_clock() {
    return rt::TimeFunction::clock();
}

rt::Vector3Function vec(rt::TimeFunction x, rt::TimeFunction y, rt::TimeFunction z) {
    return rt::Vector3Function{{x, y, z}};
}

rt::TransformStep step(rt::TransformKind kind, rt::Vector3Function v,
                       rt::TimeFunction amount = 0.0) {
    rt::TransformStep s{};
    s.kind = kind;
    s.vector = v;
    s.amount = amount;
    return s;
}

std::shared_ptr<rt::ObjectRecord> object(rt::Shape shape) {
    auto o = std::make_shared<rt::ObjectRecord>();
    o->shape = std::move(shape);
    return o;
}

std::vector<std::string> dump(const rt::SceneDescription& scene, double t) {
    std::ostringstream out;
    hexant::app::dump_scene(scene, t, out);
    std::vector<std::string> lines;
    std::istringstream in(out.str());
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

const std::string kIdentity = "transform=[1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0]";
const std::string kFlags = "no_shadow=0 hollow=0 inverse=0";

}  // namespace

TEST_CASE("dump: an empty scene is POV-Ray's default camera and a black background",
          "[app][dump]") {
    const auto lines = dump(rt::SceneDescription{}, 0.0);
    REQUIRE(lines.size() == 2);
    CHECK(lines[0] ==
          "camera location=<0, 0, 0> direction=<0, 0, 1> right=<1.33, 0, 0> up=<0, 1, 0> "
          "sky=<0, 1, 0>");
    CHECK(lines[1] == "background colour=<0, 0, 0, 0, 0>");
}

TEST_CASE("dump: the camera, background and lights at the clock asked for", "[app][dump]") {
    rt::SceneDescription scene;
    rt::CameraItem location{};
    location.kind = rt::CameraItem::Kind::Location;
    location.vector = vec(0.0, 0.0, symbolic_clock() * -10.0);
    scene.camera.items.push_back(location);
    scene.background = rt::ColourFunction{{symbolic_clock(), 0.5, 1.0, 0.0, 0.25}};
    rt::LightRecord light;
    light.position = vec(0.0, 10.0, 0.0);
    light.colour = rt::ColourFunction{{1.0, 1.0, 1.0, 0.0, 0.0}};
    light.shadowless = true;
    light.transform.append(step(rt::TransformKind::Translate, vec(symbolic_clock(), 0.0, 0.0)));
    scene.lights.push_back(light);
    scene.lights.push_back(rt::LightRecord{});
    const auto lines = dump(scene, 0.5);
    REQUIRE(lines.size() == 4);
    CHECK(lines[0] ==
          "camera location=<0, 0, -5> direction=<0, 0, 1> right=<1.33, 0, 0> up=<0, 1, 0> "
          "sky=<0, 1, 0>");
    CHECK(lines[1] == "background colour=<0.5, 0.5, 1, 0, 0.25>");
    CHECK(lines[2] == "light[0] position=<0.5, 10, 0> colour=<1, 1, 1, 0, 0> shadowless=1");
    CHECK(lines[3] == "light[1] position=<0, 0, 0> colour=<0, 0, 0, 0, 0> shadowless=0");
}

TEST_CASE("dump: a moving sphere with its matrix and texture", "[app][dump]") {
    rt::SceneDescription scene;
    auto sphere = object(rt::Sphere{vec(symbolic_clock() * 2.0, 0.0, 0.0), symbolic_clock() + 0.5});
    // translate <1, 2, 3> then scale 2: POV-Ray's matrix has rows x, y, z, translation.
    sphere->transform.append(step(rt::TransformKind::Translate, vec(1.0, 2.0, 3.0)));
    sphere->transform.append(step(rt::TransformKind::Scale, vec(2.0, 2.0, 2.0)));
    rt::Texture texture;
    texture.pigment.colours[0] = rt::ColourFunction{{1.0, 0.5, symbolic_clock(), 0.0, 0.0}};
    texture.finish.edit().phong = 1.0;
    texture.finish.edit().reflection = rt::ColourFunction{{0.25, 0.25, 0.25, 0.0, 0.0}};
    sphere->texture = texture;
    sphere->no_shadow = true;
    scene.objects.push_back(sphere);
    const auto lines = dump(scene, 0.25);
    REQUIRE(lines.size() == 3);
    CHECK(lines[2] ==
          "object[0] sphere center=<0.5, 0, 0> radius=0.75 transform=[2, 0, 0, 0, 2, 0, 0, 0, 2, "
          "2, 4, 6] "
          "pigment=solid<1, 0.5, 0.25, 0, 0> finish=ambient:0.1,diffuse:0.6,brilliance:1,phong:1,"
          "phong_size:40,specular:0,roughness:0.05,reflection:<0.25, 0.25, 0.25> "
          "no_shadow=1 hollow=0 inverse=0");
}

TEST_CASE("dump: numbers as %.10g, never -0", "[app][dump]") {
    rt::SceneDescription scene;
    scene.objects.push_back(object(rt::Sphere{vec(1.0 / 3.0, -0.0, 1e-12), 123456789012.0}));
    const auto lines = dump(scene, 0.0);
    REQUIRE(lines.size() == 3);
    CHECK(lines[2] == "object[0] sphere center=<0.3333333333, 0, 1e-12> radius=1.23456789e+11 " +
                          kIdentity + " " + kFlags);
}

TEST_CASE("dump: each shape's own keys", "[app][dump]") {
    rt::SceneDescription scene;
    scene.objects.push_back(object(rt::Box{vec(-1.0, -1.0, -1.0), vec(1.0, 2.0, 3.0)}));
    scene.objects.push_back(object(rt::Plane{vec(0.0, 1.0, 0.0), -symbolic_clock()}));
    scene.objects.push_back(
        object(rt::Polygon{{vec(0.0, 0.0, 0.0), vec(1.0, 0.0, 0.0), vec(0.0, 1.0, 0.0)}}));
    scene.objects.push_back(object(
        rt::Triangle{{vec(0.0, 0.0, 0.0), vec(1.0, 0.0, 0.0), vec(0.0, 1.0, 0.0)}, std::nullopt}));
    scene.objects.push_back(
        object(rt::SmoothTriangle{{vec(0.0, 0.0, 0.0), vec(1.0, 0.0, 0.0), vec(0.0, 1.0, 0.0)},
                                  {vec(0.0, 0.0, 1.0), vec(0.0, 0.0, 2.0), vec(0.0, 0.0, 3.0)},
                                  std::nullopt}));
    scene.objects.push_back(object(rt::Disc{vec(0.0, 0.0, 0.0), vec(0.0, 1.0, 0.0), 2.0, 0.5}));
    scene.objects.push_back(
        object(rt::Cylinder{vec(0.0, 0.0, 0.0), vec(0.0, symbolic_clock(), 0.0), 0.5, true}));
    scene.objects.push_back(
        object(rt::Cone{vec(0.0, 0.0, 0.0), 1.0, vec(0.0, 1.0, 0.0), 0.0, false}));
    scene.objects.push_back(object(rt::Torus{2.0, 0.25}));
    scene.objects.push_back(object(
        rt::Prism{0.0,
                  1.0,
                  {rt::Vector2Function{{0.0, 0.0}}, rt::Vector2Function{{1.0, symbolic_clock()}}},
                  false,
                  {}}));
    const auto lines = dump(scene, 2.0);
    REQUIRE(lines.size() == 12);
    const std::vector<std::string> shapes = {
        "object[0] box corner1=<-1, -1, -1> corner2=<1, 2, 3>",
        "object[1] plane normal=<0, 1, 0> distance=-2",
        "object[2] polygon points=<0, 0, 0>;<1, 0, 0>;<0, 1, 0>",
        "object[3] triangle p1=<0, 0, 0> p2=<1, 0, 0> p3=<0, 1, 0>",
        "object[4] smooth_triangle p1=<0, 0, 0> n1=<0, 0, 1> p2=<1, 0, 0> n2=<0, 0, 2> p3=<0, 1, "
        "0> n3=<0, 0, 3>",
        "object[5] disc center=<0, 0, 0> normal=<0, 1, 0> radius=2 hole_radius=0.5",
        "object[6] cylinder base=<0, 0, 0> cap=<0, 2, 0> radius=0.5 open=1",
        "object[7] cone base=<0, 0, 0> base_radius=1 cap=<0, 1, 0> cap_radius=0 open=0",
        "object[8] torus major_radius=2 minor_radius=0.25",
        "object[9] prism height1=0 height2=1 points=<0, 0>;<1, 2> open=0",
    };
    for (std::size_t i = 0; i < shapes.size(); ++i)
        CHECK(lines[i + 2] == shapes[i] + " " + kIdentity + " " + kFlags);
}

TEST_CASE("dump: CSG children on the lines after their parent, numbered by path", "[app][dump]") {
    rt::SceneDescription scene;
    auto inner =
        object(rt::Csg{rt::Csg::Kind::Difference,
                       {object(rt::Torus{1.0, 0.5}), object(rt::Sphere{vec(0.0, 0.0, 0.0), 1.0})}});
    inner->inverse = true;
    auto outer = object(rt::Csg{rt::Csg::Kind::Union,
                                {object(rt::Box{vec(0.0, 0.0, 0.0), vec(1.0, 1.0, 1.0)}), inner}});
    outer->transform.append(step(rt::TransformKind::Translate, vec(0.0, 0.0, 5.0)));
    outer->hollow = true;
    scene.objects.push_back(object(rt::Sphere{vec(0.0, 0.0, 0.0), 1.0}));
    scene.objects.push_back(outer);
    const auto lines = dump(scene, 0.0);
    REQUIRE(lines.size() == 8);
    CHECK(lines[3] ==
          "object[1] union children=2 transform=[1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 5] "
          "no_shadow=0 hollow=1 inverse=0");
    CHECK(lines[4].rfind("object[1.0] box corner1=<0, 0, 0> corner2=<1, 1, 1> " + kIdentity, 0) ==
          0);
    CHECK(lines[5] ==
          "object[1.1] difference children=2 " + kIdentity + " no_shadow=0 hollow=0 inverse=1");
    CHECK(lines[6].rfind("object[1.1.0] torus ", 0) == 0);
    CHECK(lines[7].rfind("object[1.1.1] sphere ", 0) == 0);
}

TEST_CASE("dump: a deformed object lists its steps instead of a matrix", "[app][dump]") {
    rt::SceneDescription scene;
    auto box = object(rt::Box{vec(-1.0, -1.0, -1.0), vec(1.0, 1.0, 1.0)});
    box->transform.append(step(rt::TransformKind::Translate, vec(0.0, 1.0, 0.0)));
    box->transform.append(
        step(rt::TransformKind::Twist, vec(0.0, 1.0, 0.0), symbolic_clock() * 90.0));
    rt::TransformStep matrix = step(rt::TransformKind::Matrix, vec(0.0, 0.0, 0.0));
    for (int i = 0; i < 12; ++i) matrix.matrix[i] = static_cast<double>(i);
    matrix.inverse = true;
    box->transform.append(matrix);
    box->transform.append(step(rt::TransformKind::Bend, vec(1.0, 0.0, 0.0), 30.0));
    scene.objects.push_back(box);
    const auto lines = dump(scene, 0.5);
    REQUIRE(lines.size() == 3);
    CHECK(lines[2] ==
          "object[0] box corner1=<-1, -1, -1> corner2=<1, 1, 1> "
          "steps=translate(<0, 1, 0>);twist(axis=<0, 1, 0>,amount=45);"
          "matrix^-1([0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]);bend(axis=<1, 0, 0>,amount=30) " +
              kFlags);
}

TEST_CASE("dump: a pattern's kind and modifiers, normals, the sky, fog and a parallel light",
          "[app][dump]") {
    rt::SceneDescription scene;
    auto o = object(rt::Sphere{{{0.0, 0.0, 0.0}}, 1.0});
    rt::Texture texture;
    texture.pigment.pattern = rt::Pigment::Pattern::Patterned;
    texture.pigment.patterned = rt::pattern::Pattern::of(*rt::pattern::find_kind("bozo"));
    texture.pigment.patterned.edit().phase = symbolic_clock();
    texture.normal.emplace();
    texture.normal->patterned = rt::pattern::Pattern::of(*rt::pattern::find_kind("bumps"));
    o->texture = texture;
    scene.objects.push_back(o);
    rt::Fog fog;
    fog.distance = 5.0;
    scene.fogs.push_back(fog);
    rt::LightRecord light;
    light.parallel = true;
    scene.lights.push_back(light);
    const auto lines = dump(scene, 0.25);
    const auto has = [&](const std::string& text) {
        for (const auto& l : lines)
            if (l.find(text) != std::string::npos) return true;
        return false;
    };
    CHECK(has("pigment=bozo frequency=1 phase=0.25"));
    CHECK(has("normal=bumps amount=0.5"));
    CHECK(has("fog type=1 distance=5"));
    CHECK(has("parallel point_at=<0, 0, 1>"));
}

TEST_CASE("dump: a texture_map's entries and a layered texture's layers", "[app][dump]") {
    rt::SceneDescription scene;
    rt::Texture top, under, map;
    top.pigment.colours[0] = rt::ColourFunction{{1.0, 0.0, 0.0, 0.0, 0.5}};
    under.pigment.colours[0] = rt::ColourFunction{{0.0, 0.0, 1.0, 0.0, 0.0}};
    top.below.push_back(under);
    map.patterned = rt::pattern::Pattern::of(*rt::pattern::find_kind("gradient"));
    map.texture_map.push_back({0.25, std::make_shared<rt::Texture>(top)});
    map.texture_map.push_back({0.75, std::make_shared<rt::Texture>(under)});
    auto a = object(rt::Sphere{{{0.0, 0.0, 0.0}}, 1.0});
    a->texture = top;
    auto b = object(rt::Sphere{{{0.0, 0.0, 0.0}}, 1.0});
    b->texture = map;
    scene.objects = {a, b};
    const auto lines = dump(scene, 0.0);
    REQUIRE(lines.size() >= 2);
    const auto& layered = *std::find_if(lines.begin(), lines.end(),
                                        [](const auto& l) { return l.find("object[0]") == 0; });
    CHECK(layered.find("pigment=solid<1, 0, 0, 0, 0.5>") != std::string::npos);
    CHECK(layered.find("under [pigment=solid<0, 0, 1, 0, 0>") != std::string::npos);
    const auto& mapped = *std::find_if(lines.begin(), lines.end(),
                                       [](const auto& l) { return l.find("object[1]") == 0; });
    CHECK(mapped.find("texture_map=gradient") != std::string::npos);
    CHECK(mapped.find(" 0.25[pigment=solid<1, 0, 0, 0, 0.5>") != std::string::npos);
    CHECK(mapped.find(" 0.75[pigment=solid<0, 0, 1, 0, 0>") != std::string::npos);
}

TEST_CASE("dump: a map entry used twice is printed once and named after", "[app][dump]") {
    // (A declared chain of such maps is exponential printed as a tree.)
    rt::SceneDescription scene;
    auto shared = std::make_shared<rt::Texture>();
    rt::Texture map;
    map.patterned = rt::pattern::Pattern::of(*rt::pattern::find_kind("checker"));
    map.texture_map = {{0.0, shared}, {1.0, shared}};
    auto a = object(rt::Sphere{{{0.0, 0.0, 0.0}}, 1.0});
    a->texture = map;
    scene.objects = {a};
    const auto lines = dump(scene, 0.0);
    const auto& line = *std::find_if(lines.begin(), lines.end(),
                                     [](const auto& l) { return l.find("object[0]") == 0; });
    CHECK(line.find(" 0[#1 pigment=solid") != std::string::npos);
    CHECK(line.find(" 1[#1]") != std::string::npos);
}
