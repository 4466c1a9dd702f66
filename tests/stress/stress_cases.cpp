// The stress suite (label `stress`): scenes and rays that break careless
// tracers. For each case the spacetime hierarchy (and the per-frame one)
// must find exactly the hits brute force finds: the same rays hit, at the
// same depth to a relative 1e-9, with finite normals; no curved-path search
// (deformed objects) gives up at its limit of pieces; a small render has no
// NaN or Inf pixel; and the work per ray (bound and object tests, counted,
// never timed) stays within a stated factor of a tame scene's, and the
// deformation maps per ray within a stated limit.
//
// HEXANT_STRESS_RAYS=N runs N rays per case instead of 1500 (the long run:
// README.md, "What hexant guarantees numerically").
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "language/interpreter.hpp"
#include "runtime/geometry/curved_path_root.hpp"
#include "runtime/objects/object_factory.hpp"
#include "runtime/work_counts.hpp"
#include "tracer/ray_query.hpp"
#include "tracer/renderer.hpp"

namespace rt = hexant::runtime;
namespace tr = hexant::tracer;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

int rays_per_case() {
    const char* text = std::getenv("HEXANT_STRESS_RAYS");
    return text ? std::max(1, std::atoi(text)) : 1500;
}

struct Case {
    std::string sdl;  // objects only; a camera is added for the render
    std::string camera = "camera { location <0, 1, -8> look_at 0 }\n";
    double shutter = 1.0;  // of each frame's clock step
    int frames = 4;
    bool cyclic = false;
};

rt::SceneDescription parse(const Case& c) {
    hexant::language::ParseOptions options;
    options.animation.width = 24;
    options.animation.height = 16;
    options.animation.initial_frame = 1;
    options.animation.final_frame = c.frames;
    options.animation.cyclic = c.cyclic;
    options.animation.shutter = c.shutter;
    return hexant::language::parse_scene_text(
        c.camera + "light_source { <-3, 9, -6>, rgb 1 }\n" + c.sdl, "stress.pov", options);
}

struct Work {
    double tests_per_ray = 0.0;  // bound and object tests of the spacetime mode
    int hits = 0;
    double ns_per_ray = 0.0;    // spacetime first hits, timed apart; printed, never asserted
    double maps_per_ray = 0.0;  // points and boxes through a deformation in that pass (asserted)
};

// The box an object occupies at one instant (nothing for unbounded ones).
std::optional<rt::Box4> box_at(const rt::IntelligentObject& object, const rt::Box4& root,
                               double t) {
    if (!object.bounded()) return std::nullopt;
    rt::Box4 region = root;
    region.lo.w = region.hi.w = t;
    std::vector<rt::SlabBound> bounds;
    object.bound(region, bounds);
    std::optional<rt::Box4> box;
    for (const auto& b : bounds) {
        if (b.is_empty()) continue;
        const rt::Box4 one = b.box();
        if (!box)
            box = one;
        else
            for (int i = 0; i < 4; ++i) {
                box->lo[i] = std::min(box->lo[i], one.lo[i]);
                box->hi[i] = std::max(box->hi[i], one.hi[i]);
            }
    }
    return box;
}

