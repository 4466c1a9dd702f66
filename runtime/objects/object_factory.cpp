#include "runtime/objects/object_factory.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "runtime/objects/bounded_object.hpp"
#include "runtime/objects/clipped_object.hpp"
#include "runtime/objects/csg_object.hpp"
#include "runtime/objects/instance_object.hpp"
#include "runtime/objects/lifetime_object.hpp"
#include "runtime/objects/object_error.hpp"
#include "runtime/objects/primitive.hpp"
#include "runtime/scene/media_volume.hpp"

namespace hexant::runtime {

namespace {

// What a group hands down to its children, already in world terms.
struct Inherited {
    Transform to_world;  // the group's object space to the world
    std::optional<Texture> texture;
    std::shared_ptr<const Texture> interior_texture;  // null: none
    std::optional<Interior> interior;
    // The interior's media, compiled once for the object that wrote it
    // and shared by its members (build_shape).
    std::shared_ptr<const MediaVolume> media;
    bool no_shadow = false;
    ObjectFlags flags;  // no_image, no_reflection, double_illuminate
    int csg_depth = 0;  // CSG objects around this one (unions split apart do not count)
    // The lifetime of unions split apart around it (a group kept whole
    // carries its own, runtime/objects/lifetime_object.hpp).
    Lifetime lifetime;
    // Is it a member of an intersection (LifetimeObject's inside_when_absent)?
    bool in_intersection = false;
    // The interior refraction knows it by (TextureEvaluator::interior_key):
    // the one of the nearest object around with an interior { } of its own,
    // else of the outermost; null until a group or a mesh needs one to share.
    std::shared_ptr<const void> interior_key;
    // Inside an instance: the union's space to the world (to_world then
    // stops at the union), which textures and interiors still go through:
    // the members' shapes are built in the union's space, their textures
    // in the world (instance_object.hpp).
    Transform placement;
    bool in_instance = false;
};

// A group's interior identity, for its members to share: the one it was
// handed, else a new one.
std::shared_ptr<const void> shared_interior(const std::shared_ptr<const void>& key) {
    struct InteriorIdentity {
        char unused = 0;  // (a distinct address each)
    };
    return key ? key : std::make_shared<const InteriorIdentity>();
}

// The tracer tests a CSG's children recursively for every ray, on threads
// whose stacks are a few MB: deeper nesting than this is refused where it is
// written (a generated scene reached 8,000 intersections, a crash; real
// scenes nest tens).
constexpr int kMaxCsgDepth = 1000;

// What the scene's top hands its objects: the default texture.
Inherited top_level(const Texture& default_texture) {
    Inherited top;
    top.texture = default_texture;
    top.lifetime = Lifetime::always();
    return top;
}

// What `record` holds in world terms under `parent`: its transform after
// the parent's, its texture (mapped to the parent's space) or the parent's,
// its interior or the parent's, no_shadow if either says so; the rest as
// the parent's.
// An object's photon flags: its own, then its group's over them, as
// POV-Ray's Post_Process promotes a CSG's to its children. A target's
// number is its record's address folded to 31 bits (records are at least
// 16-byte aligned; two would share one only 32 GB apart): the same however
// often the record is handed down while its object is built.
void handed_photons(const ObjectRecord& record, const ObjectFlags& parent, ObjectFlags& down) {
    const ObjectPhotons& own = record.photons;
    if (parent.photon_target > 0.0f) {
        down.photon_target = parent.photon_target;
        down.photon_group = parent.photon_group;
    } else if (own.target > 0.0) {
        down.photon_target = static_cast<float>(own.target);
        down.photon_group = static_cast<std::int32_t>(
            (reinterpret_cast<std::uintptr_t>(&record) >> 4) & 0x7fffffffu);
    } else {
        down.photon_target = 0.0f;
        down.photon_group = -1;
    }
    down.photon_refraction =
        parent.photon_refraction != 0 ? parent.photon_refraction : own.refraction;
    down.photon_reflection =
        parent.photon_reflection != 0 ? parent.photon_reflection : own.reflection;
    down.photon_pass_through = own.pass_through || parent.photon_pass_through;
    down.photon_collect = own.collect && parent.photon_collect;
}

Inherited handed_down(const ObjectRecord& record, const Inherited& parent) {
    Inherited down = parent;
    down.to_world = record.transform;
    down.to_world.append(parent.to_world);
    if (record.texture) {
        // The record's texture maps to the record's parent space.
        down.texture = *record.texture;
        down.texture->transform_by(parent.to_world);
        if (parent.in_instance) down.texture->transform_by(parent.placement);
    }
    // (A group's interior texture reaches members without their own, as
    // POV-Ray's Post_Process promotes it, whatever their own texture.)
    if (record.interior_texture) {
        auto inside = std::make_shared<Texture>(*record.interior_texture);
        inside->transform_by(parent.to_world);
        if (parent.in_instance) inside->transform_by(parent.placement);
        down.interior_texture = std::move(inside);
    }
    if (record.interior) {
        // (Its media's densities, as the texture, map to the parent's space.)
        down.interior = *record.interior;
        down.interior->transform_by(parent.to_world);
        if (parent.in_instance) down.interior->transform_by(parent.placement);
        down.interior_key = nullptr;  // (its own: POV-Ray's Post_Process keeps it)
    }
    down.no_shadow = record.no_shadow || parent.no_shadow;
    if (record.no_image) down.flags.hidden_from |= kSightImage;
    if (record.no_reflection) down.flags.hidden_from |= kSightReflection;
    if (record.no_radiosity) down.flags.hidden_from |= kSightRadiosity;
    if (down.no_shadow) down.flags.hidden_from |= kSightPhoton;
    down.flags.double_illuminate = record.double_illuminate || parent.flags.double_illuminate;
    handed_photons(record, parent.flags, down.flags);
    // (A group's hollow reaches its members, as POV-Ray's
    // Set_CSG_Children_Flag; a member's own says for itself.)
    down.flags.hollow = record.hollow || parent.flags.hollow;
    // (A light_group's members: its lights and those of the groups around
    // it; global_lights as the outermost group says, which POV-Ray's
    // Set_CSG_Children_Flag writes over the inner groups' members last.)
    if (record.light_group) {
        if (parent.flags.light_group < 0)
            down.flags.no_global_lights = !record.light_group->global_lights;
        down.flags.light_group = record.light_group->id;
    }
    return down;
}

IntelligentObjectPtr build_object(const ObjectRecord& record, const Inherited& parent);
IntelligentObjectPtr build_shape(const ObjectRecord& record, const Inherited& parent);
IntelligentObjectPtr build(const ObjectRecord& record, const Inherited& parent);

// A difference whose first member lives part of the time (made under a
// branch on clock): POV-Ray takes the later members away from the first
// member there is, so where the first written is absent the next present
// one is the base. One difference per base, each living where its base is
// the first present, side by side in a union (they never overlap in time).
IntelligentObjectPtr build_difference_by_base(const Csg& csg, const Inherited& down, bool inverse) {
    std::vector<IntelligentObjectPtr> parts;
    Lifetime none_before = Lifetime::always();  // where every member so far is absent
    for (std::size_t k = 0; k < csg.children.size(); ++k) {
        const Lifetime& life = csg.children[k]->lifetime;
        const Lifetime base = life.intersect(none_before);
        if (!base.is_never()) {
            std::vector<IntelligentObjectPtr> members;
            for (std::size_t j = k; j < csg.children.size(); ++j)
                members.push_back(build(*csg.children[j], down));
            auto part =
                std::make_unique<CsgObject>(Csg::Kind::Difference, std::move(members), inverse);
            if (base.is_always())
                parts.push_back(std::move(part));
            else
                parts.push_back(std::make_unique<LifetimeObject>(std::move(part), base, false));
        }
        if (life.is_always()) break;
        none_before = none_before.intersect(life.complement_within(Interval::entire()));
        if (none_before.is_never()) break;
    }
    return std::make_unique<CsgObject>(Csg::Kind::Union, std::move(parts), false);
}

// The object, and where it lives only part of the time, wrapped in its
// lifetime.
// (The flags go on every object made for a record, wrappers and the
// primitive within alike: the walk asks the one in the hierarchy which
// rays see it, the shader asks the primitive hit how it is lit.)
IntelligentObjectPtr flagged(IntelligentObjectPtr object, const ObjectFlags& flags) {
    object->set_flags(flags);
    return object;
}

IntelligentObjectPtr build(const ObjectRecord& record, const Inherited& parent) {
    const ObjectFlags flags = handed_down(record, parent).flags;
    IntelligentObjectPtr object = flagged(build_object(record, parent), flags);
    const Lifetime lifetime = record.lifetime.intersect(parent.lifetime);
    if (lifetime.is_always()) return object;
    return flagged(
        std::make_unique<LifetimeObject>(std::move(object), lifetime, parent.in_intersection),
        flags);
}

// An object's clipped_by and bounded_by objects as intelligent objects,
// built once under its transform (`own`: what the record hands down) and
// shared by the members of a union split apart.
struct BuiltLimits {
    ClippedObject::Limits clips;
    BoundedObject::Limits bounds;
};
BuiltLimits build_limits(const ObjectRecord& record, const Inherited& own, int csg_depth) {
    BuiltLimits built;
    if (!record.limits) return built;
    if (csg_depth >= kMaxCsgDepth)
        throw ObjectError(record.place, "clipped_by, bounded_by and CSG nested more than " +
                                            std::to_string(kMaxCsgDepth) + " levels deep");
    // Written in the object's space (ObjectLimits); one that does not exist
    // at some instant limits nothing then.
    Inherited down = own;
    down.csg_depth = csg_depth + 1;
    down.lifetime = Lifetime::always();
    down.in_intersection = true;
    const auto make = [&](const std::vector<ObjectPtr>& records) {
        std::vector<IntelligentObjectPtr> objects;
        objects.reserve(records.size());
        for (const auto& r : records) objects.push_back(build(*r, down));
        return std::make_shared<const std::vector<IntelligentObjectPtr>>(std::move(objects));
    };
    if (!record.limits->clipped_by.empty()) built.clips = make(record.limits->clipped_by);
    if (!record.limits->bounded_by.empty()) built.bounds = make(record.limits->bounded_by);
    return built;
}

// POV-Ray tests the bounds before the object and the clips on each hit.
// `exact`, `box_always`: BoundedObject's.
IntelligentObjectPtr limited(IntelligentObjectPtr object, const BuiltLimits& limits, bool exact,
                             bool box_always) {
    if (limits.bounds)
        object =
            std::make_unique<BoundedObject>(std::move(object), limits.bounds, exact, box_always);
    if (limits.clips) object = std::make_unique<ClippedObject>(std::move(object), limits.clips);
    return object;
}

// Where POV-Ray keeps an object's bounded_by (Link_To_Frame, with
// Remove_Bounds on): inside a CSG object or a clip (never linked to the
// frame), and on a CSG object, a poly (and a quadric) or a text at the top.
bool keeps_bounds(const ObjectRecord& record, const Inherited& parent) {
    if (parent.csg_depth > 0) return true;
    return std::visit(
        [](const auto& shape) {
            using Kind = std::decay_t<decltype(shape)>;
            return std::is_same_v<Kind, Csg> || std::is_same_v<Kind, Text> ||
                   std::is_base_of_v<PolySurface, Kind>;
        },
        record.shape);
}

IntelligentObjectPtr build_object(const ObjectRecord& record, const Inherited& parent) {
    IntelligentObjectPtr object = build_shape(record, parent);
    if (!record.limits) return object;
    const ObjectFlags flags = object->flags();
    return flagged(limited(std::move(object),
                           build_limits(record, handed_down(record, parent), parent.csg_depth),
                           keeps_bounds(record, parent), false),
                   flags);
}

IntelligentObjectPtr build_shape(const ObjectRecord& record, const Inherited& parent) {
    Inherited own = handed_down(record, parent);
    if (record.interior) {
        own.media = nullptr;
        // (A density pattern hexant lacks throws, naming its place.)
        if (!own.interior->media.empty())
            own.media = std::make_shared<const MediaVolume>(own.interior->media);
    }
    const Transform& to_world = own.to_world;
    const std::optional<Interior>& interior = own.interior;

    if (const auto* csg = std::get_if<Csg>(&record.shape)) {
        if (parent.csg_depth >= kMaxCsgDepth)
            throw ObjectError(record.place, "CSG nested more than " + std::to_string(kMaxCsgDepth) +
                                                " levels deep (intersection, difference or merge "
                                                "inside one another)");
        Inherited down = own;
        down.interior_key = shared_interior(own.interior_key);
        down.csg_depth = parent.csg_depth + 1;
        down.lifetime = Lifetime::always();
        down.in_intersection = csg->kind == Csg::Kind::Intersection;
        if (csg->kind == Csg::Kind::Difference && !csg->children.empty() &&
            !csg->children.front()->lifetime.is_always())
            return flagged(build_difference_by_base(*csg, down, record.inverse), own.flags);
        const bool members_always =
            std::all_of(csg->children.begin(), csg->children.end(),
                        [](const ObjectPtr& child) { return child->lifetime.is_always(); });
        if (record.inverse && csg->kind != Csg::Kind::Difference && members_always) {
            // POV-Ray's Invert_CSG_Object: an inverted union or merge is
            // the intersection of its members inverted (a union's surfaces
            // inside another member are gone), an inverted intersection
            // their merge (csg.cpp, CSG::Invert and Morph).
            const Csg::Kind kind =
                csg->kind == Csg::Kind::Intersection ? Csg::Kind::Merge : Csg::Kind::Intersection;
            down.in_intersection = kind == Csg::Kind::Intersection;
            std::vector<IntelligentObjectPtr> children;
            children.reserve(csg->children.size());
            for (const auto& child : csg->children) {
                ObjectRecord inverted = *child;
                inverted.inverse = !inverted.inverse;
                children.push_back(build(inverted, down));
            }
            return flagged(std::make_unique<CsgObject>(kind, std::move(children), false),
                           own.flags);
        }
        std::vector<IntelligentObjectPtr> children;
        children.reserve(csg->children.size());
        for (const auto& child : csg->children) children.push_back(build(*child, down));
        // (A merge, intersection or difference is seen or hidden whole, by
        // its own flags: POV-Ray's kludge lets primary rays see its members
        // hidden by their own no_image.)
        return flagged(std::make_unique<CsgObject>(csg->kind, std::move(children), record.inverse),
                       own.flags);
    }
    TextureEvaluator evaluator(*own.texture, interior);
    evaluator.set_media(own.media);
    // (A mesh's faces with textures of their own are one interior.)
    std::shared_ptr<const void> key = own.interior_key;
    if (!key && std::visit(
                    [](const auto& shape) {
                        return requires {
                            shape.part_textures();
                        };
                    },
                    record.shape))
        key = shared_interior(nullptr);
    evaluator.set_interior_key(key);
    if (own.interior_texture) evaluator.set_interior_texture(*own.interior_texture, interior);
    const PrimitiveOptions options{record.inverse, own.no_shadow};
    return std::visit(
        [&](const auto& shape) -> IntelligentObjectPtr {
            using Kind = std::decay_t<decltype(shape)>;
            if constexpr (std::is_same_v<Kind, Csg>) {
                throw std::logic_error("make_intelligent_object: CSG handled above");
            } else {
                using Model = typename Kind::Model;
                if constexpr (requires { shape.standalone_error(); })
                    if (const auto refused = shape.standalone_error())
                        throw ObjectError(record.place, *refused);
                if (Primitive<Model>::kUnbounded && to_world.has_deformation())
                    throw ObjectError(record.place,
                                      "a " + std::string(Kind::keyword) +
                                          " cannot be twisted, tapered or bent (it has no bound "
                                          "to search in); deform a box or a polygon instead");
                // Textures of the kind's own parts (a mesh's faces), written
                // in its object space.
                std::vector<TextureEvaluator> parts;
                if constexpr (requires { shape.part_textures(); })
                    for (const Texture& part : shape.part_textures()) {
                        Texture world = part;
                        world.transform_by(to_world);
                        if (own.in_instance) world.transform_by(own.placement);
                        parts.emplace_back(world, interior);
                        parts.back().set_media(own.media);
                        parts.back().set_interior_key(key);
                    }
                // A model whose shape depends on its placement (a
                // bicubic_patch, which POV-Ray subdivides in the world)
                // is given it.
                if constexpr (std::is_constructible_v<Model, const Kind&, const Transform&>)
                    return flagged(std::make_unique<Primitive<Model>>(
                                       Model(shape, to_world), to_world, std::move(evaluator),
                                       options, std::move(parts)),
                                   own.flags);
                else
                    return flagged(std::make_unique<Primitive<Model>>(Model(shape), to_world,
                                                                      std::move(evaluator), options,
                                                                      std::move(parts)),
                                   own.flags);
            }
        },
        record.shape);
}

// An instance pays where a union under a moving transform has many members
// (each would otherwise be swept by the whole motion in the hierarchy); a
// few are as well apart, where the hierarchy can part them.
constexpr std::size_t kInstanceLeast = 16;

// Is the shape's model made for its placement in the world (a
// bicubic_patch, subdivided there)? Inside an instance it would get the
// union's space instead.
bool placed_in_world(const Shape& shape) {
    return std::visit(
        [](const auto& s) {
            using Kind = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<Kind, Csg>)
                return false;
            else
                return std::is_constructible_v<typename Kind::Model, const Kind&, const Transform&>;
        },
        shape);
}

// Can the union's members stand in an instance (instance_object.hpp)?
// Nothing about their shapes, places or presence changes with time (their
// textures may), and none has what the instance answers for as a whole: a
// flag of its own (no_shadow, no_image, no_reflection, double_illuminate,
// hollow, a light_group), an interior of its own. None whose shape or
// bounds are made in the world: a bicubic_patch's subdivision, a
// bounded_by's box (an axis-aligned box there, BoundedObject, would be one
// in the union's space, cutting otherwise as it turns). And at least
// kInstanceLeast objects once nested unions are split.
bool instanceable(const Csg& csg) {
    std::size_t objects = 0;
    std::vector<const ObjectRecord*> stack;
    for (const auto& child : csg.children) stack.push_back(child.get());
    while (!stack.empty()) {
        const ObjectRecord& r = *stack.back();
        stack.pop_back();
        if (!r.lifetime.is_always() || r.transform.depends_on_time() || r.no_shadow || r.no_image ||
            r.no_reflection || r.no_radiosity || r.photons != ObjectPhotons{} ||
            r.double_illuminate || r.hollow || r.light_group || r.interior)
            return false;
        if (r.limits) {
            if (!r.limits->bounded_by.empty()) return false;
            for (const auto& clip : r.limits->clipped_by)
                if (clip->depends_on_time() || placed_in_world(clip->shape)) return false;
        }
        if (placed_in_world(r.shape)) return false;
        const auto* inner = std::get_if<Csg>(&r.shape);
        if (!inner) {
            if (r.shape_depends_on_time()) return false;
            ++objects;
            continue;
        }
        // (A nested union is split into the instance's members, anything
        // else is one member: count it once, look at all of it.)
        if (inner->kind != Csg::Kind::Union || r.inverse || r.limits) ++objects;
        for (const auto& child : inner->children) stack.push_back(child.get());
    }
    return objects >= kInstanceLeast;
}

void build_split(const ObjectRecord& root, const Inherited& top, const ObjectOptions& options,
                 std::vector<IntelligentObjectPtr>& out);

// The union's members in its own space, under its transform `down` hands
// down (moving, affine): one instance, or null where a member turns out
// unbounded (a plane), which the hierarchy must keep apart.
IntelligentObjectPtr build_instance(const Csg& csg, const Inherited& down,
                                    const ObjectOptions& options) {
    Inherited local = down;
    local.placement = down.to_world;
    local.to_world = Transform{};
    local.in_instance = true;
    local.lifetime = Lifetime::always();
    std::vector<IntelligentObjectPtr> members;
    for (const auto& child : csg.children) build_split(*child, local, options, members);
    for (const auto& m : members)
        if (!m->bounded()) return nullptr;
    IntelligentObjectPtr object =
        flagged(std::make_unique<InstanceObject>(std::move(members), down.to_world), down.flags);
    if (down.lifetime.is_always()) return object;
    return flagged(
        std::make_unique<LifetimeObject>(std::move(object), down.lifetime, down.in_intersection),
        down.flags);
}

// A union's children become objects of their own, with what the union
// hands down; anything else is one object.
void build_split(const ObjectRecord& root, const Inherited& top, const ObjectOptions& options,
                 std::vector<IntelligentObjectPtr>& out) {
    // Depth first, members in order, on a stack of its own: unions nest as
    // deep as objects may (kMaxObjectDepth: a union built up in a loop), and
    // each level's inheritance (a texture, an interior) is too large for a
    // thread's stack at that depth (7,000 levels crashed the render).
    struct Pending {
        const ObjectRecord* record;
        std::shared_ptr<const Inherited> parent;
    };
    std::vector<Pending> stack{{&root, std::make_shared<const Inherited>(top)}};
    while (!stack.empty()) {
        const Pending pending = std::move(stack.back());
        stack.pop_back();
        const ObjectRecord& record = *pending.record;
        const Inherited& parent = *pending.parent;
        const auto* csg = std::get_if<Csg>(&record.shape);
        if (!csg || csg->kind != Csg::Kind::Union || record.inverse) {
            out.push_back(build(record, parent));
            continue;
        }
        auto down = std::make_shared<Inherited>(handed_down(record, parent));
        down->interior_key = shared_interior(down->interior_key);
        // (Its interior's media, one volume for all its members, as
        // build_shape makes a group's.)
        if (record.interior) {
            down->media = nullptr;
            if (!down->interior->media.empty())
                down->media = std::make_shared<const MediaVolume>(down->interior->media);
        }
        down->lifetime = record.lifetime.intersect(parent.lifetime);
        if (!record.limits && options.instances && !parent.in_instance &&
            down->to_world.depends_on_time() && !down->to_world.has_deformation() &&
            instanceable(*csg)) {
            if (IntelligentObjectPtr instance = build_instance(*csg, *down, options)) {
                out.push_back(std::move(instance));
                continue;
            }
        }
        if (!record.limits) {
            for (auto child = csg->children.rbegin(); child != csg->children.rend(); ++child)
                stack.push_back({child->get(), down});
            continue;
        }
        // Clipping or bounding a union is clipping or bounding each member
        // (a point is in the union's surface where it is in a member's; a
        // ray meets the bounds or not whichever member it tests). POV-Ray
        // keeps a clipped or bounded union whole, with its bounds (its
        // Split_Unions is off by default); one with a member of no finite
        // extent has a box of everything, so the bounds' box always gates it.
        const BuiltLimits limits = build_limits(record, *down, parent.csg_depth);
        std::vector<IntelligentObjectPtr> members;
        for (const auto& child : csg->children) build_split(*child, *down, options, members);
        const bool finite =
            std::all_of(members.begin(), members.end(), [](const auto& m) { return m->bounded(); });
        for (auto& member : members) {
            const ObjectFlags flags = member->flags();
            out.push_back(flagged(limited(std::move(member), limits, true, !finite), flags));
        }
    }
}

}  // namespace

IntelligentObjectPtr make_intelligent_object(const ObjectRecord& record,
                                             const Texture& default_texture) {
    return build(record, top_level(default_texture));
}

void make_intelligent_objects(const ObjectRecord& record, const Texture& default_texture,
                              std::vector<IntelligentObjectPtr>& out,
                              const ObjectOptions& options) {
    build_split(record, top_level(default_texture), options, out);
}

}  // namespace hexant::runtime
