// Static ray/text geometry (POV-Ray's text object in text space): caps and
// walls of hand-made outlines (always run), holes by the even-odd rule,
// outward normals whatever the contour direction, thickness <= 0 as POV-Ray
// (caps only), rays aimed at sampled surface points; then, with POV-Ray's
// fonts (HEXANT_POV_FONT_DIR, else skipped), caps against FreeType's own
// rasterizer, wall hits on FreeType's outline with normals across it, and
// bounds and may-meet around hit points.
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <chrono>
#include <cstring>
#include <filesystem>
#include <vector>

#include "geometry_test_support.hpp"
#include "runtime/geometry/box_queries.hpp"
#include "runtime/objects/text/text_geometry.hpp"
#include "runtime/objects/text/true_type_font.hpp"

using namespace geometry_test;
using hexant::runtime::geometry::make_text_glyph;
using hexant::runtime::geometry::TextGeometry;
using hexant::runtime::geometry::TextGlyph;
using hexant::runtime::geometry::TextSegment;
namespace objects = hexant::runtime::objects;

namespace {

using Contour = std::vector<TextSegment>;

TextSegment line(glm::dvec2 a, glm::dvec2 b) {
    return {a, 0.5 * (a + b), b, false};
}
TextSegment quad(glm::dvec2 a, glm::dvec2 c, glm::dvec2 b) {
    return {a, c, b, true};
}

glm::dvec2 bezier(const TextSegment& s, double t) {
    if (!s.quadratic) return s.p0 + t * (s.p2 - s.p0);
    const double u = 1.0 - t;
    return u * u * s.p0 + 2.0 * t * u * s.control + t * t * s.p2;
}
glm::dvec2 bezier_tangent(const TextSegment& s, double t) {
    if (!s.quadratic) return s.p2 - s.p0;
    return 2.0 * ((1.0 - t) * (s.control - s.p0) + t * (s.p2 - s.control));
}

// Distance from p to a segment and the parameter of the nearest point:
// dense sampling, then Newton on the squared distance (long double).
double distance_to_segment(const TextSegment& s, glm::dvec2 p, double* at = nullptr) {
    double best_t = 0.0, best = kInf;
    const int n = s.quadratic ? 400 : 1;
    for (int i = 0; i <= n; ++i) {
        const double t = double(i) / n;
        const double d = glm::length(bezier(s, t) - p);
        if (d < best) best = d, best_t = t;
    }
    if (!s.quadratic) {
        const glm::dvec2 e = s.p2 - s.p0;
        const double ee = glm::dot(e, e);
        best_t = ee > 0.0 ? std::clamp(glm::dot(p - s.p0, e) / ee, 0.0, 1.0) : 0.0;
    } else {
        for (int k = 0; k < 30; ++k) {
            const glm::dvec2 r = bezier(s, best_t) - p, d1 = bezier_tangent(s, best_t);
            const glm::dvec2 d2 = 2.0 * (s.p0 - 2.0 * s.control + s.p2);
            const double g = glm::dot(r, d1), h = glm::dot(d1, d1) + glm::dot(r, d2);
            if (!(h > 0.0)) break;
            best_t = std::clamp(best_t - g / h, 0.0, 1.0);
        }
    }
    const glm::dvec2 q = bezier(s, best_t);
    const long double dx = (long double)q.x - p.x, dy = (long double)q.y - p.y;
    if (at) *at = best_t;
    return static_cast<double>(std::sqrt(dx * dx + dy * dy));
}

// Independent even-odd test: crossings of a ray toward +x with a dense
// polyline of every segment.
bool inside_by_polyline(const std::vector<Contour>& contours, glm::dvec2 p, int pieces = 2000) {
    bool odd = false;
    for (const auto& contour : contours) {
        for (const TextSegment& s : contour) {
            const int n = s.quadratic ? pieces : 1;
            for (int i = 0; i < n; ++i) {
                const glm::dvec2 a = bezier(s, double(i) / n), b = bezier(s, double(i + 1) / n);
                if ((a.y > p.y) == (b.y > p.y)) continue;
                const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
                if (x > p.x) odd = !odd;
            }
        }
    }
    return odd;
}

// A unit square with a square hole, and a "D": a line up and a quadratic back.
std::vector<Contour> hand_made_contours(bool reverse_square) {
    Contour square = {line({0, 0}, {1, 0}), line({1, 0}, {1, 1}), line({1, 1}, {0, 1}),
                      line({0, 1}, {0, 0})};
    if (reverse_square) {
        Contour r;
        for (auto it = square.rbegin(); it != square.rend(); ++it)
            r.push_back(line(it->p2, it->p0));
        square = r;
    }
    const Contour hole = {line({0.25, 0.25}, {0.25, 0.75}), line({0.25, 0.75}, {0.75, 0.75}),
                          line({0.75, 0.75}, {0.75, 0.25}), line({0.75, 0.25}, {0.25, 0.25})};
    const Contour d = {line({2, 0}, {2, 1}), quad({2, 1}, {3.5, 0.5}, {2, 0})};
    return {square, hole, d};
}

TextGeometry hand_made(double thickness, bool reverse_square = false) {
    TextGeometry g;
    g.thickness = thickness;
    g.glyphs.push_back(make_text_glyph(hand_made_contours(reverse_square)));
    return g;
}

struct HandCase {
    std::vector<Contour> contours;
    TextGeometry g;
    double scale;
    glm::dvec2 shift;

