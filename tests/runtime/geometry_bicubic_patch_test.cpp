// Static ray/bicubic_patch geometry against references that do not halve:
// a planar patch (hits on its plane, normals along its axis, uv as the
// uv_vectors' bilinear blend), the pieces' count and their corners against
// the Bernstein form on the dyadic grid, flatness measured after the
// placement's linear part (POV-Ray moves the points into the world first),
// normals against the tangents' cross product (and POV-Ray's <1, 0, 0>
// where a row of points is one point), each ray's own subdivision (type 0)
// against the kept one (type 1), surface_may_meet never "no" beside a hit,
// and no NaN or Inf out for extreme rays.
#include <cmath>
#include <limits>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include "runtime/objects/bicubic_patch/bicubic_patch_geometry.hpp"

namespace geo = hexant::runtime::geometry;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The patch's point at (u, v) from the Bernstein form.
glm::dvec3 bernstein(const geo::BicubicNet& p, double u, double v) {
    const double bu[4] = {(1 - u) * (1 - u) * (1 - u), 3 * u * (1 - u) * (1 - u),
                          3 * u * u * (1 - u), u * u * u};
    const double bv[4] = {(1 - v) * (1 - v) * (1 - v), 3 * v * (1 - v) * (1 - v),
                          3 * v * v * (1 - v), v * v * v};
    glm::dvec3 out(0.0);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) out += bu[i] * bv[j] * p[static_cast<std::size_t>(4 * i + j)];
    return out;
}

// A patch whose points are the grid (i, j, h(i, j)) / 3.
geo::BicubicPatchGeometry patch_of(double (*height)(int, int), double flatness, int u_steps,
                                   int v_steps) {
    geo::BicubicPatchGeometry g;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            g.points[static_cast<std::size_t>(4 * i + j)] = {i / 3.0, j / 3.0, height(i, j)};
    g.flatness = flatness;
    g.u_steps = u_steps;
    g.v_steps = v_steps;
    return g;
}

double flat(int, int) {
    return 0.0;
}
double wavy(int i, int j) {
    return 0.3 * std::sin(1.7 * i + 0.4) * std::cos(1.3 * j - 0.2);
}

std::size_t piece_count(const geo::BicubicPatchGeometry& g) {
    std::size_t n = 0;
    geo::each_bicubic_piece(g, [&](const geo::BicubicPiece&) { ++n; });
    return n;
}

}  // namespace

TEST_CASE("bicubic_patch: a planar patch is hit on its plane, with its axis as normal",
          "[geometry][bicubic_patch]") {
    geo::BicubicPatchGeometry g = patch_of(flat, 0.0, 2, 1);
    g.uv_corners = {glm::dvec2(0.0, 0.0), glm::dvec2(2.0, 0.0), glm::dvec2(2.0, 4.0),
                    glm::dvec2(0.0, 4.0)};
    for (const bool kept : {false, true}) {
        if (kept) geo::keep_subdivision(g);
        for (int k = 0; k < 50; ++k) {
            const double x = 0.02 + 0.96 * ((k * 37) % 50) / 50.0;
            const double y = 0.02 + 0.96 * ((k * 11) % 50) / 50.0;
            const geo::Ray3 ray{{x, y, 5.0}, {0.0, 0.0, -2.0}};
            const auto hit = geo::intersect(g, ray, 0.0, kInf);
            REQUIRE(hit);
            CHECK(hit->s == Approx(2.5).epsilon(1e-14));
            CHECK(hit->point.z == 0.0);
            CHECK(std::fabs(hit->normal.z) == 1.0);
            CHECK(std::fabs(hit->shading_normal.z) == Approx(1.0).epsilon(1e-14));
            // The grid is uniform, so (u, v) = (x, y); uv blends the
            // uv_vectors at (v, u): here (2 v, 4 u).
            CHECK(hit->uv.x == Approx(2.0 * y).margin(1e-12));
            CHECK(hit->uv.y == Approx(4.0 * x).margin(1e-12));
        }
    }
    // Beside it, nothing.
    CHECK_FALSE(geo::intersect(g, {{1.5, 0.5, 5.0}, {0.0, 0.0, -1.0}}, 0.0, kInf));
    CHECK_FALSE(geo::inside(g, {0.5, 0.5, 0.0}));
}

