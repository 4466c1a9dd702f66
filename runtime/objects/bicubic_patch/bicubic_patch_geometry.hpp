// POV-Ray 3.7's bicubic_patch in object space at one instant (bezier.cpp):
// the Bezier patch P(u, v) = sum B_i(u) B_j(v) P[i][j] of 4 x 4 control
// points, rendered as POV-Ray renders it, which is not the patch itself
// but triangles of it:
//
//   - the patch is halved by de Casteljau's rule, along u and v together
//     while both have steps left, then along the one that has, until a
//     piece is flat (its control points lie within `flatness` of the plane
//     of three of its corners) or u_steps and v_steps halvings are done
//     (bezier_subdivider, bezier_tree_builder: the same pieces for type 0
//     and type 1);
//   - each piece is two triangles of its corners, P[0][0] P[0][3] P[3][3]
//     and P[0][0] P[3][3] P[3][0] (bezier_subpatch_intersect);
//   - the shading normal at a hit is the blend, by the hit's barycentric
//     weights, of the patch's unit normals Pu x Pv at the triangle's three
//     corners' (u, v) (intersect_subpatch, bezier_value; (1, 0, 0) where
//     a normal vanishes, as POV-Ray's); the geometric normal is the
//     triangle's own;
//   - uv is the corners' uv_vectors blended bilinearly at the hit's (u, v)
//     (Compute_Texture_UV).
//
// POV-Ray moves the control points into the world before it subdivides,
// so its flatness and its normals are measured in the world. hexant keeps
// the points in object space (the ray comes to them), so the geometry
// carries the placement's linear part (`measure`): the flatness test and
// the normals are taken on the points it maps, which gives POV-Ray's
// pieces and normals under any affine placement (de Casteljau's halving
// commutes with affine maps). The shading normal returned is that world
// normal carried back (times measure's transpose), so that the placement's
// inverse transpose gives it again.
//
// Differences from POV-Ray, all at rounding level or below: a triangle is
// skipped only when its area is exactly zero (POV-Ray skips slivers of
// sine below 1e-5); corners coincide when they are equal (POV-Ray: within
// 1e-10, an absolute distance); hits are found by the watertight triangle
// test with hexant's error bounds instead of POV-Ray's 1e-5 minimum depth.
//
// Bounds: every triangle's corners are control points of a piece, which
// lie in the box of the patch's control points (each halving takes
// midpoints, and a midpoint rounded lies between its ends), so the box of
// the control points holds the surface, and each piece's box its own.
// No NaN or Inf leaves these routines for finite input; control points so
// large that their arithmetic overflows give no hits.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/geometry/ray3.hpp"

namespace hexant::runtime::geometry {

// P[i][j] at 4 i + j: i runs along u, j along v (POV-Ray's Control_Points).
using BicubicNet = std::array<glm::dvec3, 16>;

// A piece of the subdivided patch: its corners P[0][0], P[0][3], P[3][3],
// P[3][0] and the rectangle of (u, v) it covers.
struct BicubicPiece {
    std::array<glm::dvec3, 4> corners;
    double u0 = 0.0, u1 = 1.0, v0 = 0.0, v1 = 1.0;
};

// The subdivision kept for a patch that does not change: a tree of the
// pieces' control-point boxes (POV-Ray's type 1 Node_Tree).
struct BicubicTree {
    struct Node {
        Box3 box;                 // of the node's control points
        std::uint32_t first = 0;  // inner: children [first, first + count); leaf: its piece
        std::uint32_t count = 0;  // 0 for a leaf
    };
    std::vector<Node> nodes;  // the root first
    std::vector<BicubicPiece> pieces;
};

struct BicubicPatchGeometry {
    BicubicNet points{};
    // The placement's linear part, in which flatness and normals are
    // measured (the identity for a deformed object: hexant's deformations
    // have no POV-Ray counterpart).
    glm::dmat3 measure{1.0};
    double flatness = 0.0;
    int u_steps = 0, v_steps = 0;
    std::array<glm::dvec2, 4> uv_corners{{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}};
    // The subdivision, when kept (keep_subdivision); otherwise each ray
    // subdivides the pieces its path meets, as POV-Ray's type 0.
    std::shared_ptr<const BicubicTree> tree;
};

// The most pieces a kept subdivision holds (about 12 MB); a patch finer
// than that is subdivided for each ray instead.
inline constexpr std::size_t kMaxKeptBicubicPieces = std::size_t(1) << 16;

// Subdivides g once and keeps the pieces in g.tree (left empty past
// kMaxKeptBicubicPieces).
void keep_subdivision(BicubicPatchGeometry& g);

// POV-Ray's determine_subpatch_flatness of a piece, in g's measure: the
// largest distance of its control points from the plane of its corners
// P[0][0], P[0][3], P[3][0] (or, where the first two coincide, of P[0][0],
// P[3][3], P[3][0]); negative when no such plane exists.
double bicubic_flatness(const BicubicPatchGeometry& g, const BicubicNet& net);

// The unit normal of the patch at (u, v) in g's measure (POV-Ray's
// bezier_value): (Pu x Pv) normalised, (1, 0, 0) where it vanishes against
// the tangents (|Pu x Pv|^2 <= 1e-10 |Pu|^2 |Pv|^2).
glm::dvec3 bicubic_normal(const BicubicPatchGeometry& g, double u, double v);

// Calls piece(p) for every piece of g's subdivision, in no set order.
void each_bicubic_piece(const BicubicPatchGeometry& g,
                        const std::function<void(const BicubicPiece&)>& piece);

// Hits: part 0 (the first triangle of a piece) or 1 (the second); uv as
// POV-Ray's (the uv_vectors blended at the hit's (u, v)).
std::optional<SurfaceHit> intersect(const BicubicPatchGeometry& g, const Ray3& ray, double s_min,
                                    double s_max);
bool inside(const BicubicPatchGeometry& g, glm::dvec3 p);  // always false: a patch is no solid
Box3 object_bounds(const BicubicPatchGeometry& g);
bool surface_may_meet(const BicubicPatchGeometry& g, const Box3& box);

}  // namespace hexant::runtime::geometry