    double residual(const glm::dvec3& p) const {
        double d = kInf;
        const double th = g.thickness;
        const double z_out = std::max({-p.z, p.z - th, 0.0});
        for (const auto& c : contours) {
            for (const auto& s : c) {
                const double e = distance_to_segment(s, {p.x, p.y});
                d = std::min(d, std::sqrt(e * e + z_out * z_out));
            }
        }
        if (inside_by_polyline(contours, {p.x, p.y})) {
            d = std::min({d, std::fabs(p.z), std::fabs(p.z - th)});
        }
        return d;
    }

    double edge_distance(glm::dvec2 q) const {
        double d = kInf;
        for (const auto& c : contours)
            for (const auto& s : c) d = std::min(d, distance_to_segment(s, q));
        return d;
    }

    SurfaceSample sample(Random& random) const {
        const double th = g.thickness;
        if (random.uniform() < 0.4) {
            for (;;) {
                const glm::dvec2 q =
                    shift + scale * glm::dvec2(random.uniform(0.0, 2.75), random.uniform(0.0, 1.0));
                if (!inside_by_polyline(contours, q)) continue;
                const double edge = edge_distance(q);
                if (edge < 1e-4 * scale) continue;
                const bool top = random.uniform() < 0.5;
                SurfaceSample s{{q.x, q.y, top ? th : 0.0}, {0.0, 0.0, top ? 1.0 : -1.0}};
                s.edge_distance = edge;
                return s;
            }
        }
        const auto& c = contours[random.integer(0, (int)contours.size() - 1)];
        const TextSegment& s = c[random.integer(0, (int)c.size() - 1)];
        const double t = random.uniform(1e-3, 1.0 - 1e-3);
        const glm::dvec2 q = bezier(s, t), tangent = bezier_tangent(s, t);
        glm::dvec2 right{tangent.y, -tangent.x};
        right /= glm::length(right);
        const bool right_inside = inside_by_polyline(contours, q + 1e-6 * scale * right);
        const glm::dvec2 out = right_inside ? -right : right;
        const double z = th * random.uniform(1e-3, 1.0 - 1e-3);
        SurfaceSample sample{{q.x, q.y, z}, {out.x, out.y, 0.0}};
        const double len = glm::length(s.p2 - s.p0);
        sample.edge_distance = std::min({t * len, (1.0 - t) * len, z, th - z});
        // The curve's radius of curvature (a line: none).
        if (s.quadratic) {
            const glm::dvec2 d1 = bezier_tangent(s, t), d2 = 2.0 * (s.p0 - 2.0 * s.control + s.p2);
            const double cross = std::fabs(d1.x * d2.y - d1.y * d2.x);
            sample.curvature_radius = std::pow(glm::length(d1), 3) / cross;
        }
        return sample;
    }
};

HandCase make_hand_case(double scale, glm::dvec2 shift, double thickness) {
    HandCase c;
    c.scale = scale;
    c.shift = shift;
    c.contours = hand_made_contours(false);
    for (auto& contour : c.contours) {
        for (auto& s : contour) {
            s.p0 = shift + scale * s.p0;
            s.control = shift + scale * s.control;
            s.p2 = shift + scale * s.p2;
        }
    }
    c.g.thickness = thickness * scale;
    c.g.glyphs.push_back(make_text_glyph(c.contours));
    return c;
}

std::filesystem::path font_dir() {
    if (const char* env = std::getenv("HEXANT_POV_FONT_DIR")) return env;
#ifdef HEXANT_POV_FONT_DIR
    return HEXANT_POV_FONT_DIR;
#else
    return "/usr/share/povray-3.7/include";
#endif
}

}  // namespace

