// The camera checked against POV-Ray 3.7.0.10 (Debian's `povray`).
//
// POV-Ray does not print its camera vectors, so each camera was rendered at
// 3x3 pixels looking out from the centre of a unit sphere whose colour encodes
// the direction of the point seen (r, g, b = 0.5 + 0.5 * x, y, z):
//   povray +Iscene.pov +W3 +H3 -A +FP16 +Oout.ppm File_Gamma=1.0 -D
// with scene.pov (CAMERA replaced by the camera's items, LOCATION by the
// camera's final location):
//   #version 3.7;
//   global_settings { assumed_gamma 1 }
//   #declare Cam = camera { CAMERA }
//   camera { Cam }
//   sphere { 0, 1
//     pigment { average pigment_map {
//       [ function { 0.5 + 0.5 * x } color_map { [0 rgb 0] [1 rgb <3,0,0>] } ]
//       [ function { 0.5 + 0.5 * y } color_map { [0 rgb 0] [1 rgb <0,3,0>] } ]
//       [ function { 0.5 + 0.5 * z } color_map { [0 rgb 0] [1 rgb <0,0,3>] } ]
//     } }
//     finish { emission 1 diffuse 0 ambient 0 }
//     translate LOCATION
//   }
// Each pixel's 16-bit colour c gives the unit ray direction 2 c / 65535 - 1
// (good to about 3e-5). Pixel (i, j) (j counted from the top) is the ray
// direction + u right + v up with u = (i + 0.5) / 3 - 0.5 and
// v = 0.5 - (j + 0.5) / 3, which is what the recorded directions are
// compared with. Only directions are observable this way, so these tests fix
// the camera up to a common scale of direction, right and up.
#include "runtime/scene/camera.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

using namespace hexant::runtime;

