#include "runtime/objects/height_field/height_field_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/objects/box_hierarchy.hpp"
#include "runtime/objects/triangle/triangle_geometry.hpp"

namespace hexant::runtime::geometry {

namespace {

using objects::HeightFieldData;

// POV-Ray's HFIELD_OFFSET: the box's margin above and below the heights.
constexpr double kOffset = 0.001;

// A cell's triangle: its corners in POV-Ray's order and its upward normal
// in object space.
struct CellTriangle {
    glm::dvec3 p1, p2, p3;
    glm::dvec3 normal;
};

CellTriangle cell_triangle(const HeightFieldData& d, int x, int z, int which) {
    const double y1 = d.height(x, z), y2 = d.height(x + 1, z), y3 = d.height(x, z + 1),
                 y4 = d.height(x + 1, z + 1);
    CellTriangle t;
    glm::dvec3 n;
    if (which == 0) {
        t.p1 = d.vertex(x, z);
        t.p2 = d.vertex(x + 1, z);
        t.p3 = d.vertex(x, z + 1);
        n = {y1 - y2, 1.0, y1 - y3};  // grid units (exact: small integers)
    } else {
        t.p1 = d.vertex(x + 1, z + 1);
        t.p2 = d.vertex(x, z + 1);
        t.p3 = d.vertex(x + 1, z);
        n = {y3 - y4, 1.0, y2 - y4};
    }
    // A normal in grid units to object space: the scaling's inverse
    // transpose, diag(width - 1, 65536, depth - 1) (POV-Ray's MTransNormal).
    t.normal = glm::normalize(glm::dvec3(n.x * d.x_scale(), 65536.0, n.z * d.z_scale()));
    return t;
}

}  // namespace

double height_field_floor(const HeightFieldData& data, double water_level) {
    const double water = 65536.0 * water_level;
    return (std::max(static_cast<double>(data.min_height()), std::isnan(water) ? 0.0 : water) -
            kOffset) /
           65536.0;
}

glm::dvec3 height_field_smooth_normal(const HeightFieldData& d, const glm::dvec3& point,
                                      const glm::dmat3* normal_to_world) {
    const auto& normals = d.smooth_normals();
    const double gx = point.x * d.x_scale(), gz = point.z * d.z_scale();
    // (int) truncation, clamped to the last cell (HField::Normal).
    const int px = std::clamp(std::isfinite(gx) ? static_cast<int>(std::clamp(gx, -1.0, 1e9)) : 0,
                              0, d.width() - 2);
    const int pz = std::clamp(std::isfinite(gz) ? static_cast<int>(std::clamp(gz, -1.0, 1e9)) : 0,
                              0, d.depth() - 2);
    const double x = gx - px, z = gz - pz;
    const auto corner = [&](int cx, int cz) {
        const auto& s = normals[static_cast<std::size_t>(cz) * static_cast<std::size_t>(d.width()) +
                                static_cast<std::size_t>(cx)];
        const glm::dvec3 n(s[0] * d.x_scale(), s[1] * 65536.0, s[2] * d.z_scale());
        const double length = glm::length(normal_to_world ? *normal_to_world * n : n);
        return length > 0.0 && std::isfinite(length) ? n / length : glm::dvec3(0.0, 1.0, 0.0);
    };
    const glm::dvec3 n0 = corner(px, pz), n1 = corner(px + 1, pz), n2 = corner(px, pz + 1),
                     n3 = corner(px + 1, pz + 1);
    const double u = 1.0 - x, v = 1.0 - z;
    const glm::dvec3 r = v * (u * n0 + x * n1) + z * (u * n2 + x * n3);
    const double length = glm::length(r);
    if (!(length > 0.0) || !std::isfinite(length)) return glm::dvec3(0.0, 1.0, 0.0);
    return r / length;
}

std::optional<SurfaceHit> intersect(const HeightFieldGeometry& field, const Ray3& ray, double s_min,
                                    double s_max) {
    if (!field.data || !(s_min < s_max)) return std::nullopt;
    const HeightFieldData& d = *field.data;
    const auto& nodes = d.nodes();
    const glm::dvec3 inverse = 1.0 / ray.direction;
    // Cells wholly below the floor hold no surface.
    const double floor_height = field.floor * 65536.0;
    struct Pending {
        std::uint32_t node;
        double entry;
    };
    Pending stack[256];
    int top = 0;
    double entry = 0.0;
    if (d.max_height() < floor_height) return std::nullopt;
    if (!objects::ray_meets_box(d.node_box(nodes[0], field.floor), ray.origin, inverse, s_min,
                                s_max, entry))
        return std::nullopt;
    stack[top++] = {0, entry};
    struct Best {
        BarycentricHit hit;
        CellTriangle triangle;
        int part;
    };
    std::optional<Best> best;
    while (top > 0) {
        const Pending p = stack[--top];
        if (!(p.entry < s_max)) continue;
        const auto& node = nodes[p.node];
        if (node.count == 0) {
            for (auto z = node.z0; z < node.z1; ++z)
                for (auto x = node.x0; x < node.x1; ++x) {
                    const int cx = static_cast<int>(x), cz = static_cast<int>(z);
                    const double top_height =
                        std::max({d.height(cx, cz), d.height(cx + 1, cz), d.height(cx, cz + 1),
                                  d.height(cx + 1, cz + 1)});
                    if (top_height < floor_height) continue;
                    for (int which = 0; which < 2; ++which) {
                        const CellTriangle t = cell_triangle(d, cx, cz, which);
                        const auto hit = intersect_barycentric(t.p1, t.p2, t.p3, ray, s_min, s_max);
                        if (!hit) continue;
                        const double y = hit->b1 * t.p1.y + hit->b2 * t.p2.y + hit->b3 * t.p3.y;
                        if (y < field.floor) continue;
                        best = Best{*hit, t, which};
                        s_max = hit->s;
                    }
                }
            continue;
        }
        // Children nearer first: pushed farthest first.
        Pending children[4];
        int n = 0;
        for (std::uint32_t c = 0; c < node.count; ++c) {
            const auto& child = nodes[node.first + c];
            if (child.hi < floor_height) continue;
            double e = 0.0;
            if (objects::ray_meets_box(d.node_box(child, field.floor), ray.origin, inverse, s_min,
                                       s_max, e))
                children[n++] = {node.first + c, e};
        }
        // Farthest entry first, by insertion (at most four; the order
        // std::sort gave, which for so few is this same insertion sort,
        // without GCC 12's false -Warray-bounds about its unrolled one).
        for (int i = 1; i < n; ++i)
            for (int j = i; j > 0 && children[j].entry > children[j - 1].entry; --j)
                std::swap(children[j], children[j - 1]);
        for (int i = 0; i < n && top < 256; ++i) stack[top++] = children[i];
    }
    if (!best) return std::nullopt;
    const BarycentricHit& h = best->hit;
    const CellTriangle& t = best->triangle;
    SurfaceHit out;
    out.s = h.s;
    place_barycentric_hit(h, t.p1, t.p2, t.p3, ray, out);
    out.normal = t.normal;
    out.shading_normal = field.smooth ? height_field_smooth_normal(d, out.point) : t.normal;
    out.uv = {out.point.x, out.point.z};
    out.part = best->part;
    if (!is_finite(out)) return std::nullopt;
    return out;
}

bool inside(const HeightFieldGeometry& field, glm::dvec3 p) {
    if (!field.data) return false;
    const HeightFieldData& d = *field.data;
    // HField::Inside in grid units.
    const glm::dvec3 test(p.x * d.x_scale(), p.y * 65536.0, p.z * d.z_scale());
    const double water = field.floor * 65536.0;
    if (!(test.x >= 0.0) || test.x >= d.x_scale() || !(test.z >= 0.0) || test.z >= d.z_scale())
        return false;
    if (!(test.y < d.max_height() + kOffset)) return false;
    if (test.y < water) return true;
    int px = static_cast<int>(test.x), pz = static_cast<int>(test.z);
    const double x = test.x - px, z = test.z - pz;
    const auto h = [&](int cx, int cz) {
        return std::max(static_cast<double>(d.height(cx, cz)), water);
    };
    glm::dvec3 origin, normal;
    if (x + z < 1.0) {
        const double y1 = h(px, pz), y2 = h(px + 1, pz), y3 = h(px, pz + 1);
        origin = {px, y1, pz};
        normal = {y1 - y2, 1.0, y1 - y3};
    } else {
        px = static_cast<int>(std::ceil(test.x));
        pz = static_cast<int>(std::ceil(test.z));
        const double y1 = h(px, pz), y2 = h(px - 1, pz), y3 = h(px, pz - 1);
        origin = {px, y1, pz};
        normal = {y2 - y1, 1.0, y3 - y1};
    }
    return glm::dot(test, normal) < glm::dot(origin, normal);
}

Box3 object_bounds(const HeightFieldGeometry& field) {
    if (!field.data) return Box3::nowhere();
    const double top = (field.data->max_height() + kOffset) / 65536.0;
    return {{0.0, std::min(field.floor, top), 0.0}, {1.0, top, 1.0}};
}

bool surface_may_meet(const HeightFieldGeometry& field, const Box3& box) {
    if (!field.data) return false;
    const HeightFieldData& d = *field.data;
    const Box3 wide = widened(box, meet_slack(box, 1.0));
    const double floor_height = field.floor * 65536.0;
    bool met = false;
    d.descend([&](std::uint32_t i) {
        if (met) return false;
        const auto& node = d.nodes()[i];
        if (node.hi < floor_height) return false;
        if (!overlaps(d.node_box(node, field.floor), wide)) return false;
        if (node.count > 0) return true;
        for (auto z = node.z0; z < node.z1 && !met; ++z)
            for (auto x = node.x0; x < node.x1 && !met; ++x)
                for (int which = 0; which < 2 && !met; ++which) {
                    const CellTriangle t =
                        cell_triangle(d, static_cast<int>(x), static_cast<int>(z), which);
                    if (std::max({t.p1.y, t.p2.y, t.p3.y}) < field.floor) continue;
                    met = triangle_may_meet(t.p1, t.p2, t.p3, wide);
                }
        return false;
    });
    return met;
}

}  // namespace hexant::runtime::geometry