TEST_CASE("bicubic_patch: the pieces are the dyadic grid's cells, corners on the patch",
          "[geometry][bicubic_patch]") {
    // Never flat (flatness 0): u_steps and v_steps halvings, u and v
    // together while both have steps (POV-Ray's order).
    const geo::BicubicPatchGeometry g = patch_of(wavy, 0.0, 3, 1);
    CHECK(piece_count(g) == 16);
    geo::each_bicubic_piece(g, [&](const geo::BicubicPiece& p) {
        CHECK(p.u1 - p.u0 == 0.125);
        CHECK(p.v1 - p.v0 == 0.5);
        const glm::dvec3 expected[4] = {
            bernstein(g.points, p.u0, p.v0), bernstein(g.points, p.u0, p.v1),
            bernstein(g.points, p.u1, p.v1), bernstein(g.points, p.u1, p.v0)};
        for (int k = 0; k < 4; ++k)
            CHECK(glm::length(p.corners[static_cast<std::size_t>(k)] - expected[k]) < 1e-15);
    });
    CHECK(piece_count(patch_of(wavy, 0.0, 0, 0)) == 1);
    CHECK(piece_count(patch_of(wavy, 0.0, 2, 4)) == 64);
    // A flat patch is one piece however many steps it may take; a wavy one
    // stops where its pieces are flat enough.
    CHECK(piece_count(patch_of(flat, 0.01, 5, 5)) == 1);
    const std::size_t loose = piece_count(patch_of(wavy, 0.05, 6, 6));
    const std::size_t tight = piece_count(patch_of(wavy, 0.001, 6, 6));
    CHECK(loose > 1);
    CHECK(loose < tight);
    CHECK(tight < 4096);
}

TEST_CASE("bicubic_patch: flatness is measured after the placement's linear part",
          "[geometry][bicubic_patch]") {
    // Every piece of the patch as placed by scale 3 is the piece of the
    // patch whose points are scaled by 3.
    geo::BicubicPatchGeometry placed = patch_of(wavy, 0.02, 6, 6);
    placed.measure = glm::dmat3(3.0);
    geo::BicubicPatchGeometry scaled = placed;
    scaled.measure = glm::dmat3(1.0);
    for (auto& p : scaled.points) p *= 3.0;
    CHECK(piece_count(placed) == piece_count(scaled));
    CHECK(piece_count(placed) > piece_count(patch_of(wavy, 0.02, 6, 6)));
    // And the normals too: a squash's normal is the squashed patch's.
    geo::BicubicPatchGeometry squashed = patch_of(wavy, 0.0, 0, 0);
    squashed.measure = glm::dmat3(glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 1.0, 0.0),
                                  glm::dvec3(0.0, 0.0, 0.25));
    geo::BicubicPatchGeometry moved = squashed;
    moved.measure = glm::dmat3(1.0);
    for (auto& p : moved.points) p.z *= 0.25;
    for (const double u : {0.0, 0.3, 1.0})
        for (const double v : {0.0, 0.6, 1.0})
            CHECK(glm::length(geo::bicubic_normal(squashed, u, v) -
                              geo::bicubic_normal(moved, u, v)) < 1e-14);
}

TEST_CASE("bicubic_patch: normals are Pu x Pv, and <1, 0, 0> where it vanishes",
          "[geometry][bicubic_patch]") {
    const geo::BicubicPatchGeometry g = patch_of(wavy, 0.0, 0, 0);
    for (const double u : {0.0, 0.25, 0.7})
        for (const double v : {0.1, 0.5, 1.0}) {
            constexpr double h = 1e-6;
            const glm::dvec3 pu = (bernstein(g.points, u + h, v) - bernstein(g.points, u - h, v));
            const glm::dvec3 pv = (bernstein(g.points, u, v + h) - bernstein(g.points, u, v - h));
            const glm::dvec3 expected = glm::normalize(glm::cross(pu, pv));
            CHECK(glm::length(geo::bicubic_normal(g, u, v) - expected) < 1e-8);
        }
    // A row of one point (a dome's pole, the teapot's lid): no tangent
    // along v at u = 0, POV-Ray's fallback.
    geo::BicubicPatchGeometry pole = g;
    for (int j = 0; j < 4; ++j) pole.points[static_cast<std::size_t>(j)] = {0.0, 0.0, 1.0};
    CHECK(geo::bicubic_normal(pole, 0.0, 0.4) == glm::dvec3(1.0, 0.0, 0.0));
    CHECK(std::fabs(glm::length(geo::bicubic_normal(pole, 0.5, 0.4)) - 1.0) < 1e-15);
    // The pole's triangles of no area are no surface; the others are.
    pole.u_steps = pole.v_steps = 2;
    int hits = 0;
    for (int k = 0; k < 400; ++k) {
        const glm::dvec3 target =
            bernstein(pole.points, 0.05 + 0.9 * (k % 20) / 20.0, 0.05 + 0.9 * (k / 20) / 20.0);
        const geo::Ray3 ray{target + glm::dvec3(0.1, 0.2, 4.0), {-0.1, -0.2, -4.0}};
        const auto hit = geo::intersect(pole, ray, 0.0, kInf);
        if (!hit) continue;
        ++hits;
        CHECK(std::fabs(glm::length(hit->normal) - 1.0) < 1e-14);
        CHECK(std::fabs(glm::length(hit->shading_normal) - 1.0) < 1e-14);
    }
    CHECK(hits > 300);
}

