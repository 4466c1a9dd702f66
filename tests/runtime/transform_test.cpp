// Transform conventions checked against POV-Ray 3.7.0.10 (Debian's `povray`):
//     povray +Iscene.pov +W1 +H1 -D -F +GDdebug.txt
// with this scene, whose #debug output is recorded in the tests below
// (str(v, 0, 10), so good to 1e-10):
//
// #include "transforms.inc"
// #macro V(Name, X)
// #debug concat(Name, " = ", vstr(3, X, ", ", 0, 10), "\n")
// #end
// V("vrotate_a", vrotate(<1,2,3>, <30,40,50>))
// V("vrotate_b", vrotate(<-0.5,4,0.25>, <-75,200,10>))
// V("vrotate_x", vrotate(<0,1,0>, <90,0,0>))
// V("vrotate_y", vrotate(<0,0,1>, <0,90,0>))
// V("vrotate_z", vrotate(<1,0,0>, <0,0,90>))
// #declare T1 = transform { rotate <30,40,50> }
// V("rotate", vtransform(<1,2,3>, T1))
// #declare T2 = transform { scale <2,-1,0.5> rotate <10,-20,30> translate <1,2,3> }
// V("chain", vtransform(<1,2,3>, T2))
// #declare T3 = transform { matrix <1,2,3, 4,5,6, 7,8,10, -1,0.5,2> }
// V("matrix", vtransform(<1,2,3>, T3))
// #declare T4 = transform { translate <1,0,0> matrix <0,1,0, -1,0,0, 0,0,1, 0,0,5> scale 3 }
// V("matrix_chain", vtransform(<1,2,3>, T4))
// #declare T5 = transform { T2 inverse }
// V("inverse", vtransform(<2,-1,0.5>, T5))
// #declare T6 = transform { rotate <30,40,50> inverse }
// V("rotate_inverse", vtransform(<1,2,3>, T6))
// V("vaxis_rotate", vaxis_rotate(<1,2,3>, <1,1,0>, 30))
// V("vinv_transform", vinv_transform(<2,-1,0.5>, T2))
//
// Output:
// vrotate_a = 1.8012810619, 2.5076901472, 2.1134986779
// vrotate_b = 1.5205958752, 1.5645757611, 3.3988808264
// vrotate_x = 0.0000000000, 0.0000000000, 1.0000000000
// vrotate_y = 1.0000000000, 0.0000000000, 0.0000000000
// vrotate_z = 0.0000000000, 1.0000000000, 0.0000000000
// rotate = 1.8012810619, 2.5076901472, 2.1134986779
// chain = 3.4079604546, 0.8151530651, 4.7458133319
// matrix = 29.0000000000, 36.5000000000, 47.0000000000
// matrix_chain = -6.0000000000, 6.0000000000, 24.0000000000
// inverse = -0.7253958041, 3.4212967543, -3.1240564838
// rotate_inverse = -0.2623107749, 2.2979853471, 2.9411658236
// vaxis_rotate = 2.1276474699, 0.8723525301, 2.9516296019
// vinv_transform = -0.7253958041, 3.4212967543, -3.1240564838
#include "runtime/motion/transform.hpp"

#include <catch2/catch.hpp>
#include <glm/vec4.hpp>

using namespace hexant::runtime;

namespace {

TransformStep step(TransformKind kind, double x, double y, double z) {
    TransformStep s;
    s.kind = kind;
    s.vector = Vector3Function{{TimeFunction(x), TimeFunction(y), TimeFunction(z)}};
    return s;
}

TransformStep matrix_step(std::array<double, 12> m) {
    TransformStep s;
    s.kind = TransformKind::Matrix;
    for (int i = 0; i < 12; ++i) s.matrix[i] = TimeFunction(m[i]);
    return s;
}

glm::dvec3 apply(const Transform& t, glm::dvec3 p, double time = 0.0) {
    const glm::dvec4 q = t.matrix_at(time) * glm::dvec4(p, 1.0);
    return {q.x, q.y, q.z};
}

void check(glm::dvec3 got, glm::dvec3 want) {
    INFO("got " << got.x << ", " << got.y << ", " << got.z);
    CHECK(got.x == Approx(want.x).margin(1e-9));
    CHECK(got.y == Approx(want.y).margin(1e-9));
    CHECK(got.z == Approx(want.z).margin(1e-9));
}

Transform chain() {  // T2
    Transform t;
    t.append(step(TransformKind::Scale, 2, -1, 0.5));
    t.append(step(TransformKind::Rotate, 10, -20, 30));
    t.append(step(TransformKind::Translate, 1, 2, 3));
    return t;
}

}  // namespace

TEST_CASE("rotate turns about x, then y, then z, as POV-Ray's vrotate", "[transform]") {
    auto rotated = [](glm::dvec3 p, glm::dvec3 angles) {
        Transform t;
        t.append(step(TransformKind::Rotate, angles.x, angles.y, angles.z));
        return apply(t, p);
    };
    check(rotated({1, 2, 3}, {30, 40, 50}), {1.8012810619, 2.5076901472, 2.1134986779});
    check(rotated({-0.5, 4, 0.25}, {-75, 200, 10}), {1.5205958752, 1.5645757611, 3.3988808264});
    check(rotated({0, 1, 0}, {90, 0, 0}), {0, 0, 1});
    check(rotated({0, 0, 1}, {0, 90, 0}), {1, 0, 0});
    check(rotated({1, 0, 0}, {0, 0, 90}), {0, 1, 0});
}

TEST_CASE("steps apply in the order written", "[transform]") {
    check(apply(chain(), {1, 2, 3}), {3.4079604546, 0.8151530651, 4.7458133319});
}

TEST_CASE("matrix takes POV-Ray's rows: p' = p * M with the fourth row the translation",
          "[transform]") {
    Transform t3;
    t3.append(matrix_step({1, 2, 3, 4, 5, 6, 7, 8, 10, -1, 0.5, 2}));
    check(apply(t3, {1, 2, 3}), {29, 36.5, 47});

    Transform t4;
    t4.append(step(TransformKind::Translate, 1, 0, 0));
    t4.append(matrix_step({0, 1, 0, -1, 0, 0, 0, 0, 1, 0, 0, 5}));
    t4.append(step(TransformKind::Scale, 3, 3, 3));
    check(apply(t4, {1, 2, 3}), {-6, 6, 24});
}

TEST_CASE("inverse undoes the whole chain", "[transform]") {
    check(apply(chain().inverse(), {2, -1, 0.5}), {-0.7253958041, 3.4212967543, -3.1240564838});
    TransformStep r = step(TransformKind::Rotate, 30, 40, 50);
    r.inverse = true;
    Transform t6;
    t6.append(r);
    check(apply(t6, {1, 2, 3}), {-0.2623107749, 2.2979853471, 2.9411658236});
}

TEST_CASE("a rotation driven by clock is evaluated at each time", "[transform]") {
    // rotate y*360*clock at clock 0.25 is rotate <0, 90, 0>.
    TransformStep s;
    s.kind = TransformKind::Rotate;
    s.vector = Vector3Function{
        {TimeFunction(0.0),
         TimeFunction::apply(TimeOp::Multiply, TimeFunction(360.0), TimeFunction::clock()),
         TimeFunction(0.0)}};
    Transform t;
    t.append(s);
    CHECK(t.depends_on_time());
    check(apply(t, {0, 0, 1}, 0.25), {1, 0, 0});
    check(apply(t, {0, 0, 1}, 0.0), {0, 0, 1});
}
