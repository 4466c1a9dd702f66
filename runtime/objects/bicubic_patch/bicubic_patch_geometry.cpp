#include "runtime/objects/bicubic_patch/bicubic_patch_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "runtime/geometry/box_queries.hpp"
#include "runtime/geometry/stable_arithmetic.hpp"
#include "runtime/objects/box_hierarchy.hpp"
#include "runtime/objects/triangle/triangle_geometry.hpp"

namespace hexant::runtime::geometry {

namespace {

// POV-Ray's BEZIER_EPSILON, in its relative tests only (a cross product
// against its factors' lengths: a sine squared).
constexpr double kBezierEpsilon = 1e-10;

// (a + b) / 2 as POV-Ray's midpoint rounds it, without overflow; it lies
// between a and b in each coordinate (rounding is monotone).
glm::dvec3 midpoint(const glm::dvec3& a, const glm::dvec3& b) {
    return 0.5 * a + 0.5 * b;
}

// One cubic halved by de Casteljau's rule (a column of POV-Ray's
// bezier_split_left_right, in its order of midpoints).
void halve(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3,
           std::array<glm::dvec3, 4>& low, std::array<glm::dvec3, 4>& high) {
    const glm::dvec3 l1 = midpoint(p0, p1), half = midpoint(p1, p2), h2 = midpoint(p2, p3);
    const glm::dvec3 l2 = midpoint(l1, half), h1 = midpoint(half, h2);
    const glm::dvec3 m = midpoint(l2, h1);
    low = {p0, l1, l2, m};
    high = {m, h1, h2, p3};
}

struct SubPatch {
    BicubicNet net;
    double u0, u1, v0, v1;
};

// Halved along u, the first index (bezier_split_left_right).
void split_u(const SubPatch& p, SubPatch& low, SubPatch& high) {
    for (int j = 0; j < 4; ++j) {
        std::array<glm::dvec3, 4> a, b;
        halve(p.net[j], p.net[4 + j], p.net[8 + j], p.net[12 + j], a, b);
        for (int i = 0; i < 4; ++i) {
            low.net[4 * i + j] = a[i];
            high.net[4 * i + j] = b[i];
        }
    }
    const double mid = (p.u0 + p.u1) / 2.0;
    low.u0 = p.u0, low.u1 = mid, high.u0 = mid, high.u1 = p.u1;
    low.v0 = high.v0 = p.v0;
    low.v1 = high.v1 = p.v1;
}

// Halved along v, the second index (bezier_split_up_down).
void split_v(const SubPatch& p, SubPatch& low, SubPatch& high) {
    for (int i = 0; i < 4; ++i) {
        std::array<glm::dvec3, 4> a, b;
        halve(p.net[4 * i], p.net[4 * i + 1], p.net[4 * i + 2], p.net[4 * i + 3], a, b);
        for (int j = 0; j < 4; ++j) {
            low.net[4 * i + j] = a[j];
            high.net[4 * i + j] = b[j];
        }
    }
    const double mid = (p.v0 + p.v1) / 2.0;
    low.v0 = p.v0, low.v1 = mid, high.v0 = mid, high.v1 = p.v1;
    low.u0 = high.u0 = p.u0;
    low.u1 = high.u1 = p.u1;
}

bool flat_enough(const BicubicPatchGeometry& g, const BicubicNet& net) {
    const double distance = bicubic_flatness(g, net);
    return distance >= 0.0 && distance < g.flatness;
}

// The parts a sub-patch at `depth` halvings is cut into, or 0 when it is a
// piece (flat, or no steps left): bezier_subdivider's and
// bezier_tree_builder's choice, u and v together while both have steps.
int parts_of(const BicubicPatchGeometry& g, const SubPatch& p, int depth,
             std::array<SubPatch, 4>& out) {
    if (flat_enough(g, p.net)) return 0;
    const bool along_u = depth < g.u_steps, along_v = depth < g.v_steps;
    if (along_u && along_v) {
        SubPatch low, high;
        split_u(p, low, high);
        split_v(low, out[0], out[1]);
        split_v(high, out[2], out[3]);
        return 4;
    }
    if (along_u) {
        split_u(p, out[0], out[1]);
        return 2;
    }
    if (along_v) {
        split_v(p, out[0], out[1]);
        return 2;
    }
    return 0;
}

Box3 box_of(const BicubicNet& net) {
    Box3 box{net[0], net[0]};
    for (const glm::dvec3& p : net) {
        box.lo = glm::min(box.lo, p);
        box.hi = glm::max(box.hi, p);
    }
    return box;
}

BicubicPiece piece_of(const SubPatch& p) {
    return {{p.net[0], p.net[3], p.net[15], p.net[12]}, p.u0, p.u1, p.v0, p.v1};
}

// Each ray's own subdivision (POV-Ray's type 0): a part is cut only where
// enter(its box) says so.
template <class Enter, class Piece>
void walk_parts(const BicubicPatchGeometry& g, const SubPatch& p, int depth, Enter& enter,
                Piece& piece) {
    if (!enter(box_of(p.net))) return;
    std::array<SubPatch, 4> parts;
    const int n = parts_of(g, p, depth, parts);
    if (n == 0) {
        piece(piece_of(p));
        return;
    }
    for (int k = 0; k < n; ++k) walk_parts(g, parts[k], depth + 1, enter, piece);
}

// The pieces whose boxes, and their ancestors' boxes, enter() accepts.
template <class Enter, class Piece>
void walk(const BicubicPatchGeometry& g, Enter&& enter, Piece&& piece) {
    if (!g.tree) {
        walk_parts(g, SubPatch{g.points, 0.0, 1.0, 0.0, 1.0}, 0, enter, piece);
        return;
    }
    const BicubicTree& tree = *g.tree;
    // At most 3 siblings wait at each of the 17 levels.
    std::uint32_t stack[4 * (2 + 16)];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const BicubicTree::Node& node = tree.nodes[stack[--top]];
        if (!enter(node.box)) continue;
        if (node.count == 0) {
            piece(tree.pieces[node.first]);
            continue;
        }
        for (std::uint32_t k = 0; k < node.count; ++k) stack[top++] = node.first + k;
    }
}

bool build(const BicubicPatchGeometry& g, const SubPatch& p, int depth, BicubicTree& tree,
           std::size_t index) {
    tree.nodes[index].box = box_of(p.net);
    std::array<SubPatch, 4> parts;
    const int n = parts_of(g, p, depth, parts);
    if (n == 0) {
        if (tree.pieces.size() >= kMaxKeptBicubicPieces) return false;
        tree.nodes[index].first = static_cast<std::uint32_t>(tree.pieces.size());
        tree.nodes[index].count = 0;
        tree.pieces.push_back(piece_of(p));
        return true;
    }
    const std::size_t first = tree.nodes.size();
    tree.nodes.resize(first + static_cast<std::size_t>(n));
    tree.nodes[index].first = static_cast<std::uint32_t>(first);
    tree.nodes[index].count = static_cast<std::uint32_t>(n);
    for (int k = 0; k < n; ++k)
        if (!build(g, parts[k], depth + 1, tree, first + static_cast<std::size_t>(k))) return false;
    return true;
}

// The triangles of a piece (bezier_subpatch_intersect): corners and their
// (u, v).
constexpr int kTriangles[2][3] = {{0, 1, 2}, {0, 2, 3}};

std::array<glm::dvec2, 4> corner_uv(const BicubicPiece& p) {
    return {glm::dvec2(p.u0, p.v0), glm::dvec2(p.u0, p.v1), glm::dvec2(p.u1, p.v1),
            glm::dvec2(p.u1, p.v0)};
}

}  // namespace

