// From the language's object records to the tracer's intelligent objects:
// one Primitive per shape, CsgObject for groups. A group's transform,
// texture, interior and no_shadow pass down into its children here, so that
// every primitive carries its whole object-to-world map and a group only
// combines its children's answers.
#pragma once

#include "runtime/objects/intelligent_object.hpp"
#include "runtime/objects/object.hpp"

namespace hexant::runtime {

// Throws ObjectError (naming where the object was written) for what the
// tracer cannot do: an unsupported pigment pattern in use, a deformed plane.
// `default_texture` is the scene's (#default) for objects that have none.
IntelligentObjectPtr make_intelligent_object(const ObjectRecord& record,
                                             const Texture& default_texture = Texture{});

// The same, with a union's children as objects of their own, recursively
// (POV-Ray's split_union, on by default for unions): the hierarchy then
// bounds and separates them like any objects, rather than testing a whole
// union whenever a ray meets its bound. A union is kept whole where
// splitting would change it: `inverse` (its inside matters to no parent
// here, but its flipped normals must stay flipped together), clipped_by
// or bounded_by (one clip for the whole), and merge, intersection and
// difference (their surfaces depend on each other).
// A union of many members that stand still inside it, under a moving
// transform, is one instance (instance_object.hpp) where `options` allow.
// Appends to `out`.
struct ObjectOptions {
    // Off: every member of such a union an object of its own, as before
    // instances (a comparison); off too wherever a ray may travel in time
    // (a finite speed of light), which an instance cannot meet.
    bool instances = true;
};
void make_intelligent_objects(const ObjectRecord& record, const Texture& default_texture,
                              std::vector<IntelligentObjectPtr>& out,
                              const ObjectOptions& options = {});

}  // namespace hexant::runtime
