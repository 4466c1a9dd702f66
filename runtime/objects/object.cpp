#include "runtime/objects/object.hpp"

#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace hexant::runtime {

const char* shape_name(const Shape& shape) {
    if (const auto* csg = std::get_if<Csg>(&shape)) {
        static const char* kinds[] = {"union", "merge", "intersection", "difference"};
        return kinds[static_cast<int>(csg->kind)];
    }
    // Keywords are string literals: data() ends in a '\0'.
    return std::visit(
        [](const auto& s) -> const char* {
            if constexpr (std::is_same_v<std::decay_t<decltype(s)>, Csg>)
                return "";
            else
                return std::decay_t<decltype(s)>::keyword.data();
        },
        shape);
}

namespace {

bool varies(const TimeFunction& f) {
    return f.depends_on_time();
}
bool varies(const Vector3Function& v) {
    return v.depends_on_time();
}
bool varies(const Vector2Function& v) {
    return v.depends_on_time();
}
bool varies(const Transform& t) {
    return t.depends_on_time();
}
template <typename T>
bool varies(const std::vector<T>& items) {
    for (const auto& item : items)
        if (varies(item)) return true;
    return false;
}
// Flags, strings and described parameters are fixed when the scene is read.
template <typename T>
bool varies(const T&) {
    return false;
}

}  // namespace

std::vector<std::string> ObjectRecord::timed_parameters() const {
    std::vector<std::string> names;
    if (const auto* csg = std::get_if<Csg>(&shape)) {
        for (const auto& child : csg->children)
            if (child->depends_on_time()) return {"children"};
        return names;
    }
    for_each_parameter(shape, [&](const char* name, const char*, const auto& value) {
        if (varies(value)) names.emplace_back(name);
    });
    return names;
}

bool ObjectRecord::shape_depends_on_time() const {
    return !timed_parameters().empty();
}

bool ObjectRecord::texture_depends_on_time() const {
    return (texture && texture->depends_on_time()) ||
           (interior_texture && interior_texture->depends_on_time());
}

bool ObjectRecord::depends_on_time() const {
    if (!lifetime.is_always() || shape_depends_on_time() || transform.depends_on_time() ||
        texture_depends_on_time() || (interior && varies(interior->ior)))
        return true;
    if (limits)
        for (const auto* list : {&limits->clipped_by, &limits->bounded_by})
            for (const auto& clip : *list)
                if (clip->depends_on_time()) return true;
    return false;
}

}  // namespace hexant::runtime