void keep_subdivision(BicubicPatchGeometry& g) {
    auto tree = std::make_shared<BicubicTree>();
    tree->nodes.resize(1);
    if (build(g, SubPatch{g.points, 0.0, 1.0, 0.0, 1.0}, 0, *tree, 0))
        g.tree = std::move(tree);
    else
        g.tree = nullptr;
}

double bicubic_flatness(const BicubicPatchGeometry& g, const BicubicNet& net) {
    BicubicNet w;
    for (std::size_t k = 0; k < 16; ++k) w[k] = g.measure * net[k];
    // Three corners that span a plane: P[0][0], P[0][3], P[3][0], or, where
    // the first two coincide, P[0][0], P[3][3], P[3][0].
    const glm::dvec3 a = w[0], c = w[12];
    glm::dvec3 b = w[3];
    if (a == b) {
        b = w[15];
        if (b == a || b == c) return -1.0;
    } else if (b == c) {
        return -1.0;
    }
    // subpatch_normal(a, b, c): no plane where the edges are parallel.
    const glm::dvec3 e1 = a - b, e2 = c - b;
    glm::dvec3 n = glm::cross(e1, e2);
    const double n2 = glm::dot(n, n);
    if (!(n2 > kBezierEpsilon * glm::dot(e1, e1) * glm::dot(e2, e2))) return -1.0;
    n /= std::sqrt(n2);
    const double d = -glm::dot(n, a);
    const double length = glm::length(n);  // point_plane_distance's divisor
    double distance = 0.0;
    for (const glm::dvec3& p : w)
        distance = std::max(distance, std::fabs(glm::dot(p, n) + d) / length);
    return distance;
}

