// A scene object as the language builds it: a shape, its transform (which
// may include deformations), its texture and flags.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "runtime/motion/transform.hpp"
#include "runtime/objects/shapes.hpp"
#include "runtime/scene/light.hpp"
#include "runtime/source_place.hpp"
#include "runtime/texture/material.hpp"
#include "runtime/time/lifetime.hpp"

namespace hexant::runtime {

// How deep object records may nest (a union built up in a loop, `#declare
// O = union { object { O } sphere { ... } }`, nests one level a turn): at
// this depth reading, checking and rendering stay within the main thread's
// 8 MB stack; 15,000 levels overflowed it.
inline constexpr int kMaxObjectDepth = 10000;
// Where ObjectRecord::objects stops counting: past any limit.
inline constexpr std::uint64_t kManyObjects = std::uint64_t(1) << 62;
inline std::uint64_t add_objects(std::uint64_t a, std::uint64_t b) {
    return a >= kManyObjects - b ? kManyObjects : a + b;
}

// An object's clipped_by and bounded_by objects (POV-Ray's Clip and Bound
// lists), in the object's own space: written in the space around it, they
// are moved there by the inverse of the transforms the object had when
// they were read, so the object's later transforms move them with it (as
// POV-Ray's Parse_Object_Mods applies later transforms to them).
struct ObjectLimits {
    // Its surface is kept only inside every one of these (clipped_by).
    std::vector<std::shared_ptr<const ObjectRecord>> clipped_by;
    // It is tested only for rays that meet every one of these or start
    // inside it (bounded_by: POV-Ray's Ray_In_Bound), which cuts an object
    // larger than its bound the way POV-Ray does.
    std::vector<std::shared_ptr<const ObjectRecord>> bounded_by;
};

// light_group { }: a union whose own lights light only its members (and
// the members of groups within it); with global_lights its members are lit
// by the scene's other lights too (POV-Ray's Parse_Light_Group and
// Promote_Local_Lights). `id` is the group's index in the scene's
// light_groups, given when the object is added to the scene, each copy its
// own; -1 before.
struct LightGroupMark {
    bool global_lights = false;
    int id = -1;
};

struct ObjectRecord {
    Shape shape;
    Transform transform;             // object space to the parent's space
    std::optional<Texture> texture;  // none: inherit the parent's, or the default
    // interior_texture { }: what a ray meeting the surface from inside sees
    // (POV-Ray's Interior_Texture); null: the parent's, or none. Shared
    // between copies (most objects have none: a pointer keeps records small).
    std::shared_ptr<const Texture> interior_texture;
    BoxedOptional<Interior> interior;  // (boxed: most objects have none)
    bool no_shadow = false;
    // POV-Ray's no_image, no_reflection, double_illuminate (passed down to
    // a group's members, as its Parse_Object_Mods and Set_CSG_Tree_Flag).
    bool no_image = false;
    bool no_reflection = false;
    bool no_radiosity = false;  // hidden from radiosity's gathering rays
    ObjectPhotons photons;      // its photons { }
    bool double_illuminate = false;
    bool hollow = false;
    bool inverse = false;  // inside and outside swapped (CSG)
    // Objects nested in it and itself: 1, or 1 + its deepest CSG child's.
    // Everything that walks a record's children recurses, so the language
    // refuses records deeper than kMaxObjectDepth where they are made.
    int depth = 1;
    // Objects it makes for the render (language/limits.hpp, Limits::objects):
    // 1, or the sum of its CSG members' and its clipped_by and bounded_by
    // objects' (saturating at kManyObjects). Counted where it is made, so a
    // union doubled in a loop is refused before anything walks its members.
    std::uint64_t objects = 1;
    // When it exists: always, or the pieces of time of the clock-dependent
    // branches it was made under (Interpreter::domain, language/interpreter_state.hpp). Its CSG
    // children exist within it.
    Lifetime lifetime;
    // Light sources written inside a CSG move with it.
    std::vector<LightRecord> lights;
    std::optional<LightGroupMark> light_group;  // a union that is a light_group
    SourcePlace place;                          // where the object was written
    // What its own modifiers ask for that hexant lacks (photons, ...).
    std::vector<Unrendered> unrendered;
    // clipped_by and bounded_by; shared between copies, null when neither
    // is written (most objects: a pointer keeps records small).
    std::shared_ptr<const ObjectLimits> limits;

    // What its own shape makes of ObjectRecord::objects: none for a CSG
    // (its members count), what a kind says when it says (a text: its
    // glyphs), else one.
    std::uint64_t own_objects() const {
        return std::visit(
            [](const auto& s) -> std::uint64_t {
                if constexpr (std::is_same_v<std::decay_t<decltype(s)>, Csg>)
                    return 0;
                else if constexpr (requires { s.objects(); })
                    return std::max<std::uint64_t>(s.objects(), 1);
                else
                    return 1;
            },
            shape);
    }

    bool depends_on_time() const;  // anything about it
    bool shape_depends_on_time() const;
    // The names of the shape's parameters that depend on time ("center", ...).
    std::vector<std::string> timed_parameters() const;
    bool texture_depends_on_time() const;
};

}  // namespace hexant::runtime
