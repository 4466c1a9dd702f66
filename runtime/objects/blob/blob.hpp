// POV-Ray's blob { threshold T  sphere { <C>, R, [strength] S }
// cylinder { <A>, <B>, R, [strength] S }  component S, R, <C>  [sturm]
// [hierarchy B] }: the surface where the sum of its components' fields
// equals the threshold (blob_geometry.hpp). The object kind
// (runtime/objects/shape_kind.hpp); its block is read by a rule of its own
// (language/grammar.hpp, blob_block), which adds each component through
// add_component; `threshold` and `hierarchy` are its settings.
//
// Every centre, radius and strength, and the threshold, may be a function
// of time: a blob whose spheres move and merge with clock is one object.
// A component may carry its own transforms (affine, possibly moving) and
// texture, as POV-Ray's Parse_Blob_Element_Mods reads them: the transforms
// map the component's space into the blob's, and where any component has a
// texture the blob's textures are blended at a hit by each component's
// |field| there (POV-Ray's Blob::Determine_Textures), a component without
// one lending the blob's.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/motion/transform.hpp"
#include "runtime/objects/blob/blob_geometry.hpp"
#include "runtime/objects/shape_kind.hpp"
#include "runtime/texture/material.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class BlobModel;
}  // namespace objects

struct Blob {
    static constexpr std::string_view keyword = "blob";
    static constexpr bool kOwnSyntax = true;
    static constexpr std::array<std::string_view, 2> settings{"hierarchy", "threshold"};
    using Model = objects::BlobModel;

    TimeFunction threshold = 1.0;  // POV-Ray's default
    // Component i: kinds[i], its centre (or a cylinder's base) a[i], a
    // cylinder's apex b[i] (a sphere's centre again), radii[i], strengths[i].
    std::vector<geometry::BlobComponent::Kind> kinds;
    std::vector<Vector3Function> a, b;
    std::vector<TimeFunction> radii, strengths;
    // Component i's own transforms (empty: none), and its texture: an index
    // into `textures` (in the blob's space, moved by the component's
    // transforms written after it), or -1 for the blob's own.
    std::vector<Transform> transforms;
    std::vector<int> texture_index;
    std::vector<Texture> textures;

    // One component from its block's values: `kind` is "sphere" (centre,
    // radius, strength), "cylinder" (two ends, radius, strength) or
    // "component" (POV-Ray 3.1's strength, radius, centre). Throws through
    // `args` when the values are not those.
    void add_component(std::string_view kind, const objects::ShapeArguments& args);
    // The last component's own transforms and texture.
    void set_component_modifiers(Transform transform, std::optional<Texture> texture);
    // The component textures (as a mesh's texture_list: the factory maps
    // them to the world with the blob).
    const std::vector<Texture>& part_textures() const { return textures; }
    void set(std::string_view setting, const objects::ShapeArguments& value);
    template <class F>
    void parameters(F&& f) const {
        std::size_t cylinders = 0;
        for (const auto k : kinds) cylinders += k == geometry::BlobComponent::Kind::cylinder;
        f("components", "components",
          objects::DescribedParameter{std::to_string(kinds.size() - cylinders) + " spheres, " +
                                      std::to_string(cylinders) + " cylinders"});
        f("threshold", "threshold", threshold);
        f("a", "a blob component's centre or base", a);
        f("b", "a blob cylinder's apex", b);
        f("radii", "a blob component's radius", radii);
        f("strengths", "a blob component's strength", strengths);
        f("transforms", "a blob component's transform", transforms);
        f("textures", "textures", objects::DescribedParameter{std::to_string(textures.size())});
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/blob/blob_model.hpp"