namespace {

Vector3Function vec(glm::dvec3 v) {
    return Vector3Function{{TimeFunction(v.x), TimeFunction(v.y), TimeFunction(v.z)}};
}

CameraItem item(CameraItem::Kind kind, glm::dvec3 v) {
    CameraItem it;
    it.kind = kind;
    it.vector = vec(v);
    return it;
}
CameraItem loc(glm::dvec3 v) {
    return item(CameraItem::Kind::Location, v);
}
CameraItem look(glm::dvec3 v) {
    return item(CameraItem::Kind::LookAt, v);
}
CameraItem dir(glm::dvec3 v) {
    return item(CameraItem::Kind::Direction, v);
}
CameraItem right(glm::dvec3 v) {
    return item(CameraItem::Kind::Right, v);
}
CameraItem up(glm::dvec3 v) {
    return item(CameraItem::Kind::Up, v);
}
CameraItem sky(glm::dvec3 v) {
    return item(CameraItem::Kind::Sky, v);
}
CameraItem angle(TimeFunction a) {
    CameraItem it;
    it.kind = CameraItem::Kind::Angle;
    it.angle = a;
    return it;
}
CameraItem xf(TransformKind kind, glm::dvec3 v) {
    CameraItem it;
    it.kind = CameraItem::Kind::Transform;
    it.step.kind = kind;
    it.step.vector = vec(v);
    return it;
}

struct Recorded {
    const char* camera;             // the items as written for POV-Ray
    std::vector<CameraItem> items;  // the same items for hexant
    glm::dvec3 location;            // where the camera ends up
    glm::dvec3 rays[9];             // unit ray directions, row by row from the top
};

std::vector<Recorded> recorded() {
    return {
        {"",
         {},
         {0, 0, 0},
         {{-0.38769, 0.29149, 0.87448},
          {0.00002, 0.31621, 0.94867},
          {0.38769, 0.29149, 0.87448},
          {-0.40529, 0.00002, 0.91418},
          {0.00002, 0.00002, 1.00000},
          {0.40529, 0.00002, 0.91418},
          {-0.38769, -0.29149, 0.87448},
          {0.00002, -0.31621, 0.94867},
          {0.38769, -0.29149, 0.87448}}},
        {"location <1,2,-3> look_at <0,1,2>",
         {loc({1, 2, -3}), look({0, 1, 2})},
         {1, 2, -3},
         {{-0.55947, 0.11775, 0.82046},
          {-0.19451, 0.12773, 0.97253},
          {0.20085, 0.11775, 0.97250},
          {-0.57336, -0.17592, 0.80020},
          {-0.19246, -0.19246, 0.96225},
          {0.22148, -0.17592, 0.95917},
          {-0.53747, -0.45434, 0.71044},
          {-0.17064, -0.49288, 0.85321},
          {0.22286, -0.45434, 0.86249}}},
        {"location <1,2,-3> look_at <0,1,2> angle 60",
         {loc({1, 2, -3}), look({0, 1, 2}), angle(60)},
         {1, 2, -3},
         {{-0.52328, 0.08248, 0.84817},
          {-0.19536, 0.08794, 0.97678},
          {0.15682, 0.08248, 0.98419},
          {-0.53185, -0.17961, 0.82757},
          {-0.19246, -0.19246, 0.96225},
          {0.17263, -0.17961, 0.96847},
          {-0.50359, -0.42925, 0.74975},
          {-0.17436, -0.45766, 0.87185},
          {0.17650, -0.42925, 0.88577}}},
        {"look_at <0,1,2> angle 60 location <1,2,-3>",
         {look({0, 1, 2}), angle(60), loc({1, 2, -3})},
         {1, 2, -3},
         {{-0.52328, 0.08248, 0.84817},
          {-0.19536, 0.08794, 0.97678},
          {0.15682, 0.08248, 0.98419},
          {-0.53185, -0.17961, 0.82757},
          {-0.19246, -0.19246, 0.96225},
          {0.17263, -0.17961, 0.96847},
          {-0.50359, -0.42925, 0.74975},
          {-0.17436, -0.45766, 0.87185},
          {0.17650, -0.42925, 0.88577}}},
        {"sky <1,1,0> location <0,0,-5> look_at <0,0,0> right x*1 up y*2",
         {sky({1, 1, 0}), loc({0, 0, -5}), look({0, 0, 0}), right({1, 0, 0}), up({0, 2, 0})},
         {0, 0, -5},
         {{0.18898, 0.56695, 0.80179},
          {0.39223, 0.39223, 0.83206},
          {0.56695, 0.18898, 0.80179},
          {-0.22362, 0.22362, 0.94867},
          {0.00002, 0.00002, 1.00000},
          {0.22362, -0.22362, 0.94867},
          {-0.56695, -0.18898, 0.80179},
          {-0.39223, -0.39223, 0.83206},
          {-0.18898, -0.56695, 0.80179}}},
        {"right -1.33*x location <0,0,-5> look_at <1,1,0>",
         {right({-1.33, 0, 0}), loc({0, 0, -5}), look({1, 1, 0})},
         {0, 0, -5},
         {{0.53747, 0.45434, 0.71044},
          {0.17064, 0.49288, 0.85321},
          {-0.22286, 0.45434, 0.86249},
          {0.57336, 0.17592, 0.80020},
          {0.19246, 0.19246, 0.96225},
          {-0.22148, 0.17592, 0.95917},
          {0.55947, -0.11775, 0.82046},
          {0.19451, -0.12773, 0.97253},
          {-0.20085, -0.11775, 0.97250}}},
        {"location <0,0,-5> look_at <0,0,0> rotate y*30 translate <1,0,0>",
         {loc({0, 0, -5}), look({0, 0, 0}), xf(TransformKind::Rotate, {0, 30, 0}),
          xf(TransformKind::Translate, {1, 0, 0})},
         {-1.5, 0, -4.330127018922193},
         {{0.10149, 0.29149, 0.95117},
          {0.47433, 0.31621, 0.82159},
          {0.77301, 0.29149, 0.56347},
          {0.10610, 0.00002, 0.99435},
          {0.49999, 0.00002, 0.86603},
          {0.80807, 0.00002, 0.58907},
          {0.10149, -0.29149, 0.95117},
          {0.47433, -0.31621, 0.82159},
          {0.77301, -0.29149, 0.56347}}},
        {"rotate y*30 translate <1,0,0> location <0,0,-5> look_at <0,0,0>",
         {xf(TransformKind::Rotate, {0, 30, 0}), xf(TransformKind::Translate, {1, 0, 0}),
          loc({0, 0, -5}), look({0, 0, 0})},
         {-1.5, 0, -4.330127018922193},
         {{0.10149, 0.29149, 0.95117},
          {0.47433, 0.31621, 0.82159},
          {0.77301, 0.29149, 0.56347},
          {0.10610, 0.00002, 0.99435},
          {0.49999, 0.00002, 0.86603},
          {0.80807, 0.00002, 0.58907},
          {0.10149, -0.29149, 0.95117},
          {0.47433, -0.31621, 0.82159},
          {0.77301, -0.29149, 0.56347}}},
        {"direction <0,0,2> right <2,0,0> up <0,1.5,0> location 0 look_at <1,1,1>",
         {dir({0, 0, 2}), right({2, 0, 0}), up({0, 1.5, 0}), loc({0, 0, 0}), look({1, 1, 1})},
         {0, 0, 0},
         {{0.22115, 0.72137, 0.65631},
          {0.46111, 0.75814, 0.46111},
          {0.65631, 0.72137, 0.22115},
          {0.32412, 0.54772, 0.77133},
          {0.57736, 0.57736, 0.57736},
          {0.77133, 0.54772, 0.32412},
          {0.40957, 0.34450, 0.84472},
          {0.65911, 0.36208, 0.65911},
          {0.84472, 0.34450, 0.40957}}},
        {"location 0 look_at <0,5,0>",
         {loc({0, 0, 0}), look({0, 5, 0})},
         {0, 0, 0},
         {{-0.38769, 0.87448, -0.29149},
          {0.00002, 0.94867, -0.31621},
          {0.38769, 0.87448, -0.29149},
          {-0.40529, 0.91418, 0.00002},
          {0.00002, 1.00000, 0.00002},
          {0.40529, 0.91418, 0.00002},
          {-0.38769, 0.87448, 0.29149},
          {0.00002, 0.94867, 0.31621},
          {0.38769, 0.87448, 0.29149}}},
        {"location <0,1,-4> look_at 0 scale <1,2,1>",
         {loc({0, 1, -4}), look({0, 0, 0}), xf(TransformKind::Scale, {1, 2, 1})},
         {0, 2, -4},
         {{-0.38482, 0.14034, 0.91226},
          {0.00002, 0.15206, 0.98837},
          {0.38482, 0.14034, 0.91226},
          {-0.37835, -0.41396, 0.82794},
          {0.00002, -0.44723, 0.89444},
          {0.37835, -0.41396, 0.82794},
          {-0.29436, -0.75149, 0.59045},
          {0.00002, -0.78631, 0.61782},
          {0.29436, -0.75149, 0.59045}}},
        {"angle 90",
         {angle(90)},
         {0, 0, 0},
         {{-0.51196, 0.38494, 0.76794},
          {0.00002, 0.44811, 0.89398},
          {0.51196, 0.38494, 0.76794},
          {-0.55471, 0.00002, 0.83206},
          {0.00002, 0.00002, 1.00000},
          {0.55471, 0.00002, 0.83206},
          {-0.51196, -0.38494, 0.76794},
          {0.00002, -0.44811, 0.89398},
          {0.51196, -0.38494, 0.76794}}},
        {"location <0,0,-5> look_at <0,0,0> angle 45 direction <0,0,3> right <1,0,0>",
         {loc({0, 0, -5}), look({0, 0, 0}), angle(45), dir({0, 0, 3}), right({1, 0, 0})},
         {0, 0, -5},
         {{-0.25722, 0.25722, 0.93149},
          {0.00002, 0.26619, 0.96393},
          {0.25722, 0.25722, 0.93149},
          {-0.26619, 0.00002, 0.96393},
          {0.00002, 0.00002, 1.00000},
          {0.26619, 0.00002, 0.96393},
          {-0.25722, -0.25722, 0.93149},
          {0.00002, -0.26619, 0.96393},
          {0.25722, -0.25722, 0.93149}}},
    };
}

}  // namespace

