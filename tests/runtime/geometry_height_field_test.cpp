// height_field (runtime/objects/height_field): the hierarchy against every
// triangle tested, normals, smooth normals, inside, bounds, the water cut,
// POV-Ray's pixel-to-height rules and reading PNG files.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <png.h>
#include <unistd.h>

#include "runtime/objects/height_field/height_field_data.hpp"
#include "runtime/objects/height_field/height_field_geometry.hpp"
#include "runtime/objects/triangle/triangle_geometry.hpp"

namespace {

namespace fs = std::filesystem;
using hexant::image::StoredImage;
using hexant::runtime::geometry::Box3;
using hexant::runtime::geometry::HeightFieldGeometry;
using hexant::runtime::geometry::Ray3;
using hexant::runtime::geometry::SurfaceHit;
using hexant::runtime::objects::HeightFieldData;
using hexant::runtime::objects::HeightFieldError;
namespace geo = hexant::runtime::geometry;
namespace obj = hexant::runtime::objects;

constexpr double kInf = std::numeric_limits<double>::infinity();

std::shared_ptr<const HeightFieldData> field_of(int w, int d, const std::vector<std::uint16_t>& h) {
    return std::make_shared<const HeightFieldData>(w, d, h);
}

// A bumpy random field: smooth hills plus noise.
std::shared_ptr<const HeightFieldData> random_field(int w, int d, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> noise(-3000, 3000);
    std::vector<std::uint16_t> h(static_cast<std::size_t>(w) * static_cast<std::size_t>(d));
    for (int z = 0; z < d; ++z)
        for (int x = 0; x < w; ++x) {
            const double v =
                30000.0 + 15000.0 * std::sin(0.3 * x) * std::cos(0.21 * z) + noise(rng);
            h[static_cast<std::size_t>(z * w + x)] =
                static_cast<std::uint16_t>(std::clamp(v, 0.0, 65535.0));
        }
    return field_of(w, d, h);
}

struct Reference {
    double s;
    int part;
    glm::dvec3 normal;
};

// Every triangle tested, POV-Ray's split and the floor's cut.
std::optional<Reference> brute_force(const HeightFieldGeometry& g, const Ray3& ray, double s_min,
                                     double s_max) {
    const HeightFieldData& d = *g.data;
    std::optional<Reference> best;
    for (int z = 0; z + 1 < d.depth(); ++z)
        for (int x = 0; x + 1 < d.width(); ++x)
            for (int which = 0; which < 2; ++which) {
                glm::dvec3 p1, p2, p3;
                if (which == 0) {
                    p1 = d.vertex(x, z), p2 = d.vertex(x + 1, z), p3 = d.vertex(x, z + 1);
                } else {
                    p1 = d.vertex(x + 1, z + 1), p2 = d.vertex(x, z + 1), p3 = d.vertex(x + 1, z);
                }
                const auto hit = geo::intersect_barycentric(p1, p2, p3, ray, s_min, s_max);
                if (!hit) continue;
                if (hit->b1 * p1.y + hit->b2 * p2.y + hit->b3 * p3.y < g.floor) continue;
                glm::dvec3 n = glm::normalize(glm::cross(p3 - p1, p2 - p1));
                if (n.y < 0.0) n = -n;
                best = Reference{hit->s, which, n};
                s_max = hit->s;
            }
    return best;
}

bool well_formed(const SurfaceHit& h) {
    return geo::is_finite(h) && std::fabs(glm::length(h.normal) - 1.0) < 1e-12 &&
           std::fabs(glm::length(h.shading_normal) - 1.0) < 1e-12;
}

glm::dvec3 random_unit(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (;;) {
        const glm::dvec3 v(u(rng), u(rng), u(rng));
        const double l = glm::length(v);
        if (l > 0.1 && l <= 1.0) return v / l;
    }
}

void compare_with_brute_force(const HeightFieldGeometry& g, int count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int hits = 0;
    for (int i = 0; i < count; ++i) {
        // Aimed at a point over the field from around it, or random.
        const glm::dvec3 target(u(rng), u(rng) * 0.9, u(rng));
        const glm::dvec3 origin = i % 3 == 0
                                      ? glm::dvec3(u(rng) * 3 - 1, u(rng) * 3 - 1, u(rng) * 3 - 1)
                                      : target + (0.2 + 2.0 * u(rng)) * random_unit(rng);
        glm::dvec3 dir = target - origin;
        if (i % 17 == 0) dir = {0.0, -1.0, 0.0};  // straight down
        if (i % 19 == 0) dir.y = 0.0;             // level
        const Ray3 ray{origin, dir * (0.5 + u(rng))};
        const auto got = geo::intersect(g, ray, 0.0, kInf);
        const auto want = brute_force(g, ray, 0.0, kInf);
        INFO("ray " << i);
        REQUIRE(got.has_value() == want.has_value());
        if (!got) continue;
        ++hits;
        REQUIRE(well_formed(*got));
        REQUIRE(got->s == want->s);
        REQUIRE(got->part == want->part);
        REQUIRE(glm::length(got->normal - want->normal) < 1e-12);
        REQUIRE(got->point.y >= g.floor);
        const Box3 b = geo::object_bounds(g);
        REQUIRE(got->point.x >= b.lo.x - 1e-12);
        REQUIRE(got->point.x <= b.hi.x + 1e-12);
        REQUIRE(got->point.y >= b.lo.y - 1e-12);
        REQUIRE(got->point.y <= b.hi.y + 1e-12);
        REQUIRE(got->point.z >= b.lo.z - 1e-12);
        REQUIRE(got->point.z <= b.hi.z + 1e-12);
        REQUIRE(glm::length(ray.origin + got->s * ray.direction - got->point) < 1e-9);
        REQUIRE(geo::surface_may_meet(g, Box3{got->point, got->point}));
    }
    REQUIRE(hits > count / 5);
}

// Writes a PNG with libpng: `bits` 8 or 16 per sample, `colour` a PNG
// colour type, samples row by row (top first).
void write_png(const fs::path& path, int w, int h, int colour, int bits,
               const std::vector<unsigned>& samples, const std::vector<png_color>& palette = {}) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    REQUIRE(f != nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, bits, colour, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (!palette.empty()) png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
    png_write_info(png, info);
    const int per_pixel = colour == PNG_COLOR_TYPE_RGB ? 3 : 1;
    const int bytes = bits / 8;
    std::vector<unsigned char> row(static_cast<std::size_t>(w * per_pixel * bytes));
    for (int y = 0; y < h; ++y) {
        for (int i = 0; i < w * per_pixel; ++i) {
            const unsigned v = samples[static_cast<std::size_t>(y * w * per_pixel + i)];
            if (bytes == 2) {
                row[static_cast<std::size_t>(2 * i)] = static_cast<unsigned char>(v >> 8);
                row[static_cast<std::size_t>(2 * i + 1)] = static_cast<unsigned char>(v & 255);
            } else {
                row[static_cast<std::size_t>(i)] = static_cast<unsigned char>(v);
            }
        }
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

fs::path temp_folder() {
    const fs::path dir =
        fs::temp_directory_path() / ("hexant_hf_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

}  // namespace

TEST_CASE("height_field: grid, vertices and quadtree", "[geometry][height_field]") {
    const auto d = random_field(37, 23, 1);
    REQUIRE(d->width() == 37);
    REQUIRE(d->depth() == 23);
    REQUIRE(d->vertex(36, 22).x == 1.0);
    REQUIRE(d->vertex(36, 22).z == 1.0);
    REQUIRE(d->vertex(5, 7).y == d->height(5, 7) / 65536.0);
    // Every cell in exactly one leaf; every node's range holds its corners.
    std::vector<int> covered(36 * 22, 0);
    for (const auto& n : d->nodes()) {
        for (std::uint32_t z = n.z0; z <= n.z1; ++z)
            for (std::uint32_t x = n.x0; x <= n.x1; ++x) {
                REQUIRE(d->height(int(x), int(z)) >= n.lo);
                REQUIRE(d->height(int(x), int(z)) <= n.hi);
            }
        if (n.count == 0)
            for (std::uint32_t z = n.z0; z < n.z1; ++z)
                for (std::uint32_t x = n.x0; x < n.x1; ++x) ++covered[z * 36 + x];
    }
    for (int c : covered) REQUIRE(c == 1);
    REQUIRE_THROWS_AS(HeightFieldData(1, 5, std::vector<std::uint16_t>(5)), HeightFieldError);
}

TEST_CASE("height_field: hierarchy finds what testing every triangle finds",
          "[geometry][height_field]") {
    for (int smooth = 0; smooth < 2; ++smooth) {
        const auto d = random_field(41, 29, 2);
        HeightFieldGeometry g{d, geo::height_field_floor(*d, 0.0), smooth == 1};
        compare_with_brute_force(g, 3000, 3 + smooth);
    }
    // Tiny grids: 2 x 2 (one cell) and 2 x 9.
    const auto one = field_of(2, 2, {0, 65535, 30000, 1000});
    compare_with_brute_force({one, geo::height_field_floor(*one, 0.0), false}, 1000, 5);
    const auto strip = random_field(2, 9, 6);
    compare_with_brute_force({strip, geo::height_field_floor(*strip, 0.0), true}, 1000, 7);
    // A flat field: the plane y = h / 65536.
    const auto flat = field_of(5, 5, std::vector<std::uint16_t>(25, 32768));
    HeightFieldGeometry fg{flat, geo::height_field_floor(*flat, 0.0), true};
    const auto hit = geo::intersect(fg, Ray3{{0.3, 2.0, 0.6}, {0.1, -1.0, 0.05}}, 0.0, kInf);
    REQUIRE(hit);
    REQUIRE(hit->point.y == Approx(0.5).margin(1e-15));
    REQUIRE(hit->normal.y == 1.0);
    REQUIRE(glm::length(hit->shading_normal - glm::dvec3(0, 1, 0)) < 1e-12);
    REQUIRE(hit->uv.x == Approx(hit->point.x));
    REQUIRE(hit->uv.y == Approx(hit->point.z));
    // s_min and s_max bound the hit; rays from below pass through to the
    // surface too (the field has no bottom).
    REQUIRE_FALSE(geo::intersect(fg, Ray3{{0.3, 2.0, 0.6}, {0.0, -1.0, 0.0}}, 0.0, 1.4));
    const auto below = geo::intersect(fg, Ray3{{0.3, -1.0, 0.6}, {0.0, 1.0, 0.0}}, 0.0, kInf);
    REQUIRE(below);
    REQUIRE(below->s == Approx(1.5));
    REQUIRE(below->normal.y > 0.0);  // the field's upward side, not flipped
}

TEST_CASE("height_field: 1024 x 1024 field through the quadtree", "[geometry][height_field]") {
    const auto d = random_field(1024, 1024, 8);
    HeightFieldGeometry g{d, geo::height_field_floor(*d, 0.0), true};
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 origin(u(rng) * 2 - 0.5, 1.5, u(rng) * 2 - 0.5);
        const glm::dvec3 target(u(rng), 0.3, u(rng));
        const auto h = geo::intersect(g, Ray3{origin, target - origin}, 0.0, kInf);
        if (!h) continue;
        ++hits;
        REQUIRE(well_formed(*h));
    }
    REQUIRE(hits > 10000);
}

TEST_CASE("height_field: triangle normals are POV-Ray's", "[geometry][height_field]") {
    // One cell, corners (x, z): (0,0) 1000, (1,0) 5000, (0,1) 9000, (1,1) 2000,
    // on a 2 x 2 grid: object scale x 1, z 1, y 1/65536.
    const auto d = field_of(2, 2, {1000, 5000, 9000, 2000});
    HeightFieldGeometry g{d, geo::height_field_floor(*d, 0.0), false};
    // Lower triangle (x + z < 1): N = <y1 - y2, 1, y1 - y3> in grid units,
    // object space <N.x (w - 1), 65536, N.z (d - 1)>.
    auto h = geo::intersect(g, Ray3{{0.2, 1.0, 0.3}, {0.0, -1.0, 0.0}}, 0.0, kInf);
    REQUIRE(h);
    REQUIRE(h->part == 0);
    const glm::dvec3 lower = glm::normalize(glm::dvec3(1000.0 - 5000.0, 65536.0, 1000.0 - 9000.0));
    REQUIRE(glm::length(h->normal - lower) < 1e-15);
    h = geo::intersect(g, Ray3{{0.8, 1.0, 0.7}, {0.0, -1.0, 0.0}}, 0.0, kInf);
    REQUIRE(h);
    REQUIRE(h->part == 1);
    const glm::dvec3 upper = glm::normalize(glm::dvec3(9000.0 - 2000.0, 65536.0, 5000.0 - 2000.0));
    REQUIRE(glm::length(h->normal - upper) < 1e-15);
    // The hit lies on the plane through the triangle's corners.
    const glm::dvec3 p4(1.0, 2000.0 / 65536.0, 1.0);
    REQUIRE(std::fabs(glm::dot(h->point - p4, upper)) < 1e-15);
}

TEST_CASE("height_field: smooth normals", "[geometry][height_field]") {
    // A tilted plane: every vertex normal is the plane's (up to the 16-bit
    // quantization), and so is the blend.
    std::vector<std::uint16_t> tilt;
    for (int z = 0; z < 6; ++z)
        for (int x = 0; x < 9; ++x)
            tilt.push_back(static_cast<std::uint16_t>(1000 + 700 * x + 300 * z));
    const auto d = field_of(9, 6, tilt);
    const glm::dvec3 plane = glm::normalize(glm::dvec3(-700.0 * 8, 65536.0, -300.0 * 5));
    std::mt19937_64 rng(10);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 n = geo::height_field_smooth_normal(*d, {u(rng), 0.0, u(rng)});
        REQUIRE(glm::length(n) == Approx(1.0));
        REQUIRE(glm::length(n - plane) < 2e-3);
    }
    // A peak in the middle of a 3 x 3 grid: the centre vertex's normal is
    // straight up; at a corner vertex the blend is that vertex's normal.
    const auto peak = field_of(3, 3, {0, 0, 0, 0, 20000, 0, 0, 0, 0});
    const glm::dvec3 c = geo::height_field_smooth_normal(*peak, {0.5, 0.0, 0.5});
    REQUIRE(glm::length(c - glm::dvec3(0, 1, 0)) < 1e-12);
    // Vertex (0, 0): its only triangle is (0,0), (1,0), (0,1), all 0 but
    // (1,1) is 20000 — not in it, so the normal there is up.
    const glm::dvec3 corner = geo::height_field_smooth_normal(*peak, {0.0, 0.0, 0.0});
    REQUIRE(glm::length(corner - glm::dvec3(0, 1, 0)) < 1e-12);
    // Vertex (1, 0) (x = 0.5, z = 0): its triangles (1,0),(2,0),(1,1) and
    // (1,0),(1,1),(0,0) rise toward +z; in grid units each face normal is
    // <0, 1, -20000> normalized, so the stored normal is (short)(32767 *
    // <0, 1/20000, -1>) = <0, 1, -32766>... taken to object space
    // <0, 65536, -32766 * 2> normalized.
    const auto& s = peak->smooth_normals()[1];
    const glm::dvec3 grid = glm::normalize(glm::dvec3(0.0, 1.0, -20000.0));
    REQUIRE(s[0] == 0);
    REQUIRE(s[1] == static_cast<std::int16_t>(32767 * grid.y));
    REQUIRE(s[2] == static_cast<std::int16_t>(32767 * grid.z));
    const glm::dvec3 edge = geo::height_field_smooth_normal(*peak, {0.5, 0.0, 0.0});
    const glm::dvec3 want = glm::normalize(glm::dvec3(0.0, s[1] * 65536.0, s[2] * 2.0));
    REQUIRE(glm::length(edge - want) < 1e-12);
    // Through intersect: the shading normal is the blend, the normal the
    // triangle's.
    HeightFieldGeometry g{peak, geo::height_field_floor(*peak, 0.0), true};
    const auto h = geo::intersect(g, Ray3{{0.3, 1.0, 0.2}, {0.0, -1.0, 0.0}}, 0.0, kInf);
    REQUIRE(h);
    REQUIRE(glm::length(h->shading_normal - geo::height_field_smooth_normal(*peak, h->point)) <
            1e-15);
    REQUIRE(h->shading_normal != h->normal);
}

TEST_CASE("height_field: inside, bounds and the water level", "[geometry][height_field]") {
    const auto d = random_field(17, 13, 11);
    HeightFieldGeometry g{d, geo::height_field_floor(*d, 0.0), false};
    const Box3 b = geo::object_bounds(g);
    REQUIRE(b.lo.x == 0.0);
    REQUIRE(b.hi.x == 1.0);
    REQUIRE(b.lo.y == Approx((d->min_height() - 0.001) / 65536.0));
    REQUIRE(b.hi.y == Approx((d->max_height() + 0.001) / 65536.0));
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 500; ++i) {
        const glm::dvec3 top(u(rng), 2.0, u(rng));
        const auto h = geo::intersect(g, Ray3{top, {0.0, -1.0, 0.0}}, 0.0, kInf);
        REQUIRE(h);
        REQUIRE(geo::inside(g, h->point - glm::dvec3(0.0, 1e-9, 0.0)));
        REQUIRE_FALSE(geo::inside(g, h->point + glm::dvec3(0.0, 1e-9, 0.0)));
        REQUIRE(geo::inside(g, {top.x, -5.0, top.z}));  // below: inside, as POV-Ray
    }
    REQUIRE_FALSE(geo::inside(g, {-0.1, 0.0, 0.5}));
    REQUIRE_FALSE(geo::inside(g, {0.5, 0.0, 1.0}));  // POV-Ray: x or z at the far edge is out
    REQUIRE_FALSE(geo::inside(g, {0.5, 1.0, 0.5}));

    // Water at the middle height: the surface below it is cut away, the
    // hierarchy agrees with every triangle tested, points below are inside.
    const double water = 0.5 * (d->min_height() + d->max_height()) / 65536.0;
    HeightFieldGeometry wet{d, geo::height_field_floor(*d, water), false};
    REQUIRE(wet.floor == Approx(water - 0.001 / 65536.0));
    REQUIRE(geo::object_bounds(wet).lo.y == wet.floor);
    compare_with_brute_force(wet, 3000, 13);
    int cut = 0;
    for (int i = 0; i < 500; ++i) {
        const glm::dvec3 top(u(rng), 2.0, u(rng));
        const auto dry = geo::intersect(g, Ray3{top, {0.0, -1.0, 0.0}}, 0.0, kInf);
        const auto h = geo::intersect(wet, Ray3{top, {0.0, -1.0, 0.0}}, 0.0, kInf);
        REQUIRE(dry);
        if (dry->point.y < wet.floor) {
            REQUIRE_FALSE(h);
            ++cut;
            REQUIRE(geo::inside(wet, {top.x, wet.floor - 1e-9, top.z}));
        } else {
            REQUIRE(h);
            REQUIRE(h->s == dry->s);
        }
    }
    REQUIRE(cut > 50);
    // Water above everything: nothing to hit, nothing to meet.
    HeightFieldGeometry drowned{d, geo::height_field_floor(*d, 1.5), false};
    REQUIRE_FALSE(geo::intersect(drowned, Ray3{{0.5, 2.0, 0.5}, {0.0, -1.0, 0.0}}, 0.0, kInf));
    REQUIRE_FALSE(geo::surface_may_meet(drowned, Box3{{0, -1, 0}, {1, 2, 1}}));
    const Box3 db = geo::object_bounds(drowned);
    REQUIRE(db.lo.y <= db.hi.y);
}

TEST_CASE("height_field: surface_may_meet", "[geometry][height_field]") {
    const auto d = random_field(21, 21, 14);
    HeightFieldGeometry g{d, geo::height_field_floor(*d, 0.0), false};
    REQUIRE(geo::surface_may_meet(g, Box3{{-1, -1, -1}, {2, 2, 2}}));
    REQUIRE_FALSE(geo::surface_may_meet(g, Box3{{0.2, 1.5, 0.2}, {0.8, 2.0, 0.8}}));
    REQUIRE_FALSE(geo::surface_may_meet(g, Box3{{0.2, -2.0, 0.2}, {0.8, -1.0, 0.8}}));
    REQUIRE_FALSE(geo::surface_may_meet(g, Box3{{1.1, 0.0, 0.2}, {1.5, 1.0, 0.8}}));
    // Boxes around surface points.
    std::mt19937_64 rng(15);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 300; ++i) {
        const auto h = geo::intersect(g, Ray3{{u(rng), 2.0, u(rng)}, {0.0, -1.0, 0.0}}, 0.0, kInf);
        REQUIRE(h);
        const double e = std::pow(10.0, -1.0 - 12.0 * u(rng));
        REQUIRE(geo::surface_may_meet(g, Box3{h->point - e * u(rng), h->point + e * u(rng)}));
    }
}

