// A scene object as the language builds it: a shape, its transform (which
// may include deformations), its texture and flags.
#pragma once

#include <memory>
#include <optional>
#include <string>
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

struct ObjectRecord {
    Shape shape;
    Transform transform;             // object space to the parent's space
    std::optional<Texture> texture;  // none: inherit the parent's, or the default
    std::optional<Interior> interior;
    bool no_shadow = false;
    bool hollow = false;
    bool inverse = false;  // inside and outside swapped (CSG)
    // Objects nested in it and itself: 1, or 1 + its deepest CSG child's.
    // Everything that walks a record's children recurses, so the language
    // refuses records deeper than kMaxObjectDepth where they are made.
    int depth = 1;
    // When it exists: always, or the pieces of time of the clock-dependent
    // branches it was made under (Interpreter::domain, language/interpreter_state.hpp). Its CSG
    // children exist within it.
    Lifetime lifetime;
    // Light sources written inside a CSG move with it.
    std::vector<LightRecord> lights;
    SourcePlace place;  // where the object was written
    // What its own modifiers ask for that hexant lacks (clipped_by, ...).
    std::vector<Unrendered> unrendered;

    bool depends_on_time() const;  // anything about it
    bool shape_depends_on_time() const;
    // The names of the shape's parameters that depend on time ("center", ...).
    std::vector<std::string> timed_parameters() const;
    bool texture_depends_on_time() const;
};

}  // namespace hexant::runtime
