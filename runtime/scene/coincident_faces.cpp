#include "runtime/scene/coincident_faces.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include <glm/glm.hpp>

#include "runtime/geometry/orthonormal_basis.hpp"
#include "runtime/objects/flat_face.hpp"

namespace hexant::runtime {
namespace {

// Two planes closer than this fraction of their points' distance from the
// origin (or of their faces' size) are one plane: far above the rounding of
// a few transforms (about 1e-16 of it), far below any gap a scene means.
constexpr double kRelative = 1e-9;
// Overlapping pairs examined at most: a pathological pile of coincident
// copies stops the search, not the reading.
constexpr std::size_t kMostExamined = 1'000'000;
// Faces collected at most (a union doubled twenty times holds 2^20 boxes):
// the check's memory stays bounded; past it the rest take no part.
constexpr std::size_t kMostFaces = std::size_t(1) << 18;
// Half-spaces a member is cut by at most (a chain of 10^4 nested
// intersections would copy a growing list at each level).
constexpr std::size_t kMostClips = 96;
// Members nested deeper than this in CSGs take no part (the walk recurses;
// objects may nest 10,000 deep, runtime/objects/object.hpp).
constexpr int kMostNesting = 256;

// The CSG an object is a member of, up to the scene (a chain shared by the
// members).
struct CsgLink {
    Csg::Kind kind;
    std::shared_ptr<const CsgLink> parent;
};

struct Owner {
    const ObjectRecord* record;
    const ObjectRecord* top;             // the scene's object it is part of
    std::shared_ptr<const CsgLink> csg;  // null: a top-level object
    const void* texture_source;          // the record whose texture it wears (or the default)
    bool opaque;
    Lifetime lifetime;
};

struct Face {
    std::size_t owner;
    glm::dvec3 normal;  // unit, canonical sign: its largest component positive
    double offset;      // dot(normal, any point of it)
    double facing;      // +1: the surface faces `normal`, -1: away
    bool two_sided;
    std::vector<glm::dvec3> corners;  // world space; empty: the whole plane
    double scale;                     // the largest coordinate magnitude of it
};

// Where a CSG lets a member's surface be, as far as its other members are
// convex polyhedra (a box, a plane: kinds with kConvexPolyhedron): behind
// every one of these planes (dot(normal, p) <= offset), in world space.
struct HalfSpace {
    glm::dvec3 normal;
    double offset;
    const ObjectRecord* from;
};

struct Clips {
    std::vector<HalfSpace> planes;
    // The corners of the bounded ones among them: a whole plane's face
    // starts as a square over them before it is cut.
    std::vector<glm::dvec3> hull;
};

// The part of a convex polygon behind a plane (Sutherland-Hodgman). A
// corner within `slack` of the plane counts as behind it (a face lying in
// the plane itself is kept), but edges are cut at the plane itself, so two
// faces cut by one plane from either side only touch.
std::vector<glm::dvec3> cut(const std::vector<glm::dvec3>& polygon, const HalfSpace& h,
                            double slack) {
    std::vector<glm::dvec3> out;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3& p = polygon[i];
        const glm::dvec3& q = polygon[(i + 1) % n];
        const double dp = glm::dot(h.normal, p) - h.offset;
        const double dq = glm::dot(h.normal, q) - h.offset;
        if (dp <= slack) out.push_back(p);
        if ((dp <= slack) != (dq <= slack) && dp != dq)
            out.push_back(p + (q - p) * std::clamp(dp / (dp - dq), 0.0, 1.0));
    }
    return out;
}

// Whether no light passes a texture: Texture::opaque, and a texture_map
// whose entries all are (Texture::opaque says no to any map, as POV-Ray's
// Test_Opacity does for its own purpose). Each map once (`known`: a
// declared chain of maps sharing their entries has 2^n paths), and no
// deeper than 64 maps (the stack).
bool lets_no_light(const Texture& texture, std::map<const Texture*, bool>& known, int depth = 0) {
    if (!texture.is_patterned()) return texture.opaque();
    if (const auto it = known.find(&texture); it != known.end()) return it->second;
    bool all = depth <= 64;
    for (const auto& entry : texture.texture_map)
        if (all && (!entry.texture || !lets_no_light(*entry.texture, known, depth + 1)))
            all = false;
    known[&texture] = all;
    return all;
}

template <class Kind>
concept ModelOf = requires {
    typename Kind::Model;
}
&&std::constructible_from<typename Kind::Model, const Kind&>;

struct Aabb {
    glm::dvec3 lo{INFINITY}, hi{-INFINITY};
};

// A static record's world box, where it is finite (a CSG's from its
// members': a union's holds them all, an intersection is within each, a
// difference within its first). Depth-limited like every record walk.
std::optional<Aabb> world_bound(const ObjectRecord& record, const glm::dmat4& parent,
                                int depth = 0) {
    // (A CSG's own shape_depends_on_time() walks all its members: each
    // member is asked alone below.)
    if (depth > 64 || record.inverse || record.transform.depends_on_time() ||
        record.transform.has_deformation() ||
        (!std::holds_alternative<Csg>(record.shape) && record.shape_depends_on_time()))
        return std::nullopt;
    const glm::dmat4 matrix = parent * record.transform.matrix_at(0.0);
    if (const auto* group = std::get_if<Csg>(&record.shape)) {
        std::optional<Aabb> out;
        for (std::size_t i = 0; i < group->children.size(); ++i) {
            if (!group->children[i]) continue;
            const auto b = world_bound(*group->children[i], matrix, depth + 1);
            switch (group->kind) {
                case Csg::Kind::Union:
                case Csg::Kind::Merge:
                    if (!b) return std::nullopt;
                    if (!out) out = Aabb{};
                    out->lo = glm::min(out->lo, b->lo);
                    out->hi = glm::max(out->hi, b->hi);
                    break;
                case Csg::Kind::Intersection:
                    if (b) {
                        if (!out) out = *b;
                        out->lo = glm::max(out->lo, b->lo);
                        out->hi = glm::min(out->hi, b->hi);
                    }
                    break;
                case Csg::Kind::Difference:
                    if (i == 0) return b;
                    break;
            }
        }
        return out;
    }
    std::optional<Aabb> out;
    std::visit(
        [&](const auto& shape) {
            using Kind = std::decay_t<decltype(shape)>;
            if constexpr (ModelOf<Kind>) {
                const typename Kind::Model model(shape);
                const IntervalBox box = model.box_over(Interval(0.0, 0.0));
                Aabb world;
                for (int corner = 0; corner < 8; ++corner) {
                    const glm::dvec3 p{(corner & 1) ? box[0].hi : box[0].lo,
                                       (corner & 2) ? box[1].hi : box[1].lo,
                                       (corner & 4) ? box[2].hi : box[2].lo};
                    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return;
                    const glm::dvec3 q(matrix * glm::dvec4(p, 1.0));
                    world.lo = glm::min(world.lo, q);
                    world.hi = glm::max(world.hi, q);
                }
                out = world;
            }
        },
        record.shape);
    return out;
}

struct Walker {
    std::vector<Owner> owners;
    std::vector<Face> faces;