TEST_CASE("height_field: random rays give finite hits or none", "[geometry][height_field]") {
    const auto d = random_field(33, 33, 16);
    HeightFieldGeometry g{d, geo::height_field_floor(*d, 0.2), true};
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 5000; ++i) {
        const double reach = std::pow(10.0, -3.0 + 10.0 * u(rng));
        const glm::dvec3 origin = glm::dvec3(0.5) + reach * random_unit(rng);
        glm::dvec3 dir = i % 2 ? glm::dvec3(0.5) - origin : random_unit(rng);
        if (i % 3 == 0) dir[i % 3] = 0.0;
        if (i % 11 == 0) dir = glm::dvec3(0.0);
        dir *= std::pow(10.0, -100.0 + 200.0 * u(rng));
        const auto h = geo::intersect(g, Ray3{origin, dir}, i % 2 ? 0.0 : -kInf, kInf);
        if (h) {
            REQUIRE(well_formed(*h));
            REQUIRE(dir != glm::dvec3(0.0));
        }
    }
}

TEST_CASE("height_field: POV-Ray's heights from pixels", "[height_field][image]") {
    // Values as image::read_stored_image gives them: byte / 255, 16-bit
    // sample / 65535. Expected heights from POV-Ray's imageutil.cpp
    // image_height_at evaluated with float arithmetic (see the test's
    // comments): 8-bit gray v -> (HF_VAL)(float(v) / 255.0f * 65535.0f).
    const auto image = [](StoredImage::Source source, int bits, std::vector<float> rgb) {
        StoredImage s;
        s.width = static_cast<int>(rgb.size() / 3);
        s.height = 1;
        s.channels = 3;
        s.source = source;
        s.source_bits = bits;
        s.values = std::move(rgb);
        return s;
    };
    {
        const int bytes[] = {0, 1, 2, 100, 128, 200, 254, 255};
        const std::uint16_t want[] = {0, 257, 514, 25700, 32896, 51400, 65278, 65535};
        std::vector<float> v;
        for (int b : bytes)
            for (int k = 0; k < 3; ++k) v.push_back(float(b / 255.0));
        const auto h = obj::heights_from_image(image(StoredImage::Source::Gray, 8, v));
        for (int i = 0; i < 8; ++i) REQUIRE(h[static_cast<std::size_t>(i)] == want[i]);
    }
    {
        const int samples[] = {0, 1, 257, 1000, 32768, 65534, 65535};
        std::vector<float> v;
        for (int s : samples)
            for (int k = 0; k < 3; ++k) v.push_back(float(s / 65535.0));
        const auto h = obj::heights_from_image(image(StoredImage::Source::Gray, 16, v));
        for (int i = 0; i < 7; ++i) REQUIRE(h[static_cast<std::size_t>(i)] == samples[i]);
    }
    {
        // 8-bit RGB: red the high byte, green the low one, blue ignored.
        const int rg[][2] = {{0, 0}, {1, 2}, {3, 0}, {128, 128}, {255, 255}, {0, 255}, {17, 250}};
        const std::uint16_t want[] = {0, 258, 768, 32896, 65535, 255, 4602};
        std::vector<float> v;
        for (const auto& p : rg) {
            v.push_back(float(p[0] / 255.0));
            v.push_back(float(p[1] / 255.0));
            v.push_back(0.7f);
        }
        const auto h = obj::heights_from_image(image(StoredImage::Source::Rgb, 8, v));
        for (int i = 0; i < 7; ++i) REQUIRE(h[static_cast<std::size_t>(i)] == want[i]);
    }
    {
        // 16-bit RGB: POV-Ray's GREY_SCALE3 (0.297, 0.589, 0.114).
        const std::vector<float> v{
            1.0f, 0.0f, 0.0f, float(1000 / 65535.0), float(2000 / 65535.0), float(3000 / 65535.0),
            1.0f, 1.0f, 1.0f};
        const auto h = obj::heights_from_image(image(StoredImage::Source::Rgb, 16, v));
        REQUIRE(h[0] == 19463);
        REQUIRE(h[1] == 1817);
        REQUIRE(h[2] == 65534);
    }
    {
        // Rows: the image's top row is the far edge z = depth - 1.
        StoredImage s;
        s.width = 2;
        s.height = 3;
        s.channels = 3;
        s.source = StoredImage::Source::Gray;
        for (int row = 0; row < 3; ++row)
            for (int x = 0; x < 2; ++x)
                for (int k = 0; k < 3; ++k) s.values.push_back(float((10 * row + x) / 255.0));
        const auto h = obj::heights_from_image(s);
        HeightFieldData d(2, 3, h);
        REQUIRE(d.height(0, 2) == 0);
        REQUIRE(d.height(1, 2) == 257);
        REQUIRE(d.height(1, 0) == 21 * 257);
    }
}