// Rays of several kinds, each at a random instant of the animation: aimed
// at a random point of a random object's box; from inside such a box;
// parallel to a coordinate plane through a box's face or corner (the slabs'
// and the cells' own planes); lying in a cell wall of the first levels.
Work check_case(const Case& c) {
    const rt::SceneDescription scene = parse(c);
    std::vector<rt::IntelligentObjectPtr> objects;
    for (const auto& record : scene.objects)
        objects.push_back(rt::make_intelligent_object(*record, scene.default_texture));
    const auto set = tr::ObjectSet::of(objects);
    const double t0 = scene.animation.time_begin(), t1 = scene.animation.time_end();
    const rt::Box4 root = tr::enclosing_box(set, t0, t1);
    tr::Counters build;
    auto brute = tr::make_ray_query(tr::Mode::Brute, set, root, {}, build);
    auto spacetime = tr::make_ray_query(tr::Mode::Spacetime, set, root, {}, build);
    auto frames = tr::make_ray_query(tr::Mode::Frames, set, root, {}, build);
    frames->prepare_frame(t0, t1, build);  // one shutter over everything
    tr::ThreadState a{tr::Mailbox(set.size()), {}}, b{tr::Mailbox(set.size()), {}},
        f{tr::Mailbox(set.size()), {}};
    std::mt19937_64 engine(1234);
    const auto uniform = [&](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(engine);
    };
    const auto unit = [&] {
        glm::dvec3 v;
        do v = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        while (glm::dot(v, v) > 1.0 || glm::dot(v, v) < 1e-6);
        return glm::normalize(v);
    };
    // A random direction parallel to the plane normal to `axis`.
    const auto in_plane = [&](int axis) {
        glm::dvec3 d = unit();
        d[axis] = 0.0;
        if (glm::length(d) < 1e-6) d[(axis + 1) % 3] = 1.0;
        return glm::normalize(d);
    };
    Work result;
    std::vector<rt::Ray4> rays;
    const std::uint64_t give_ups = rt::curved_path_give_ups();
    const int count = rays_per_case();
    for (int i = 0; i < count; ++i) {
        const double t = (i % 11 == 0) ? t0 : uniform(t0, t1);
        const auto& object = *objects[std::size_t(i) % objects.size()];
        const auto box = box_at(object, root, t);
        glm::dvec3 lo, hi;
        if (box) {
            lo = {box->lo.x, box->lo.y, box->lo.z};
            hi = {box->hi.x, box->hi.y, box->hi.z};
        } else {
            lo = {root.lo.x, root.lo.y, root.lo.z};
            hi = {root.hi.x, root.hi.y, root.hi.z};
        }
        const glm::dvec3 size = hi - lo;
        const double reach = std::max({size.x, size.y, size.z, 1e-300});
        glm::dvec3 aim{uniform(lo.x, hi.x), uniform(lo.y, hi.y), uniform(lo.z, hi.z)};
        glm::dvec3 origin, d;
        switch (i % 4) {
            case 0:  // from outside, at the box
                origin = aim + 3.0 * reach * unit();
                d = glm::normalize(aim - origin);
                break;
            case 1:  // from inside the box (the camera inside an object)
                origin = aim;
                d = unit();
                break;
            case 2:  // along a face or through a corner, parallel to an axis plane
                aim[i % 3] = (i / 4) % 2 ? lo[i % 3] : hi[i % 3];
                d = in_plane(i % 3);
                origin = aim - 3.0 * reach * d;
                break;
            default:  // in a cell wall of the first three levels
                aim[i % 3] =
                    root.lo[i % 3] + (root.hi[i % 3] - root.lo[i % 3]) * double(1 + i % 7) / 8.0;
                d = in_plane(i % 3);
                origin = aim - 3.0 * reach * d;
                break;
        }
        const rt::Ray4 ray{rt::Event(origin, t), rt::Event(d, 0.0)};
        rays.push_back(ray);
        const auto expected = brute->first_hit(ray, 0.0, kInf, a);
        const auto got = spacetime->first_hit(ray, 0.0, kInf, b);
        const auto got_frames = frames->first_hit(ray, 0.0, kInf, f);
        INFO("ray " << i << " origin " << origin.x << ' ' << origin.y << ' ' << origin.z << " d "
                    << d.x << ' ' << d.y << ' ' << d.z << " t " << t);
        INFO("brute " << (expected ? expected->s : -1.0) << " spacetime " << (got ? got->s : -1.0)
                      << " frames " << (got_frames ? got_frames->s : -1.0));
        REQUIRE(bool(got) == bool(expected));
        REQUIRE(bool(got_frames) == bool(expected));
        if (!expected) continue;
        ++result.hits;
        const double tolerance = 1e-9 * std::max(std::fabs(expected->s), 1e-300);
        REQUIRE(std::fabs(got->s - expected->s) <= tolerance);
        REQUIRE(std::fabs(got_frames->s - expected->s) <= tolerance);
        REQUIRE(std::isfinite(expected->s));
        const rt::SurfacePoint p = expected->object->complete(ray, *expected);
        REQUIRE(std::isfinite(p.geometric_normal.x + p.geometric_normal.y + p.geometric_normal.z));
        REQUIRE(std::isfinite(p.shading_normal.x + p.shading_normal.y + p.shading_normal.z));
    }
    // No curved-path search gave up at its limit of pieces (a miss by fiat).
    CHECK(rt::curved_path_give_ups() == give_ups);
    result.tests_per_ray = double(b.counters.bound_tests + b.counters.object_tests) / double(count);
    // The spacetime mode's first hits again, alone: its deformation maps
    // counted, and timed (printed only).
    const std::uint64_t maps = rt::this_thread_work.deformation_maps;
    const auto start = std::chrono::steady_clock::now();
    for (const rt::Ray4& ray : rays) (void)spacetime->first_hit(ray, 0.0, kInf, b);
    result.ns_per_ray =
        std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() /
        double(count);
    result.maps_per_ray = double(rt::this_thread_work.deformation_maps - maps) / double(count);

    // A small render: nothing NaN or Inf reaches a pixel.
    tr::RenderSettings settings;
    settings.samples_per_pixel = 2;
    tr::Renderer renderer(scene, settings);
    for (int k = scene.animation.initial_frame; k <= scene.animation.final_frame; ++k) {
        const tr::Image image = renderer.render_frame(k);
        for (const float v : image.rgb) REQUIRE(std::isfinite(v));
    }
    return result;
}

