// The shapes a scene may hold: one of the registered object kinds
// (runtime/objects/kinds.hpp), each a plain record in object space with
// POV-Ray's parameters and defaults, any of which may be a function of time;
// or a CSG group of objects. The tracer's intelligent objects are built
// from these.
#pragma once

#include <memory>
#include <variant>
#include <vector>

#include "runtime/objects/kinds.hpp"

namespace hexant::runtime {

struct ObjectRecord;
using ObjectPtr = std::shared_ptr<const ObjectRecord>;

struct Csg {
    enum class Kind { Union, Merge, Intersection, Difference };
    Kind kind = Kind::Union;
    std::vector<ObjectPtr> children;
};

namespace shape_detail {
template <class List>
struct ShapeVariant;
template <class... K>
struct ShapeVariant<objects::KindList<K...>> {
    using type = std::variant<K..., Csg>;
};
}  // namespace shape_detail

using Shape = shape_detail::ShapeVariant<ShapeKinds>::type;

// The kind's keyword, or the CSG's ("union", "difference", ...).
const char* shape_name(const Shape& shape);

// f(name, phrase, value) for each of the shape's own parameters (none for a
// CSG), as runtime/objects/shape_kind.hpp describes.
template <class F>
void for_each_parameter(const Shape& shape, F&& f) {
    std::visit(
        [&](const auto& s) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(s)>, Csg>) s.parameters(f);
        },
        shape);
}

}  // namespace hexant::runtime