TEST_CASE("height_field: reading PNG files", "[height_field][image]") {
    const fs::path dir = temp_folder();
    // 8-bit gray, 3 x 2.
    write_png(dir / "gray.png", 3, 2, PNG_COLOR_TYPE_GRAY, 8, {0, 128, 255, 1, 2, 100});
    auto d = obj::read_height_field(dir / "gray.png", "png");
    REQUIRE(d->width() == 3);
    REQUIRE(d->depth() == 2);
    REQUIRE(d->height(0, 1) == 0);
    REQUIRE(d->height(1, 1) == 32896);
    REQUIRE(d->height(2, 1) == 65535);
    REQUIRE(d->height(0, 0) == 257);
    REQUIRE(d->height(2, 0) == 25700);
    // No type word: the extension says.
    REQUIRE(obj::read_height_field(dir / "gray.png", "")->height(1, 1) == 32896);
    // 16-bit gray.
    write_png(dir / "deep.png", 2, 2, PNG_COLOR_TYPE_GRAY, 16, {0, 1000, 40000, 65535});
    d = obj::read_height_field(dir / "deep.png", "png");
    REQUIRE(d->height(0, 1) == 0);
    REQUIRE(d->height(1, 1) == 1000);
    REQUIRE(d->height(0, 0) == 40000);
    REQUIRE(d->height(1, 0) == 65535);
    // 8-bit RGB.
    write_png(dir / "rgb.png", 2, 2, PNG_COLOR_TYPE_RGB, 8,
              {1, 2, 9, 3, 0, 9, 17, 250, 0, 0, 0, 0});
    d = obj::read_height_field(dir / "rgb.png", "png");
    REQUIRE(d->height(0, 1) == 258);
    REQUIRE(d->height(1, 1) == 768);
    REQUIRE(d->height(0, 0) == 4602);
    // Paletted: the index * 256, whatever the colours.
    std::vector<png_color> palette(8);
    for (int i = 0; i < 8; ++i)
        palette[static_cast<std::size_t>(i)] = {static_cast<png_byte>(255 - i), 0,
                                                static_cast<png_byte>(i)};
    write_png(dir / "palette.png", 2, 2, PNG_COLOR_TYPE_PALETTE, 8, {0, 7, 3, 5}, palette);
    d = obj::read_height_field(dir / "palette.png", "png");
    REQUIRE(d->height(0, 1) == 0);
    REQUIRE(d->height(1, 1) == 7 * 256);
    REQUIRE(d->height(0, 0) == 3 * 256);
    REQUIRE(d->height(1, 0) == 5 * 256);
    // Refusals, naming what was refused.
    REQUIRE_THROWS_WITH(obj::read_height_field(dir / "gray.png", "sys"),
                        Catch::Contains("sys images") && Catch::Contains("Unix"));
    REQUIRE_THROWS_WITH(obj::read_height_field(dir / "x.iff", ""),
                        Catch::Contains("iff images") && Catch::Contains("Unexpected EOF"));
    REQUIRE_THROWS_WITH(obj::read_height_field(dir / "x.xyz", ""), Catch::Contains(".xyz"));
    REQUIRE_THROWS_WITH(obj::read_height_field(dir / "x.jpg", ""), Catch::Contains(".jpg"));
    REQUIRE_THROWS_WITH(obj::read_height_field(dir / "gray.png", "exr"),
                        Catch::Contains("OpenEXR"));
    REQUIRE_THROWS_AS(obj::read_height_field(dir / "missing.png", "png"), HeightFieldError);
    write_png(dir / "dot.png", 1, 1, PNG_COLOR_TYPE_GRAY, 8, {5});
    REQUIRE_THROWS_WITH(obj::read_height_field(dir / "dot.png", "png"), Catch::Contains("2 x 2"));
    fs::remove_all(dir);
}