glm::dvec3 bicubic_normal(const BicubicPatchGeometry& g, double u, double v) {
    // bezier_value: the Bernstein weights and their derivatives.
    constexpr double binomial[4] = {1.0, 3.0, 3.0, 1.0};
    double up[4] = {1.0}, um[4] = {1.0}, vp[4] = {1.0}, vm[4] = {1.0};
    double dup[4] = {0.0}, dum[4] = {0.0}, dvp[4] = {0.0}, dvm[4] = {0.0};
    for (int i = 1; i < 4; ++i) {
        up[i] = up[i - 1] * u;
        um[i] = um[i - 1] * (1.0 - u);
        vp[i] = vp[i - 1] * v;
        vm[i] = vm[i - 1] * (1.0 - v);
        dup[i] = i * up[i - 1];
        dum[i] = -i * um[i - 1];
        dvp[i] = i * vp[i - 1];
        dvm[i] = -i * vm[i - 1];
    }
    glm::dvec3 pu(0.0), pv(0.0);
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            const double c = binomial[i] * binomial[j];
            const double ut = up[i] * um[3 - i], vt = vp[j] * vm[3 - j];
            const glm::dvec3& p = g.points[static_cast<std::size_t>(4 * i + j)];
            pu += (c * vt * (dup[i] * um[3 - i] + up[i] * dum[3 - i])) * p;
            pv += (c * ut * (dvp[j] * vm[3 - j] + vp[j] * dvm[3 - j])) * p;
        }
    }
    pu = g.measure * pu;
    pv = g.measure * pv;
    const glm::dvec3 n = glm::cross(pu, pv);
    const double n2 = glm::dot(n, n);
    if (n2 > kBezierEpsilon * glm::dot(pu, pu) * glm::dot(pv, pv) && std::isfinite(n2))
        return n / std::sqrt(n2);
    return {1.0, 0.0, 0.0};
}

void each_bicubic_piece(const BicubicPatchGeometry& g,
                        const std::function<void(const BicubicPiece&)>& piece) {
    walk(
        g, [](const Box3&) { return true; }, piece);
}