namespace {
// A camera of these items, over all of time (no pieces).
CameraRecord camera_of(std::vector<CameraItem> items) {
    CameraRecord record;
    record.items = std::move(items);
    return record;
}
}  // namespace

TEST_CASE("camera rays match POV-Ray 3.7's 3x3 renders", "[camera]") {
    for (const Recorded& r : recorded()) {
        CameraRecord record = camera_of(r.items);
        const CameraFrame cam = record.evaluate(0.0);
        INFO("camera { " << r.camera << " }");
        CHECK(glm::length(cam.location - r.location) < 1e-9);
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
                const double u = (i + 0.5) / 3 - 0.5, v = 0.5 - (j + 0.5) / 3;
                const glm::dvec3 d = glm::normalize(cam.direction + u * cam.right + v * cam.up);
                const glm::dvec3 want = r.rays[j * 3 + i];
                INFO("pixel " << i << ", " << j << ": " << d.x << ", " << d.y << ", " << d.z);
                CHECK(std::abs(d.x - want.x) < 5e-5);
                CHECK(std::abs(d.y - want.y) < 5e-5);
                CHECK(std::abs(d.z - want.z) < 5e-5);
            }
    }
}

TEST_CASE("camera defaults are POV-Ray's", "[camera]") {
    const CameraFrame cam = CameraRecord{}.evaluate(0.0);
    CHECK(cam.location == glm::dvec3(0, 0, 0));
    CHECK(cam.direction == glm::dvec3(0, 0, 1));
    CHECK(cam.right == glm::dvec3(1.33, 0, 0));
    CHECK(cam.up == glm::dvec3(0, 1, 0));
    CHECK(cam.sky == glm::dvec3(0, 1, 0));
}