TEST_CASE("bicubic_patch: each ray's own subdivision gives the kept one's hits",
          "[geometry][bicubic_patch]") {
    geo::BicubicPatchGeometry lazy = patch_of(wavy, 0.004, 5, 4);
    lazy.measure =
        glm::dmat3(glm::dvec3(1.0, 0.2, 0.0), glm::dvec3(0.0, 0.8, 0.0), glm::dvec3(0.1, 0.0, 2.0));
    geo::BicubicPatchGeometry kept = lazy;
    geo::keep_subdivision(kept);
    REQUIRE(kept.tree);
    CHECK(kept.tree->pieces.size() == piece_count(lazy));
    std::uint64_t state = 7;
    const auto next = [&]() {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return double(state >> 11) / double(1ULL << 53);
    };
    int hits = 0;
    for (int k = 0; k < 2000; ++k) {
        const glm::dvec3 origin(2.0 * next() - 0.5, 2.0 * next() - 0.5, 3.0 * next() - 1.5);
        const glm::dvec3 to(next(), next(), 0.6 * next() - 0.3);
        const geo::Ray3 ray{origin, to - origin};
        const auto a = geo::intersect(lazy, ray, 0.0, kInf);
        const auto b = geo::intersect(kept, ray, 0.0, kInf);
        REQUIRE(a.has_value() == b.has_value());
        if (!a) continue;
        ++hits;
        CHECK(a->s == b->s);
        CHECK(a->shading_normal == b->shading_normal);
        CHECK(a->uv == b->uv);
        // The surface meets a small box around the hit.
        const geo::Box3 around{a->point - 1e-9, a->point + 1e-9};
        CHECK(geo::surface_may_meet(lazy, around));
        CHECK(geo::surface_may_meet(kept, around));
    }
    CHECK(hits > 500);
    // Far from it, no.
    CHECK_FALSE(geo::surface_may_meet(kept, {glm::dvec3(5.0), glm::dvec3(6.0)}));
    const geo::Box3 box = geo::object_bounds(kept);
    CHECK(box.lo.x == 0.0);
    CHECK(box.hi.y == 1.0);
}

TEST_CASE("bicubic_patch: extreme rays and points give no NaN or Inf",
          "[geometry][bicubic_patch]") {
    for (const double size : {1e-150, 1.0, 1e150, 1e300}) {
        geo::BicubicPatchGeometry g = patch_of(wavy, 0.01, 3, 3);
        for (auto& p : g.points) p *= size;
        geo::keep_subdivision(g);
        for (int k = 0; k < 200; ++k) {
            const double a = 0.37 * k, b = 0.11 * k;
            const glm::dvec3 d(std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b));
            for (const double far : {1.0, 1e10, 1e300}) {
                const geo::Ray3 ray{glm::dvec3(0.5 * size) - far * size * d, d * far};
                const auto hit = geo::intersect(g, ray, 0.0, kInf);
                if (!hit) continue;
                CHECK(std::isfinite(hit->s));
                CHECK(geo::is_finite(hit->point));
                CHECK(geo::is_finite(hit->normal));
                CHECK(geo::is_finite(hit->shading_normal));
            }
        }
    }
}