// The tame scene: a dozen objects of unit size moving by about their size
// per frame. Its work per ray is the yardstick.
const Case kTame{R"(
sphere { <-1, 0, 0>, 0.5 translate x * clock }
sphere { <1, 0.5, 0>, 0.4 rotate y * 90 * clock }
box { <-0.4, -0.4, -0.4>, <0.4, 0.4, 0.4> rotate <30, 45 * clock, 0> translate <0, 1, 1> }
cylinder { <-2, -1, 1>, <2, -1, 1>, 0.2 }
cone { <2, 0, -1>, 0.4, <2, 1, -1>, 0 translate -y * clock }
torus { 0.6, 0.15 translate <-2, 1, 1> }
triangle { <-1, -1, 2>, <1, -1, 2>, <0, 1, 2> }
plane { y, -2 }
)"};

// Every stress case's work per ray must stay within this factor of the tame
// scene's: a careless tracer that gives up on its bounds (a whole-animation
// sweep, a box grown to 10^6, a stiff twist bounded by its whole span)
// exceeds it by far. When this was written the cases ranged from 0.36 to
// 1.96 times the tame scene's work (1000 turns per frame the most:
// a blade turning that fast fills its disc in every cell).
constexpr double kWorkFactor = 4.0;

// A deformed object's search maps the ray's pieces through the deformation,
// work the tests above do not count. Its stated limit per ray: the stiff
// twists measured 41 (1500 and 5000 rays) when this was written, down from
// 105 before a twist's reach was used and several thousand while rays in a
// face or cut plane ran the search to its limit.
constexpr double kMapsPerRay = 64.0;

double tame_work() {
    static const double work = check_case(kTame).tests_per_ray;
    return work;
}

void run(const Case& c) {
    const Work w = check_case(c);
    if (std::getenv("HEXANT_STRESS_VERBOSE"))
        std::printf(
            "%s: %d of %d rays hit, %.2f tests per ray (tame %.2f), %.0f ns per ray, "
            "%.1f deformation maps per ray\n",
            Catch::getResultCapture().getCurrentTestName().c_str(), w.hits, rays_per_case(),
            w.tests_per_ray, tame_work(), w.ns_per_ray, w.maps_per_ray);
    INFO("tests per ray " << w.tests_per_ray << ", tame " << tame_work() << ", hits " << w.hits);
    CHECK(w.hits > 0);
    CHECK(w.tests_per_ray <= kWorkFactor * tame_work());
    INFO("deformation maps per ray " << w.maps_per_ray);
    CHECK(w.maps_per_ray <= kMapsPerRay);
}

}  // namespace

TEST_CASE("the tame scene", "[stress]") {
    const Work w = check_case(kTame);
    if (std::getenv("HEXANT_STRESS_VERBOSE"))
        std::printf("the tame scene: %d of %d rays hit, %.2f tests per ray, %.0f ns per ray\n",
                    w.hits, rays_per_case(), w.tests_per_ray, w.ns_per_ray);
    CHECK(w.hits > 0);
    CHECK(w.tests_per_ray > 0.0);
}

TEST_CASE("objects 10^6 units from the origin", "[stress]") {
    Case c{R"(
#declare Far = <1e6, -1e6, 1e6>;
sphere { Far, 0.5 translate x * clock }
box { Far - 0.4, Far + 0.4 translate <0, 1, 1> + y * clock }
sphere { Far + <1, 0, 0>, 0.3 translate -z * 2 * clock }
triangle { Far + <-1, -1, 2>, Far + <1, -1, 2>, Far + <0, 1, 2> }
)"};
    c.camera = "camera { location <1e6, -1e6, 1e6 - 8> look_at <1e6, -1e6, 1e6> }\n";
    run(c);
}