std::optional<SurfaceHit> intersect(const BicubicPatchGeometry& g, const Ray3& ray, double s_min,
                                    double s_max) {
    const glm::dvec3 inverse = 1.0 / ray.direction;
    double far = s_max;
    std::optional<BarycentricHit> best;
    std::array<glm::dvec3, 3> corners;
    std::array<glm::dvec2, 3> uvs;
    glm::dvec3 face(0.0);
    int part = 0;
    walk(
        g,
        [&](const Box3& box) {
            double entry = 0.0;
            return objects::ray_meets_box(box, ray.origin, inverse, s_min, far, entry);
        },
        [&](const BicubicPiece& piece) {
            const std::array<glm::dvec2, 4> uv = corner_uv(piece);
            for (int k = 0; k < 2; ++k) {
                const glm::dvec3& a = piece.corners[kTriangles[k][0]];
                const glm::dvec3& b = piece.corners[kTriangles[k][1]];
                const glm::dvec3& c = piece.corners[kTriangles[k][2]];
                const glm::dvec3 n = glm::cross(b - a, c - a);
                const double length = safe_length(n);
                if (!(length > 0.0) || !std::isfinite(length)) continue;  // no area
                const auto hit = intersect_barycentric(a, b, c, ray, s_min, far);
                if (!hit) continue;
                best = hit;
                far = hit->s;
                corners = {a, b, c};
                uvs = {uv[kTriangles[k][0]], uv[kTriangles[k][1]], uv[kTriangles[k][2]]};
                face = n / length;
                part = k;
            }
        });
    if (!best) return std::nullopt;
    const double w1 = best->b1, w2 = best->b2, w3 = best->b3;
    SurfaceHit hit;
    hit.s = best->s;
    hit.part = part;
    hit.normal = face;
    hit.point = w1 * corners[0] + w2 * corners[1] + w3 * corners[2];
    hit.error = barycentric_error(*best, corners[0], corners[1], corners[2]);
    // intersect_subpatch: the corners' normals blended by the weights.
    const glm::dvec3 blend = w1 * bicubic_normal(g, uvs[0].x, uvs[0].y) +
                             w2 * bicubic_normal(g, uvs[1].x, uvs[1].y) +
                             w3 * bicubic_normal(g, uvs[2].x, uvs[2].y);
    const double b2 = glm::dot(blend, blend);
    const glm::dvec3 world =
        b2 > kBezierEpsilon ? blend / std::sqrt(b2) : glm::dvec3(1.0, 0.0, 0.0);
    // Carried back: the placement's inverse transpose takes M^T n to n.
    const glm::dvec3 back = glm::transpose(g.measure) * world;
    const double back_length = safe_length(back);
    hit.shading_normal =
        back_length > 0.0 && std::isfinite(back_length) ? back / back_length : hit.normal;
    // Compute_Texture_UV at the point (v, u): the uv_vectors blended.
    const glm::dvec2 at = w1 * uvs[0] + w2 * uvs[1] + w3 * uvs[2];
    const auto& st = g.uv_corners;
    const glm::dvec2 along0 = st[0] + at.y * (st[1] - st[0]);
    const glm::dvec2 along1 = st[3] + at.y * (st[2] - st[3]);
    hit.uv = along0 + at.x * (along1 - along0);
    if (!is_finite(hit)) return std::nullopt;
    return hit;
}

bool inside(const BicubicPatchGeometry&, glm::dvec3) {
    return false;
}

Box3 object_bounds(const BicubicPatchGeometry& g) {
    return box_of(g.points);
}

bool surface_may_meet(const BicubicPatchGeometry& g, const Box3& box) {
    bool met = false;
    walk(
        g,
        [&](const Box3& part) {
            return !met && overlaps(widened(part, meet_slack(part, 0.0)), box);
        },
        [&](const BicubicPiece& piece) {
            for (int k = 0; k < 2 && !met; ++k)
                met = triangle_may_meet(piece.corners[kTriangles[k][0]],
                                        piece.corners[kTriangles[k][1]],
                                        piece.corners[kTriangles[k][2]], box);
        });
    return met;
}

}  // namespace hexant::runtime::geometry