TEST_CASE("angle sets direction's length to |right| / (2 tan(angle / 2))", "[camera]") {
    const CameraFrame cam = camera_of({dir({0, 0, 5}), right({2, 0, 0}), angle(90)}).evaluate(0.0);
    CHECK(cam.direction.x == 0);
    CHECK(cam.direction.z == Approx(1.0));
    const CameraFrame wide = camera_of({angle(60)}).evaluate(0.0);
    CHECK(wide.direction.z == Approx(1.33 / (2 * std::tan(3.14159265358979323846 / 6))));
}

TEST_CASE("look_at keeps the lengths and the handedness", "[camera]") {
    const CameraFrame cam = camera_of({dir({0, 0, 2}), right({-3, 0, 0}), up({0, 0.5, 0}),
                                       loc({1, 1, 1}), look({1, 1, 5})})
                                .evaluate(0.0);
    CHECK(glm::length(cam.direction - glm::dvec3(0, 0, 2)) < 1e-12);
    CHECK(glm::length(cam.right - glm::dvec3(-3, 0, 0)) < 1e-12);
    CHECK(glm::length(cam.up - glm::dvec3(0, 0.5, 0)) < 1e-12);
}

TEST_CASE("the last of a repeated camera item wins", "[camera]") {
    const CameraFrame cam = camera_of({loc({1, 2, 3}), loc({4, 5, 6})}).evaluate(0.0);
    CHECK(cam.location == glm::dvec3(4, 5, 6));
}

TEST_CASE("a camera driven by clock is evaluated at each time", "[camera]") {
    CameraItem moving = loc({0, 0, -5});
    moving.vector.c[0] =
        TimeFunction::apply(TimeOp::Multiply, TimeFunction(4.0), TimeFunction::clock());
    CameraRecord record = camera_of({moving, look({0, 0, 0})});
    CHECK(record.depends_on_time());
    CHECK_FALSE(camera_of({loc({0, 0, -5}), look({0, 0, 0})}).depends_on_time());
    const CameraFrame at_half = record.evaluate(0.5);
    CHECK(at_half.location == glm::dvec3(2, 0, -5));
    const glm::dvec3 d = glm::normalize(at_half.direction);
    CHECK(glm::length(d - glm::normalize(glm::dvec3(-2, 0, 5))) < 1e-12);
}

TEST_CASE("location equal to look_at is an error", "[camera]") {
    CHECK_THROWS(camera_of({loc({1, 1, 1}), look({1, 1, 1})}).evaluate(0.0));
}