    // A record's flat faces in world space, when it is static and plain.
    static std::optional<std::vector<objects::FlatFace>> world_faces(const ObjectRecord& record,
                                                                     const glm::dmat4& matrix) {
        if (record.transform.depends_on_time() || record.transform.has_deformation() ||
            record.shape_depends_on_time() || record.limits)
            return std::nullopt;
        std::optional<std::vector<objects::FlatFace>> out;
        std::visit(
            [&](const auto& shape) {
                if constexpr (requires { shape.flat_faces(0.0); }) {
                    out.emplace();
                    const glm::dmat3 normals = glm::transpose(glm::inverse(glm::dmat3(matrix)));
                    for (objects::FlatFace face : shape.flat_faces(0.0)) {
                        face.normal = normals * face.normal;
                        face.point = glm::dvec3(matrix * glm::dvec4(face.point, 1.0));
                        for (auto& c : face.corners) c = glm::dvec3(matrix * glm::dvec4(c, 1.0));
                        out->push_back(std::move(face));
                    }
                }
            },
            record.shape);
        return out;
    }

    // What member `i` of a CSG adds to the clips of its other members: its
    // inside (an intersection's member, a difference's first) or outside (a
    // difference's others; `inverse` swaps them), where that is convex.
    static void add_clips(const Csg& group, std::size_t i, const glm::dmat4& matrix, Clips& clips) {
        const ObjectRecord& member = *group.children[i];
        const bool inside_of = group.kind == Csg::Kind::Intersection || i == 0;
        // Within its world box, whatever its shape.
        if (inside_of)
            if (const auto box = world_bound(member, matrix)) {
                for (int a = 0; a < 3 && clips.planes.size() + 2 <= kMostClips; ++a) {
                    glm::dvec3 n(0.0);
                    n[a] = 1.0;
                    clips.planes.push_back({n, box->hi[a], &member});
                    clips.planes.push_back({-n, -box->lo[a], &member});
                }
                clips.hull.push_back(box->lo);
                clips.hull.push_back(box->hi);
            }
        const bool is_polyhedron = std::visit(
            [](const auto& shape) {
                if constexpr (requires { std::decay_t<decltype(shape)>::kConvexPolyhedron; })
                    return std::decay_t<decltype(shape)>::kConvexPolyhedron;
                else
                    return false;
            },
            member.shape);
        if (!is_polyhedron) return;
        const auto faces = world_faces(member, matrix * member.transform.matrix_at(0.0));
        if (!faces || faces->empty()) return;
        const bool inside = (group.kind == Csg::Kind::Intersection || i == 0) != member.inverse;
        if (!inside && faces->size() != 1) return;  // outside a box is not convex
        for (const auto& face : *faces) {
            const double length = glm::length(face.normal);
            if (!(length > 0.0) || !std::isfinite(length)) continue;
            const glm::dvec3 n = (inside ? 1.0 : -1.0) * face.normal / length;
            if (clips.planes.size() >= kMostClips) break;
            clips.planes.push_back({n, glm::dot(n, face.point), &member});
            if (inside)
                clips.hull.insert(clips.hull.end(), face.corners.begin(), face.corners.end());
        }
    }

