// A scene object as the language builds it: a shape, its transform (which
// may include deformations), its texture and flags.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "runtime/light.hpp"
#include "runtime/material.hpp"
#include "runtime/shapes.hpp"
#include "runtime/source_place.hpp"
#include "runtime/transform.hpp"

namespace hexant::runtime {

struct ObjectRecord {
    Shape shape;
    Transform transform;  // object space to the parent's space
    std::optional<Texture> texture;  // none: inherit the parent's, or the default
    std::optional<Interior> interior;
    bool no_shadow = false;
    bool hollow = false;
    bool inverse = false;  // inside and outside swapped (CSG)
    // Light sources written inside a CSG move with it.
    std::vector<LightRecord> lights;
    SourcePlace place;  // where the object was written

    bool depends_on_time() const;  // anything about it
    bool shape_depends_on_time() const;
    // The names of the shape's parameters that depend on time ("center", ...).
    std::vector<std::string> timed_parameters() const;
    bool texture_depends_on_time() const;
};

}  // namespace hexant::runtime
