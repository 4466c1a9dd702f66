// The messages an object answers for the tracer, after Glassner's
// "intelligent objects": each object knows its own motion and deformation and
// answers, for itself, where it may be (bound), where a ray meets it
// (intersect), what it looks like there (complete) and how much of a region
// it fills (occupancy). Nothing here knows the hierarchy.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "runtime/bounds/slab_bound.hpp"
#include "runtime/geometry/spacetime.hpp"
#include "runtime/texture/material_sample.hpp"

namespace hexant::runtime {

class IntelligentObject;

// A surface event found by intersect(): enough for complete() to finish the
// job without solving again.
struct ObjectHit {
    double s = 0.0;  // ray parameter: the event is ray.at(s)
    Event event{};
    const IntelligentObject* object = nullptr;  // the primitive hit (inside groups too)
    // Inside an instance (instance_object.hpp): `object` is the instance,
    // and this the primitive hit among its members, in the members' space
    // (object_point, object_normal, part and the rest are that primitive's).
    const IntelligentObject* member = nullptr;
    glm::dvec3 object_point{};   // in the primitive's own (undeformed) space
    glm::dvec3 object_normal{};  // geometric normal there, unit
    glm::dvec3 object_shading_normal{};
    glm::dvec2 uv{};
    int part = 0;  // which face, cap or side (per shape kind)
    // The object-to-world map's linear part at the hit's time, when the
    // intersection had it at hand (a moving undeformed object), so that
    // complete() does not evaluate the motion again.
    glm::dmat3 to_world_linear{1.0};
    bool has_linear = false;
    // The normal points into the solid the scene sees (a difference's cut,
    // an `inverse` object): complete() turns it around.
    bool flipped = false;
    // SurfaceHit::error: a bound on object_point's distance from the exact
    // surface, in the primitive's space (zero where none is known);
    // complete() carries it into the world.
    glm::dvec3 object_error{0.0};
};

// What complete() returns: world-space normals at the hit's time, texture
// coordinates and the texture to evaluate at the hit's time and place.
class TextureEvaluator;
class MediaVolume;

struct SurfacePoint {
    Event event{};
    glm::dvec3 geometric_normal{};  // unit; for solids outward, for flat shapes their own side
    glm::dvec3 shading_normal{};    // unit; faces the same side as geometric_normal
    glm::dvec2 uv{};
    // The texture: the shader asks it for the material and the perturbed
    // normals at `event` after turning the normal to face the ray.
    const TextureEvaluator* texture = nullptr;
    // Where a kind blends textures by weight at the point (a blob whose
    // components have textures: POV-Ray's Determine_Textures), those
    // textures and weights, which the shader then lights in place of
    // `texture` alone (which still gives the interior's fade and
    // caustics). Empty otherwise; all weights 0 is black, as in POV-Ray.
    struct Blended {
        const TextureEvaluator* texture;
        double weight;
    };
    std::vector<Blended> blend;
    bool blended = false;
    glm::dvec3 error{0.0};  // world bound of event's error (geometry::world_error): what a
                            // secondary ray must clear
};

// Which rays an object is hidden from (POV-Ray's no_image and
// no_reflection, trace.cpp's NoSomethingFlagRayObjectCondition), as bits
// of a ray's kind: an image ray is a primary ray or one refracted from it,
// a reflection ray one reflected anywhere on its way from the eye.
enum RaySight : std::uint8_t {
    kSightAll = 0,  // shadow rays and queries: every object
    kSightImage = 1,
    kSightReflection = 2,
    // A ray radiosity gathers along, and every ray traced from its hit
    // (POV-Ray's IsRadiosityRay): no_radiosity objects are passed by.
    kSightRadiosity = 4,
    // A photon being shot (tracer/shader_photons.cpp): no_shadow objects
    // (a light's looks_like among them) are passed by, as POV-Ray's
    // photon rays pass them.
    kSightPhoton = 8,
};

// What an object (a primitive, a group, a wrapper) carries of its record's
// flags and its parents': the rays it is hidden from, and
// double_illuminate (lit by lights behind its surface too).
struct ObjectFlags {
    std::uint8_t hidden_from = 0;  // RaySight bits
    bool double_illuminate = false;
    // `hollow`: a ray inside it is fogged (POV-Ray's IsHollowRay); inside
    // a solid one it is not.
    bool hollow = false;
    // Inside a light_group: not lit by the scene's lights (its outermost
    // group's global_lights off), and the innermost group, whose lights
    // and whose enclosing groups' lights light it (-1: none).
    bool no_global_lights = false;
    std::int32_t light_group = -1;
    // photons { } (runtime/scene/photon_settings.hpp), a group's handed to
    // its members over their own (POV-Ray's Post_Process). photon_target:
    // the spacing factor of the target it belongs to (0: none) and that
    // target's number, the same for all its members (POV-Ray's
    // IsObjectInCSG: a photon shot at a union may meet any member first).
    float photon_target = 0.0f;
    std::int32_t photon_group = -1;
    std::int8_t photon_refraction = 0, photon_reflection = 0;  // 1 on, -1 off, 0 unsaid
    bool photon_collect = true;
    bool photon_pass_through = false;
};

class IntelligentObject {
  public:
    virtual ~IntelligentObject() = default;

    const ObjectFlags& flags() const { return flags_; }
    void set_flags(const ObjectFlags& flags) { flags_ = flags; }

    // False for objects without a finite extent (a plane): the tracer keeps
    // them outside the hierarchy and tests them on every ray.
    virtual bool bounded() const { return true; }
    // Does its solid (where inside() holds) lie inside the box of its
    // surface (box_over, bound)? Then what must be inside it (an
    // intersection's surface, a clipped object's) is bounded by its
    // bounds. Not for an unbounded object, nor an `inverse` one (its solid
    // is all that lies outside its surface).
    virtual bool solid_bounded() const { return bounded(); }