    const ObjectRecord* top = nullptr;  // the scene's object being walked
    std::map<const Texture*, bool> known_opaque;

    void visit(const ObjectRecord& record, const glm::dmat4& parent, bool moving,
               const std::shared_ptr<const CsgLink>& csg, const void* texture_source, bool opaque,
               const Lifetime& lifetime, const Clips& clips, int depth = 0) {
        if (depth > kMostNesting || record.transform.has_deformation() || record.no_image) return;
        if (record.limits && !record.limits->clipped_by.empty()) return;
        moving = moving || record.transform.depends_on_time();
        const glm::dmat4 matrix = parent * record.transform.matrix_at(0.0);
        if (record.texture) {
            texture_source = &record;
            opaque = lets_no_light(*record.texture, known_opaque);
        }
        const Lifetime life = lifetime.intersect(record.lifetime);
        if (life.is_never()) return;
        if (const auto* group = std::get_if<Csg>(&record.shape)) {
            auto link = std::make_shared<const CsgLink>(CsgLink{group->kind, csg});
            const bool cuts = !moving && (group->kind == Csg::Kind::Intersection ||
                                          group->kind == Csg::Kind::Difference);
            Clips inner = clips;
            if (cuts)
                for (std::size_t i = 0; i < group->children.size(); ++i)
                    if (group->children[i]) add_clips(*group, i, matrix, inner);
            for (const auto& child : group->children)
                if (child && faces.size() < kMostFaces)
                    visit(*child, matrix, moving, link, texture_source, opaque, life,
                          cuts ? inner : clips, depth + 1);
            return;
        }
        if (moving || faces.size() >= kMostFaces) return;
        const auto own = world_faces(record, matrix);
        if (!own || own->empty()) return;
        owners.push_back({&record, top, csg, texture_source, opaque, life});
        for (const auto& face : *own) add(face, clips, owners.size() - 1);
    }