TEST_CASE("sizes 10^-6 and 10^6 in one scene", "[stress]") {
    run({R"(
sphere { <0, 0, 0>, 1e-6 translate x * 1e-6 * clock }
box { <2, 0, 0>, <2 + 2e-6, 2e-6, 2e-6> }
sphere { <0, 0, 2e6 + 10>, 1e6 translate y * clock }
sphere { <0, 1, 0>, 0.5 }
)"});
}

TEST_CASE("rays grazing spheres, parallel to slabs and in cell walls", "[stress]") {
    // Spheres and boxes on the cell walls of a root from -4 to 4: the ray
    // kinds above run along their faces, tangent planes and the walls.
    run({R"(
sphere { <0, 0, 0>, 1 }
sphere { <2, 2, 2>, 1 translate -x * clock }
box { <-4, -4, -4>, <-2, -2, -2> }
box { <2, -4, -2>, <4, -2, 0> translate y * clock }
box { <-1, 2, -1>, <1, 4, 1> }
)"});
}

TEST_CASE("motion of 1000 object sizes within one frame", "[stress]") {
    run({R"(
sphere { <0, 0, 0>, 0.01 translate x * 40 * clock }
sphere { <0, 1, 0>, 0.01 translate <40 * clock, 0, 40 * clock> }
sphere { <0, -1, 0>, 0.5 }
)"});
}

TEST_CASE("1000 turns per frame", "[stress]") {
    run({R"(
box { <0.5, -0.1, -0.1>, <1.5, 0.1, 0.1> rotate y * 360 * 4000 * clock }
sphere { <1, 1, 0>, 0.2 rotate z * 360 * 4000 * clock }
sphere { <0, -1, 0>, 0.5 }
)"});
}

// A sliding sphere and a turning box, for the extreme shutters.
const char* const kShutterObjects = R"(
sphere { <-1, 0, 0>, 0.5 translate x * 2 * clock }
box { <0, 0, 0>, <1, 1, 1> rotate y * 360 * clock }
)";

TEST_CASE("a zero-length shutter", "[stress]") {
    Case c{kShutterObjects};
    c.shutter = 0.0;
    run(c);
}

TEST_CASE("a shutter as long as the whole animation", "[stress]") {
    Case c{kShutterObjects};
    c.frames = 2;
    c.cyclic = true;
    c.shutter = 2.0;  // frame 1 opens at 0 and closes at 1
    run(c);
}

TEST_CASE("deformations with stiff rates", "[stress]") {
    run({R"(
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> twist y, 360 * 24 }
box { <-0.3, 0, -0.3>, <0.3, 2, 0.3> twist y, 360 * 12 * clock translate x * 1.5 }
cylinder { 0, 2 * y, 0.3 bend y, 80 * clock translate -x * 1.5 }
)"});
}

TEST_CASE("splines with coincident keys", "[stress]") {
    run({R"(
#declare Linear = spline { linear_spline 0, <0, 0, 0>, 0.5, <1, 0, 0>, 0.5, <1, 0, 0>, 1, <2, 1, 0> }
#declare Cubic = spline { cubic_spline -0.5, <0, 0, 0>, 0, <0, 0, 0>, 0, <0, 0, 0>, 0.5, <1, 1, 0>, 0.5, <1, 1, 0>, 1, <-1, 0, 1>, 1.5, <0, 0, 0> }
sphere { 0, 0.3 translate Linear(clock) }
sphere { 0, 0.3 translate Cubic(clock) + y }
box { -0.2, 0.2 translate Linear(clock) - y }
)"});
}

TEST_CASE("objects that appear or vanish at a frame boundary", "[stress]") {
    // hexant has no existence in time; an object that jumps in from far
    // away at clock 0.5 (a frame boundary of 4 frames) is the same test for
    // the bounds: a discontinuous motion.
    run({R"(
sphere { <0, 0, 0>, 0.5 translate y * 1000 * (clock < 0.5) }
sphere { <1, 0, 0>, 0.5 translate -y * 1000 * (clock >= 0.5) }
box { <-2, -1, -1>, <-1, 0, 0> translate z * 500 * (clock > 0.75) }
)"});
}

TEST_CASE("a camera inside an object", "[stress]") {
    Case c{R"(
sphere { <0, 1, -8>, 2 pigment { rgbf <1, 1, 1, 0.5> } interior { ior 1.3 } }
box { <-1, -1, -1>, <1, 1, 1> rotate y * 90 * clock }
)"};
    run(c);
}