TEST_CASE(
    "focal blur: the focal distance from focal_point before the transforms, an aperture only with "
    "samples",
    "[runtime][camera]") {
    // POV-Ray's Parse_Camera: |focal_point - location| before the camera's
    // transforms (a scale does not change it), else the direction's
    // length; no focal blur without blur_samples.
    CameraRecord c;
    c.items = {loc({0, 0, -5}), look({0, 0, 0}), angle(TimeFunction(60.0))};
    CameraItem aperture;
    aperture.kind = CameraItem::Kind::Aperture;
    aperture.angle = TimeFunction(0.5);
    CameraItem focus = item(CameraItem::Kind::FocalPoint, {3, 4, -5});
    c.items.push_back(aperture);
    c.items.push_back(focus);
    c.items.push_back(xf(TransformKind::Scale, {2, 2, 2}));
    CameraFrame f = c.evaluate(0.0);
    CHECK(f.aperture == 0.0);  // (no blur_samples yet)
    CHECK(f.focal_distance == Approx(5.0));
    CameraItem samples;
    samples.kind = CameraItem::Kind::BlurSamples;
    samples.angle = TimeFunction(10.0);
    c.items.push_back(samples);
    f = c.evaluate(0.0);
    CHECK(f.aperture == 0.5);
    CHECK(f.focal_distance == Approx(5.0));
    // Without a focal point: the direction's length (angle 60 on right 1.33).
    c.items.erase(c.items.begin() + 4);
    f = c.evaluate(0.0);
    CHECK(f.focal_distance == Approx(1.33 / std::tan(30.0 * 3.14159265358979323846 / 180.0) / 2.0));
}

TEST_CASE("the focal distance without a focal_point is POV-Ray's Direction_Length",
          "[runtime][camera]") {
    // Parse_Camera's Direction_Length is 1 unless angle or look_at set it:
    // a direction given alone does not (hexant took its length before).
    CameraRecord c;
    c.items = {loc({0, 0, -5}), dir({0, 0, 3})};
    CHECK(c.evaluate(0.0).focal_distance == 1.0);
    c.items.push_back(look({0, 0, 0}));
    CHECK(c.evaluate(0.0).focal_distance == Approx(3.0));
}

TEST_CASE("camera types: the orthographic resize and the wide projections' angles",
          "[runtime][camera]") {
    CameraItem type;
    type.kind = CameraItem::Kind::Type;
    // Orthographic with neither up nor right: right and up scaled by
    // |look_at - location| / |direction| (POV-Ray's Parse_Camera).
    type.type = CameraType::Orthographic;
    CameraRecord ortho;
    ortho.items = {type, loc({0, 0, -8}), look({0, 0, 0})};
    CameraFrame f = ortho.evaluate(0.0);
    CHECK(glm::length(f.right) == Approx(1.33 * 8.0));
    CHECK(glm::length(f.up) == Approx(8.0));
    // ... not when up or right is given, unless an angle is.
    ortho.items.push_back(up({0, 2, 0}));
    f = ortho.evaluate(0.0);
    CHECK(glm::length(f.up) == Approx(2.0));
    ortho.items.push_back(angle(TimeFunction(90.0)));
    f = ortho.evaluate(0.0);
    // (angle 90: direction 1.33 / 2, then the resize by 8 / 0.665.)
    CHECK(glm::length(f.up) == Approx(2.0 * 8.0 / (1.33 / 2.0)));
    // Spherical: angle H alone gives V = H / 2; a fisheye keeps its angle
    // and its direction (angle sets direction's length only on the flat
    // projections), and may be wider than 180.
    type.type = CameraType::Spherical;
    CameraRecord sphere;
    sphere.items = {type, angle(TimeFunction(300.0))};
    f = sphere.evaluate(0.0);
    CHECK(f.h_angle == 300.0);
    CHECK(f.v_angle == 150.0);
    type.type = CameraType::Fisheye;
    CameraRecord fish;
    fish.items = {type, angle(TimeFunction(200.0))};
    f = fish.evaluate(0.0);
    CHECK(f.angle == 200.0);
    CHECK(f.direction == glm::dvec3(0, 0, 1));
}