    void add(const objects::FlatFace& face, const Clips& clips, std::size_t owner) {
        const double length = glm::length(face.normal);
        if (!(length > 0.0) || !std::isfinite(length)) return;
        Face out{owner, face.normal / length, 0.0, 1.0, face.two_sided, face.corners, 0.0};
        const ObjectRecord* self = owners[owner].record;
        // A whole plane cut by a bounded member starts as a square over it.
        if (out.corners.empty() && !clips.hull.empty()) {
            glm::dvec3 centre(0.0);
            for (const auto& c : clips.hull) centre += c / double(clips.hull.size());
            double reach = 0.0;
            for (const auto& c : clips.hull) reach = std::max(reach, glm::length(c - centre));
            centre -= out.normal * (glm::dot(out.normal, centre - face.point));
            const auto basis = geometry::orthonormal_basis(out.normal);
            const double r = 2.0 * reach;
            out.corners = {centre + r * (basis.t1 + basis.t2), centre + r * (basis.t2 - basis.t1),
                           centre - r * (basis.t1 + basis.t2), centre + r * (basis.t1 - basis.t2)};
        }
        out.scale = glm::length(face.point);
        for (const auto& c : out.corners) out.scale = std::max(out.scale, glm::length(c));
        if (!out.corners.empty())
            for (const auto& h : clips.planes) {
                if (h.from == self) continue;
                out.corners = cut(out.corners, h, kRelative * out.scale);
                if (out.corners.size() < 3) return;  // cut away
            }
        // One sign per plane: the first component that is not zero at the
        // grouping's resolution is positive (the largest component would
        // flip with rounding where two are equal, as at 45 degrees).
        int first = 0;
        while (first < 2 && std::llround(std::ldexp(out.normal[first], 30)) == 0) ++first;
        if (out.normal[first] < 0.0) {
            out.normal = -out.normal;
            out.facing = -1.0;
        }
        out.offset = glm::dot(out.normal, face.point);
        if (!std::isfinite(out.offset) || !std::isfinite(out.scale)) return;
        faces.push_back(std::move(out));
    }
};

using Polygon2 = std::vector<glm::dvec2>;

// Do two convex polygons share an area (more than a sliver of `eps`)?
// Separating axes: the edge normals of both.
bool overlap(const Polygon2& a, const Polygon2& b, double eps) {
    for (const Polygon2* p : {&a, &b}) {
        const std::size_t n = p->size();
        for (std::size_t i = 0; i < n; ++i) {
            const glm::dvec2 edge = (*p)[(i + 1) % n] - (*p)[i];
            const glm::dvec2 axis{-edge.y, edge.x};
            const double length = glm::length(axis);
            if (!(length > 0.0)) continue;
            double lo_a = INFINITY, hi_a = -INFINITY, lo_b = INFINITY, hi_b = -INFINITY;
            for (const auto& q : a) {
                const double s = glm::dot(q, axis) / length;
                lo_a = std::min(lo_a, s);
                hi_a = std::max(hi_a, s);
            }
            for (const auto& q : b) {
                const double s = glm::dot(q, axis) / length;
                lo_b = std::min(lo_b, s);
                hi_b = std::max(hi_b, s);
            }
            if (hi_a <= lo_b + eps || hi_b <= lo_a + eps) return false;
        }
    }
    return true;
}

double area(const Polygon2& p) {
    double twice = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const auto& a = p[i];
        const auto& b = p[(i + 1) % p.size()];
        twice += a.x * b.y - a.y * b.x;
    }
    return std::abs(twice) / 2.0;
}

// Can a ray tell the two apart (see the header)?
bool visible(const Face& a, const Face& b, const Owner& oa, const Owner& ob) {
    // The nearest CSG holding both.
    std::set<const CsgLink*> above;
    for (const CsgLink* l = oa.csg.get(); l != nullptr; l = l->parent.get()) above.insert(l);
    const CsgLink* common = ob.csg.get();
    while (common != nullptr && above.count(common) == 0) common = common->parent.get();
    if (common != nullptr &&
        (common->kind == Csg::Kind::Intersection || common->kind == Csg::Kind::Difference))
        return true;
    if (oa.texture_source == ob.texture_source && oa.texture_source != nullptr &&
        oa.texture_source != oa.record && ob.texture_source != ob.record)
        return false;  // one CSG's texture on both
    if (a.two_sided || b.two_sided || a.facing == b.facing) return true;
    return !oa.opaque || !ob.opaque;
}

}  // namespace

