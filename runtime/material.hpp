// Surface appearance records, after POV-Ray's texture model: a pigment, a
// finish and an interior. Every number may be a function of time.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "runtime/pattern/pattern.hpp"
#include "runtime/source_place.hpp"
#include "runtime/transform.hpp"
#include "runtime/vector_function.hpp"

namespace hexant::runtime {

// A colour map's entry as the scene wrote it: at `value`, `colour`.
struct ColourMapEntry {
    TimeFunction value;
    ColourFunction colour;
};

// color_map { [v colour] ... } (a value of its own: it may be declared).
struct ColourMap {
    std::vector<ColourMapEntry> entries;  // in order of value
    bool depends_on_time() const;
};

struct Pigment {
    enum class Pattern { Solid, Patterned, Unsupported };
    Pattern pattern = Pattern::Solid;
    // Solid: colours[0].
    std::vector<ColourFunction> colours = std::vector<ColourFunction>(1);
    // Patterned: the pattern (runtime/pattern/pattern.hpp) and its colour
    // map; an empty map is the kind's default. A block pattern's colour
    // list (checker's two) is its map, at values 0, 1, 2.
    pattern::Pattern patterned;
    ColourMap colour_map;
    // The transforms written after the pattern's last warp (all of them,
    // without warps): pattern space to object space.
    Transform transform;
    // For Unsupported: the pattern's name and where it was written, so that
    // using it reports a clear error.
    std::string unsupported_name;
    SourcePlace unsupported_place;

    bool depends_on_time() const;
};

// POV-Ray 3.7's finish and its defaults.
struct Finish {
    TimeFunction ambient = 0.1;
    TimeFunction diffuse = 0.6;
    TimeFunction brilliance = 1.0;
    TimeFunction phong = 0.0;
    TimeFunction phong_size = 40.0;
    TimeFunction specular = 0.0;
    TimeFunction roughness = 0.05;
    ColourFunction reflection{};  // rgb; zero means none
    TimeFunction emission = 0.0;
};

struct Interior {
    TimeFunction ior = 1.0;
};

struct Texture {
    Pigment pigment;
    Finish finish;
    Transform transform;  // texture space to object space
    bool has_normal = false;  // a `normal { }` was given; hexant ignores it
};

}  // namespace hexant::runtime