TEST_CASE("text geometry: hand-made square with a hole and a quadratic", "[runtime][geometry]") {
    const TextGeometry g = hand_made(0.5);
    // Straight down +z onto the square's cap at z = 0.
    auto hit = intersect(g, Ray3{{0.1, 0.2, -5.0}, {0.0, 0.0, 1.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 5.0);
    CHECK(hit->part == 0);
    CHECK(hit->normal == glm::dvec3(0.0, 0.0, -1.0));
    CHECK(hit->point == glm::dvec3(0.1, 0.2, 0.0));
    CHECK(hit->uv == glm::dvec2(0.1, 0.2));
    // Down the hole: nothing.
    CHECK_FALSE(intersect(g, Ray3{{0.5, 0.5, -5.0}, {0.0, 0.0, 1.0}}, -kInf, kInf));
    // From inside the solid, up to the back cap.
    hit = intersect(g, Ray3{{0.1, 0.1, 0.25}, {0.0, 0.0, 2.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->part == 1);
    CHECK(hit->s == 0.125);
    CHECK(hit->normal == glm::dvec3(0.0, 0.0, 1.0));
    CHECK(hit->point.z == 0.5);
    // The square's outer wall from -x, the hole's wall facing into the hole.
    hit = intersect(g, Ray3{{-1.0, 0.5, 0.25}, {1.0, 0.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 1.0);
    CHECK(hit->part == 2);
    CHECK(hit->normal == glm::dvec3(-1.0, 0.0, 0.0));
    hit = intersect(g, Ray3{{0.5, 0.5, 0.25}, {1.0, 0.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 0.25);
    CHECK(hit->normal == glm::dvec3(-1.0, 0.0, 0.0));  // out of the solid, into the hole
    // The quadratic wall from +x: B(1/2) = (2.75, 0.5), tangent (0, -1).
    hit = intersect(g, Ray3{{5.0, 0.5, 0.1}, {-1.0, 0.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == Approx(2.25).epsilon(1e-14));
    CHECK(hit->point.x == Approx(2.75).epsilon(1e-15));
    CHECK(hit->point.y == Approx(0.5).epsilon(1e-15));
    CHECK(hit->normal.x == Approx(1.0));
    CHECK(std::fabs(hit->normal.y) < 1e-15);
    // The D's straight wall seen from inside the D faces -x.
    hit = intersect(g, Ray3{{2.5, 0.5, 0.1}, {-1.0, 0.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->point.x == 2.0);
    CHECK(hit->normal == glm::dvec3(-1.0, 0.0, 0.0));
    // Above the top cap: a ray along x misses.
    CHECK_FALSE(intersect(g, Ray3{{-1.0, 0.5, 0.6}, {1.0, 0.0, 0.0}}, -kInf, kInf));
    // inside()
    CHECK(inside(g, {0.1, 0.1, 0.25}));
    CHECK_FALSE(inside(g, {0.5, 0.5, 0.25}));
    CHECK(inside(g, {2.7, 0.5, 0.0}));
    CHECK_FALSE(inside(g, {2.8, 0.5, 0.25}));
    CHECK_FALSE(inside(g, {0.1, 0.1, 0.6}));
    CHECK_FALSE(inside(g, {0.1, 0.1, -0.1}));
    // Bounds: the control points' box and [0, thickness].
    const Box3 b = object_bounds(g);
    CHECK(b.lo == glm::dvec3(0.0, 0.0, 0.0));
    CHECK(b.hi == glm::dvec3(3.5, 1.0, 0.5));
    CHECK(surface_may_meet(g, Box3{{0.4, 0.1, -1.0}, {0.45, 0.15, 1.0}}));
    CHECK_FALSE(surface_may_meet(g, Box3{{0.4, 0.4, 0.1}, {0.6, 0.6, 0.4}}));    // in the hole
    CHECK_FALSE(surface_may_meet(g, Box3{{0.05, 0.05, 0.1}, {0.2, 0.2, 0.4}}));  // inside the solid
    CHECK(surface_may_meet(g, Box3{{0.05, 0.05, 0.1}, {0.2, 0.2, 0.5}}));        // reaches the cap
    CHECK_FALSE(surface_may_meet(g, Box3{{3.0, 0.9, 0.0}, {3.4, 1.0, 0.5}}));    // beside the curve
}

TEST_CASE("text geometry: contour direction, thickness <= 0, empty text", "[runtime][geometry]") {
    // A clockwise outer square: the normals are still outward.
    const TextGeometry cw = hand_made(1.0, true);
    auto hit = intersect(cw, Ray3{{-1.0, 0.1, 0.5}, {1.0, 0.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->normal == glm::dvec3(-1.0, 0.0, 0.0));
    hit = intersect(cw, Ray3{{0.1, 2.0, 0.5}, {0.0, -1.0, 0.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->normal == glm::dvec3(0.0, 1.0, 0.0));

    // Zero thickness: a flat text, seen from both sides (POV-Ray renders it).
    const TextGeometry flat = hand_made(0.0);
    hit = intersect(flat, Ray3{{0.1, 0.1, 3.0}, {0.0, 0.0, -1.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 3.0);
    CHECK(hit->point.z == 0.0);
    CHECK_FALSE(intersect(flat, Ray3{{-1.0, 0.1, 0.0}, {1.0, 0.0, 0.0}}, -kInf, kInf));
    CHECK(inside(flat, {0.1, 0.1, 0.0}));
    CHECK_FALSE(inside(flat, {0.1, 0.1, 1e-300}));

    // Negative thickness: caps at z = 0 (normal -z) and z = -1 (normal +z), no walls.
    const TextGeometry negative = hand_made(-1.0);
    hit = intersect(negative, Ray3{{0.1, 0.1, -3.0}, {0.0, 0.0, 1.0}}, 0.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 2.0);
    CHECK(hit->part == 1);
    CHECK(hit->normal == glm::dvec3(0.0, 0.0, 1.0));
    hit = intersect(negative, Ray3{{0.1, 0.1, -3.0}, {0.0, 0.0, 1.0}}, 2.0, kInf);
    REQUIRE(hit);
    CHECK(hit->s == 3.0);
    CHECK(hit->part == 0);
    CHECK_FALSE(intersect(negative, Ray3{{-1.0, 0.1, -0.5}, {1.0, 0.0, 0.0}}, -kInf, kInf));
    CHECK_FALSE(inside(negative, {0.1, 0.1, -0.5}));
    CHECK(object_bounds(negative).lo.z == -1.0);
    CHECK(object_bounds(negative).hi.z == 0.0);
    CHECK_FALSE(surface_may_meet(negative, Box3{{-1.0, -1.0, -0.75}, {4.0, 2.0, -0.25}}));

    // Empty: no glyphs, or glyphs without segments (spaces).
    TextGeometry empty;
    empty.glyphs.push_back(make_text_glyph({}));
    CHECK_FALSE(intersect(empty, Ray3{{0.0, 0.0, -1.0}, {0.0, 0.0, 1.0}}, -kInf, kInf));
    CHECK_FALSE(inside(empty, {0.0, 0.0, 0.5}));
    CHECK(object_bounds(empty).is_nowhere());
    CHECK_FALSE(surface_may_meet(empty, Box3{{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}}));
    TextGeometry nan_thickness = hand_made(std::nan(""));
    CHECK_FALSE(intersect(nan_thickness, Ray3{{0.1, 0.1, -1.0}, {0.0, 0.0, 1.0}}, -kInf, kInf));
}

TEST_CASE("text geometry: quadratic split at its extreme in y, inside vs polyline",
          "[runtime][geometry]") {
    // A glyph whose quadratic bulges beyond its ends in y.
    const std::vector<Contour> contours = {{line({0, 0}, {2, 0}), quad({2, 0}, {1, 3}, {0, 0})}};
    const TextGlyph glyph = make_text_glyph(contours);
    REQUIRE(glyph.segments.size() == 3);  // the line and the quadratic's two halves
    for (const TextSegment& s : glyph.segments) {
        if (!s.quadratic) continue;
        const double lo = std::min(s.p0.y, s.p2.y), hi = std::max(s.p0.y, s.p2.y);
        CHECK(s.control.y >= lo);
        CHECK(s.control.y <= hi);
    }
    CHECK(glyph.hi.y == 1.5);  // the split point, the curve's top
    Random random(7);
    for (int i = 0; i < 4000; ++i) {
        const glm::dvec2 p{random.uniform(-0.2, 2.2), random.uniform(-0.2, 1.7)};
        INFO(p.x << " " << p.y);
        CHECK(inside_outline(glyph, p) == inside_by_polyline(contours, p));
    }
}

TEST_CASE("text geometry: aimed rays at every scale, random rays, may-meet",
          "[runtime][geometry]") {
    struct Scale {
        const char* name;
        double scale;
        glm::dvec2 shift;
    };
    const Scale scales[] = {{"text unit", 1.0, {0.0, 0.0}},
                            {"text small far", 1e-4, {3e2, -1e2}},
                            {"text large", 1e4, {-2e4, 5e3}}};
    Random random(1234);
    for (const Scale& sc : scales) {
        const HandCase c = make_hand_case(sc.scale, sc.shift, 0.5);
        for (const double distance : {0.5, 1e3, 1e6}) {
            const AimStats stats = aim_at_surface(
                c.g, [&](Random& r) { return c.sample(r); },
                [&](const glm::dvec3& p) { return c.residual(p); }, 3.0 * sc.scale,
                distance * sc.scale, false, 300, random);
            report(sc.name, stats);
            CHECK(stats.grazing_misses <= stats.rays / 50);
            CHECK(stats.max_residual < 64.0 * kEps);
            CHECK(stats.max_point_mismatch < 64.0 * kEps);
        }
        const glm::dvec3 mid(sc.shift.x + 1.5 * sc.scale, sc.shift.y + 0.5 * sc.scale,
                             0.25 * sc.scale);
        CHECK(random_rays_are_finite(c.g, 3.0 * sc.scale, mid, 2000, random) > 20);
        boxes_around_surface(
            c.g, [&](Random& r) { return c.sample(r); }, 3.0 * sc.scale, 400, random);
    }
}

// ---------------------------------------------------------------- fonts

namespace {

struct FreeTypeReference {
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    explicit FreeTypeReference(const std::filesystem::path& path) {
        REQUIRE(FT_Init_FreeType(&library) == 0);
        REQUIRE(FT_New_Face(library, path.c_str(), 0, &face) == 0);
    }
    ~FreeTypeReference() {
        FT_Done_Face(face);
        FT_Done_FreeType(library);
    }
};

// The TrueType outline as FreeType loads it (points and on-curve tags, font
// units), turned into segments by the format's rule, written here
// independently of the code under test: between two off-curve points lies
// an implied on-curve point at their midpoint. (Not FT_Outline_Decompose:
// it rounds those midpoints to whole font units.) Em units, moved by place.
std::vector<TextSegment> freetype_segments(FT_Face face, unsigned glyph_index, glm::dvec2 place) {
    REQUIRE(FT_Load_Glyph(face, glyph_index, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) == 0);
    const FT_Outline& o = face->glyph->outline;
    const double upem = face->units_per_EM;
    std::vector<TextSegment> out;
    int first = 0;
    for (int c = 0; c < o.n_contours; ++c) {
        const int last = o.contours[c], n = last - first + 1;
        auto pt = [&](int i) {
            const FT_Vector v = o.points[first + (i % n + n) % n];
            return glm::dvec2(v.x, v.y);
        };
        auto on = [&](int i) { return (o.tags[first + (i % n + n) % n] & 1) != 0; };
        // Start at an on-curve point (these fonts' contours have one).
        int start = 0;
        while (start < n && !on(start)) ++start;
        REQUIRE(start < n);
        glm::dvec2 at = pt(start);
        for (int k = 1; k <= n; ++k) {
            const int i = start + k;
            if (on(i)) {
                out.push_back(line(place + at / upem, place + pt(i) / upem));
                at = pt(i);
                continue;
            }
            const glm::dvec2 end = on(i + 1) ? pt(i + 1) : 0.5 * (pt(i) + pt(i + 1));
            out.push_back(quad(place + at / upem, place + pt(i) / upem, place + end / upem));
            at = end;
            if (on(i + 1)) ++k;
        }
        first = last + 1;
    }
    return out;
}

// FreeType's anti-aliased rasterizer at 1 pixel per font unit, even-odd
// fill: coverage 255 means the pixel square lies inside, 0 outside.
struct Coverage {
    int width = 0, rows = 0;
    long x0 = 0, y0 = 0;  // font units of the bitmap's lower left corner
    std::vector<unsigned char> gray;
    // -1 unknown (partly covered or outside the bitmap), 0 out, 1 in.
    int at(double fx, double fy) const {
        const long col = (long)std::floor(fx) - x0, row_from_bottom = (long)std::floor(fy) - y0;
        if (col < 0 || col >= width || row_from_bottom < 0 || row_from_bottom >= rows) return 0;
        const unsigned char v = gray[(rows - 1 - row_from_bottom) * width + col];
        return v == 255 ? 1 : v == 0 ? 0 : -1;
    }
};

Coverage rasterize(FT_Library library, FT_Face face, unsigned glyph_index) {
    REQUIRE(FT_Load_Glyph(face, glyph_index, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) == 0);
    FT_Outline outline;
    REQUIRE(FT_Outline_New(library, face->glyph->outline.n_points, face->glyph->outline.n_contours,
                           &outline) == 0);
    REQUIRE(FT_Outline_Copy(&face->glyph->outline, &outline) == 0);
    FT_BBox box;
    FT_Outline_Get_CBox(&outline, &box);
    Coverage c;
    c.x0 = box.xMin - 2;
    c.y0 = box.yMin - 2;
    c.width = int(box.xMax - box.xMin) + 4;
    c.rows = int(box.yMax - box.yMin) + 4;
    // Font units to 26.6 pixels (1 unit = 1 pixel), moved to the bitmap.
    for (int i = 0; i < outline.n_points; ++i) {
        outline.points[i].x = (outline.points[i].x - c.x0) * 64;
        outline.points[i].y = (outline.points[i].y - c.y0) * 64;
    }
    outline.flags |= FT_OUTLINE_EVEN_ODD_FILL;
    c.gray.assign(std::size_t(c.width) * c.rows, 0);
    FT_Bitmap bitmap{};
    bitmap.width = c.width;
    bitmap.rows = c.rows;
    bitmap.pitch = c.width;
    bitmap.buffer = c.gray.data();
    bitmap.num_grays = 256;
    bitmap.pixel_mode = FT_PIXEL_MODE_GRAY;
    REQUIRE(FT_Outline_Get_Bitmap(library, &outline, &bitmap) == 0);
    FT_Outline_Done(library, &outline);
    return c;
}

}  // namespace

TEST_CASE("text geometry: glyphs of POV-Ray's fonts against FreeType",
          "[runtime][geometry][font]") {
    const std::filesystem::path dir = font_dir();
    if (!std::filesystem::exists(dir / "timrom.ttf")) {
        // Catch2 v2 has no SKIP: the project's way (tests/app/full_disk_test.cpp).
        WARN("not run: POV-Ray's fonts not found in "
             << dir.string() << " (set HEXANT_POV_FONT_DIR; Debian: povray-includes)");
        return;
    }
    for (const char* name : {"timrom.ttf", "cyrvetic.ttf", "crystal.ttf"}) {
        INFO(name);
        const auto font = objects::TrueTypeFont::load(dir / name);
        FreeTypeReference ft(dir / name);
        const double upem = font->units_per_em();
        const TextGeometry text = objects::lay_out_text(*font, std::string("B&g8%@Qe"), 0.4, {});
        Random random(99);
        int cap_checks = 0, wall_checks = 0, normal_checks = 0;
        for (const TextGlyph& glyph : text.glyphs) {
            if (glyph.segments.empty()) continue;
            INFO("glyph " << glyph.glyph_index << " code " << glyph.code);
            const Coverage cov = rasterize(ft.library, ft.face, glyph.glyph_index);
            // Caps: rays straight down +z at random points of the glyph's box.
            for (int i = 0; i < 3000; ++i) {
                const glm::dvec2 q{random.uniform(glyph.lo.x, glyph.hi.x),
                                   random.uniform(glyph.lo.y, glyph.hi.y)};
                const glm::dvec2 f = (q - glyph.translation) * upem;  // font units
                const int expected = cov.at(f.x, f.y);
                if (expected < 0) continue;
                const auto hit =
                    intersect(text, Ray3{{q.x, q.y, -2.0}, {0.0, 0.0, 1.0}}, 0.0, kInf);
                // Another glyph may overlap this one's box.
                bool other = false;
                for (const TextGlyph& g2 : text.glyphs)
                    if (&g2 != &glyph && inside_outline(g2, q)) other = true;
                if (other) continue;
                ++cap_checks;
                INFO("point " << q.x << " " << q.y << " font units " << f.x << " " << f.y);
                REQUIRE(bool(hit) == (expected == 1));
                if (hit) {
                    CHECK(hit->part == 0);
                    CHECK(hit->s == 2.0);
                    CHECK(hit->point == glm::dvec3(q, 0.0));
                }
            }
            // Walls: horizontal rays from outside the box at random heights and
            // directions in the plane; each wall hit on FreeType's outline.
            for (int i = 0; i < 600; ++i) {
                const double angle = random.uniform(0.0, 2.0 * kPi);
                const glm::dvec2 heading(std::cos(angle), std::sin(angle));
                const glm::dvec2 target{random.uniform(glyph.lo.x, glyph.hi.x),
                                        random.uniform(glyph.lo.y, glyph.hi.y)};
                const glm::dvec2 from = target - 2.0 * heading;
                const double z = random.uniform(0.01, 0.39);
                const auto hit = intersect(text, Ray3{{from, z}, {heading, 0.0}}, 0.0, kInf);
                if (!hit) continue;
                REQUIRE(well_formed(*hit));
                REQUIRE(hit->part == 2);
                const glm::dvec2 p(hit->point.x, hit->point.y);
                CHECK(hit->point.z == Approx(z).margin(1e-15));
                // The glyph and FreeType segment nearest the hit.
                double best = kInf, best_t = 0.0;
                TextSegment nearest;
                const TextGlyph* owner = nullptr;
                for (const TextGlyph& g2 : text.glyphs) {
                    if (g2.segments.empty() || p.x < g2.lo.x - 1e-9 || p.x > g2.hi.x + 1e-9 ||
                        p.y < g2.lo.y - 1e-9 || p.y > g2.hi.y + 1e-9)
                        continue;
                    for (const TextSegment& s :
                         freetype_segments(ft.face, g2.glyph_index, g2.translation)) {
                        double t;
                        const double d = distance_to_segment(s, p, &t);
                        if (d < best) best = d, best_t = t, nearest = s, owner = &g2;
                    }
                }
                REQUIRE(owner != nullptr);
                ++wall_checks;
                INFO("wall hit " << p.x << " " << p.y << " distance " << best << " t " << best_t);
                CHECK(best < 1e-12);
                const glm::dvec2 tangent = glm::normalize(bezier_tangent(nearest, best_t));
                if (best_t > 1e-6 && best_t < 1.0 - 1e-6) {
                    CHECK(std::fabs(glm::dot(tangent, glm::dvec2(hit->normal))) < 1e-9);
                }
                // Outward: just beyond the hit along the normal the point is
                // outside the owner glyph's reference outline, just before it
                // inside (an even-odd count over a fine polyline of FreeType's
                // points), away from the segments' ends.
                if (best_t > 1e-3 && best_t < 1.0 - 1e-3) {
                    const std::vector<Contour> ref = {
                        freetype_segments(ft.face, owner->glyph_index, owner->translation)};
                    const glm::dvec2 n(hit->normal.x, hit->normal.y);
                    ++normal_checks;
                    // 400 pieces: a chord's sag < 2e-6 em for these curves.
                    CHECK_FALSE(inside_by_polyline(ref, p + 1e-5 * n, 400));
                    CHECK(inside_by_polyline(ref, p - 1e-5 * n, 400));
                }
            }
        }
        INFO("checks " << cap_checks << " " << wall_checks << " " << normal_checks);
        CHECK(cap_checks > 5000);
        CHECK(wall_checks > 1000);
        CHECK(normal_checks > 200);
    }
}

TEST_CASE("text geometry: a 20-glyph string, bounds, may-meet, speed",
          "[runtime][geometry][font]") {
    const std::filesystem::path dir = font_dir();
    if (!std::filesystem::exists(dir / "timrom.ttf")) {
        WARN("not run: POV-Ray's fonts not found in " << dir.string()
                                                      << " (set HEXANT_POV_FONT_DIR)");
        return;
    }
    const auto font = objects::TrueTypeFont::load(dir / "timrom.ttf");
    const TextGeometry text =
        objects::lay_out_text(*font, std::string("Hexant reads POV-Ray"), 0.25, {});
    REQUIRE(text.glyphs.size() == 20);
    const Box3 bounds = object_bounds(text);
    const glm::dvec3 mid = centre(bounds);
    Random random(5);
    int hits = 0;
    const auto start = std::chrono::steady_clock::now();
    const int rays = 20000;
    for (int i = 0; i < rays; ++i) {
        const glm::dvec3 target{random.uniform(bounds.lo.x, bounds.hi.x),
                                random.uniform(bounds.lo.y, bounds.hi.y),
                                random.uniform(bounds.lo.z, bounds.hi.z)};
        const glm::dvec3 from = target + 10.0 * random.unit_vector();
        const auto hit = intersect(text, Ray3{from, target - from}, 0.0, kInf);
        if (!hit) continue;
        ++hits;
        REQUIRE(well_formed(*hit));
        INFO("hit " << hit->point.x << " " << hit->point.y << " " << hit->point.z);
        REQUIRE(contains(bounds, hit->point));
        REQUIRE(surface_may_meet(text, Box3{hit->point, hit->point}));
        // Just in front of the hit the ray is outside, just behind inside
        // (for hits not at a glyph's edge).
        const glm::dvec3 d = glm::normalize(target - from);
        if (std::fabs(glm::dot(d, hit->normal)) > 0.2) {
            const glm::dvec3 before = hit->point + 1e-7 * hit->normal;
            CHECK_FALSE(inside(text, before));
        }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (std::getenv("HEXANT_GEOMETRY_REPORT")) {
        std::printf("text 20 glyphs: %d rays, %d hits, %.2f us per ray\n", rays, hits,
                    1e6 * seconds / rays);
    }
    CHECK(hits > rays / 10);
    CHECK(random_rays_are_finite(text, 5.0, mid, 3000, random) > 20);
}