CoincidentFacesReport find_coincident_faces(const std::vector<ObjectPtr>& objects,
                                            const Texture& default_texture) {
    Walker walker;
    const bool default_opaque = lets_no_light(default_texture, walker.known_opaque);
    for (const auto& object : objects)
        if (object) {
            walker.top = object.get();
            walker.visit(*object, glm::dmat4(1.0), false, nullptr, nullptr, default_opaque,
                         Lifetime::always(), Clips{});
        }
    auto& faces = walker.faces;
    const auto& owners = walker.owners;

    // Group by direction (to 2^-30 of a unit normal), then by offset.
    auto key = [](const Face& f) {
        return std::array<long long, 3>{std::llround(std::ldexp(f.normal.x, 30)),
                                        std::llround(std::ldexp(f.normal.y, 30)),
                                        std::llround(std::ldexp(f.normal.z, 30))};
    };
    std::sort(faces.begin(), faces.end(), [&](const Face& a, const Face& b) {
        return std::make_pair(key(a), a.offset) < std::make_pair(key(b), b.offset);
    });

    CoincidentFacesReport report;
    std::set<std::pair<std::string, std::string>> said;
    std::size_t examined = 0;
    auto found = [&](const Face& a, const Face& b) {
        const Owner& oa = owners[a.owner];
        const Owner& ob = owners[b.owner];
        if (!visible(a, b, oa, ob)) return;
        if (oa.lifetime.intersect(ob.lifetime).is_never()) return;
        std::string pa = oa.record->place.to_string(), pb = ob.record->place.to_string();
        const Owner* first = &oa;
        const Owner* second = &ob;
        if (pb < pa) {
            std::swap(pa, pb);
            std::swap(first, second);
        }
        if (!said.insert({pa, pb}).second) return;
        if (report.pairs.size() < CoincidentFacesReport::kMostReported)
            report.pairs.push_back({{first->record->place, shape_name(first->record->shape),
                                     first->top->place, shape_name(first->top->shape)},
                                    {second->record->place, shape_name(second->record->shape),
                                     second->top->place, shape_name(second->top->shape)}});
        else
            ++report.more;
    };

    // A candidate pair of faces of one plane: reported when they belong to
    // two objects and `overlapping` (none: they do) says they share an area.
    auto examine = [&](std::size_t a, std::size_t b, const std::function<bool()>& overlapping) {
        if (faces[a].owner == faces[b].owner || examined >= kMostExamined) return;
        ++examined;
        // One plane for this pair: within the slack of the smaller face's
        // coordinates (a vast floor does not widen it for a small box).
        const Face& fa = faces[a];
        const Face& fb = faces[b];
        const double size = std::min(fa.corners.empty() ? INFINITY : fa.scale,
                                     fb.corners.empty() ? INFINITY : fb.scale);
        const double near = std::isfinite(size) ? size : 0.0;
        if (std::abs(fa.offset - fb.offset) >
            kRelative * (std::min(std::abs(fa.offset), std::abs(fb.offset)) + near))
            return;
        if (!overlapping || overlapping()) found(faces[a], faces[b]);
    };
    for (std::size_t start = 0; start < faces.size() && examined < kMostExamined;) {
        // One plane: consecutive faces of one direction within the tolerance.
        std::size_t end = start + 1;
        while (end < faces.size() && key(faces[end]) == key(faces[start]) &&
               faces[end].offset - faces[end - 1].offset <=
                   kRelative * (std::abs(faces[end].offset) + std::abs(faces[end - 1].offset) +
                                faces[end].scale + faces[end - 1].scale))
            ++end;
        if (end - start >= 2) {
            const auto basis = geometry::orthonormal_basis(faces[start].normal);
            std::vector<Polygon2> flat(end - start);
            std::vector<std::size_t> finite, whole;
            for (std::size_t i = start; i < end; ++i) {
                if (faces[i].corners.empty()) {
                    whole.push_back(i);
                    continue;
                }
                for (const auto& c : faces[i].corners)
                    flat[i - start].push_back({glm::dot(c, basis.t1), glm::dot(c, basis.t2)});
                // Not a sliver (a flat box's sides): area against the
                // face's own extent, not its distance from the origin.
                double extent = 0.0;
                for (const auto& q : flat[i - start])
                    extent = std::max(extent, glm::length(q - flat[i - start].front()));
                if (area(flat[i - start]) > kRelative * extent * extent) finite.push_back(i);
            }
            // A whole plane meets every face of its plane.
            for (std::size_t iw = 0; iw < whole.size(); ++iw) {
                const std::size_t w = whole[iw];
                for (std::size_t i = iw + 1; i < whole.size() && examined < kMostExamined; ++i)
                    examine(w, whole[i], {});
                for (std::size_t i = 0; i < finite.size() && examined < kMostExamined; ++i)
                    examine(w, finite[i], {});
            }
            // The others: a sweep along u over the pairs whose u-ranges overlap.
            std::vector<std::pair<double, double>> range(end - start);
            for (const std::size_t i : finite) {
                auto& [lo, hi] = range[i - start];
                lo = INFINITY;
                hi = -INFINITY;
                for (const auto& q : flat[i - start]) {
                    lo = std::min(lo, q.x);
                    hi = std::max(hi, q.x);
                }
            }
            std::sort(finite.begin(), finite.end(), [&](std::size_t a, std::size_t b) {
                return range[a - start].first < range[b - start].first;
            });
            for (std::size_t ia = 0; ia < finite.size() && examined < kMostExamined; ++ia) {
                const std::size_t a = finite[ia];
                for (std::size_t ib = ia + 1; ib < finite.size() && examined < kMostExamined;
                     ++ib) {
                    const std::size_t b = finite[ib];
                    if (range[b - start].first >= range[a - start].second) break;
                    examine(a, b, [&] {
                        const double eps = kRelative * std::max(faces[a].scale, faces[b].scale);
                        return overlap(flat[a - start], flat[b - start], eps);
                    });
                }
            }
        }
        start = end;
    }
    return report;
}

}  // namespace hexant::runtime