    // Appends to `out` one or more 12-slab bounds that together contain every
    // surface event of the object inside `region`. Conservative always; an
    // object whose surface has no event in the region may append nothing.
    virtual void bound(const Box4& region, std::vector<SlabBound>& out) const = 0;

    // A box around every surface event of the object at times in `t`: its
    // space part holds the surface at every instant of t, its time part is
    // t. Conservative always (interval evaluation), tight when t is short;
    // empty when the object has no surface then. The hierarchy caches these
    // over pieces of time (tracer/.., runtime/bounds/time_sweep.hpp) and clips them
    // to its cells; bound() answers the same question for one region.
    virtual Box4 box_over(const Interval& t) const = 0;

    // For sweeps by chords (runtime/bounds/time_sweep.hpp): over t, per world axis,
    // a bound on the second time derivative of the position of every point
    // the object's surface may occupy (`acceleration`), and `margin`, which
    // covers how far the exact positions at any instant may lie outside
    // placed_box_at() there, plus how far the double placement the tracer
    // uses may stray from the exact one. Then a line between placed boxes at
    // t0 and t1, moved out by (t1 - t0)^2 / 8 * acceleration + margin, holds
    // the surface at every instant between. Nothing where no such bound is
    // known (deformations, jumps or kinks in the motion, a changing shape).
    struct ChordBound {
        glm::dvec3 acceleration{0.0};
        glm::dvec3 margin{0.0};
    };
    virtual std::optional<ChordBound> chord_bound_over(const Interval&) const {
        return std::nullopt;
    }
    // A box around the surface at instant t as the double placement puts
    // it (the ends of the chords above); box_over(t) where there is no
    // cheaper answer.
    virtual Box4 placed_box_at(double t) const { return box_over(Interval(t)); }

    // The first surface event along `ray` with s_min < s < s_max.
    virtual std::optional<ObjectHit> intersect(const Ray4& ray, double s_min,
                                               double s_max) const = 0;

    // Is there a surface event along `ray` with s_min < s < s_max? The
    // any-hit question of shadow rays (pbrt's IntersectP): an object may
    // answer it without forming the hit.
    virtual bool occluded(const Ray4& ray, double s_min, double s_max) const {
        return intersect(ray, s_min, s_max).has_value();
    }

    // Normals, texture coordinates and material at a hit this object returned.
    virtual SurfacePoint complete(const Ray4& ray, const ObjectHit& hit) const = 0;

    // A primitive's: the linear part of its map to the space it was built
    // in at time t (the Jacobian at `object_point` where it is deformed),
    // which an instance around it (instance_object.hpp) composes with its
    // own placement. Throws std::logic_error for anything but a primitive.
    virtual glm::dmat3 to_world_linear_at(const glm::dvec3&, double) const {
        throw std::logic_error("to_world_linear_at: not a primitive");
    }

    // Is the event inside the object's solid (POV-Ray's inside, with
    // `inverse`)? Flat objects have no inside.
    virtual bool inside(const Event& event) const = 0;

    // The fraction of the region's 4D volume that the object's solid fills,
    // in [0, 1]; for the hierarchy's density criterion.
    virtual double occupancy(const Box4& region) const = 0;

    // Does anything about the object change with time?
    virtual bool moves() const = 0;
    // Is its map to world space non-affine (twist, taper, bend)?
    virtual bool deformed() const = 0;
    // Does its surface lie in one plane at every instant (a plane, disc,
    // triangle or polygon under an affine placement)? Then a ray at one
    // instant that starts off that plane and heads away from it cannot
    // meet it: a shadow ray leaving it need not test it (tracer/shader.cpp).
    virtual bool flat() const { return false; }
    // Is its solid convex at every instant, with its surface's normals
    // facing out (a sphere or a box under an affine placement, not
    // `inverse`)? Then a ray at one instant that starts outside and heads
    // away from the surface's tangent plane cannot meet it either.
    virtual bool convex() const { return false; }
    // Does it cast shadows (no no_shadow)?
    virtual bool casts_shadow() const { return true; }
    // May light pass it (a texture that filters or transmits somewhere:
    // POV-Ray's objects without OPAQUE_FLAG)? Then a shadow ray does not
    // stop at it (`occluded` passes it by) but takes the colour of each of
    // its surfaces it crosses (tracer/shader.cpp, filtered shadows).
    virtual bool filters_light() const { return false; }
    // casts_shadow() and not filters_light(): what the any-hit shadow query
    // asks of every object it meets (one call).
    virtual bool casts_full_shadow() const { return casts_shadow() && !filters_light(); }
    // The media of its interior (interior { media { } }), or null: what a
    // ray that starts inside its solid (a camera inside) passes through.
    virtual const MediaVolume* interior_media() const { return nullptr; }
    // Its interior as refraction knows it at time t (the identity its
    // surfaces' hits carry, TextureEvaluator::interior_key, and its ior):
    // what a camera ray that starts inside it has entered.
    // (`once`: entered once however many objects sharing it hold the eye;
    // else once per object, as POV-Ray's InitRayContainerState lists the
    // members of a union it split apart, each with the union's interior.)
    struct RefractiveInterior {
        const void* key = nullptr;  // null: none
        double ior = 1.0;
        bool once = false;
        double dispersion = 1.0;  // Interior::dispersion (1: none)
        int dispersion_samples = 7;
    };
    virtual RefractiveInterior refractive_interior(double) const { return {}; }

  private:
    ObjectFlags flags_;
};

using IntelligentObjectPtr = std::unique_ptr<IntelligentObject>;

}  // namespace hexant::runtime
