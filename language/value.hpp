// The values a scene's expressions and declarations produce. Floats and
// vector components are time functions (constant unless they use `clock`).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <tao/pegtl/position.hpp>

#include "language/memory_budget.hpp"
#include "language/timed_string.hpp"
#include "runtime/motion/spline.hpp"
#include "runtime/motion/transform.hpp"
#include "runtime/objects/object.hpp"
#include "runtime/scene/camera.hpp"
#include "runtime/scene/light.hpp"
#include "runtime/scene/sky_sphere.hpp"
#include "runtime/texture/material.hpp"
#include "runtime/time/user_function.hpp"

namespace hexant::language {

using runtime::TimeFunction;

// 2 to 5 components; colours are 5 (red, green, blue, filter, transmit).
struct Vector {
    int size = 3;
    std::array<TimeFunction, 5> c{};
};

// A declaration hexant keeps as source only (a `function {}`, a pattern or
// object kind it lacks): an error where it is used, never where declared.
struct Unevaluated {
    std::string what;  // e.g. "function", "isosurface"
    tao::pegtl::position where;
};

struct Macro {
    std::string name;
    std::vector<std::string> parameters;
    const char* body_begin;  // into a source buffer that outlives the parse
    const char* body_end;
    tao::pegtl::position body_position;
    tao::pegtl::position defined_at;
};

// material { texture { } interior { } }: what it gives an object, each
// part only when written (POV-Ray's MATERIAL).
struct Material {
    std::optional<runtime::Texture> texture;
    std::optional<runtime::Interior> interior;
};

struct Value;
struct Array {
    std::vector<int> dimensions;
    std::vector<std::optional<std::shared_ptr<Value>>> elements;  // row-major
    MemoryCharge charge;  // its slots and the values set in them
};

struct Value {
    using Variant =
        std::variant<TimeFunction, Vector, std::string, TimedString, runtime::ObjectPtr,
                     runtime::LightRecord, runtime::CameraRecord, runtime::Texture,
                     runtime::Pigment, runtime::Normal, runtime::ColourMap, runtime::SkySphere,
                     runtime::Finish, runtime::Interior, runtime::Media, Material,
                     runtime::Transform, std::shared_ptr<Array>,
                     std::shared_ptr<const runtime::Spline>, std::shared_ptr<const Macro>,
                     std::shared_ptr<const runtime::UserFunction>, Unevaluated>;
    Variant v;

    template <typename T>
    bool is() const {
        return std::holds_alternative<T>(v);
    }
    template <typename T>
    const T& as() const {
        return std::get<T>(v);
    }
    template <typename T>
    T& as() {
        return std::get<T>(v);
    }
};

// What Array::charge counts (language/memory_budget.hpp): a slot, and a
// value set in one (the shared value, its control block, a string's
// characters; an array set in one carries its own charge).
inline constexpr std::size_t kArraySlotBytes = sizeof(std::optional<std::shared_ptr<Value>>);
inline std::size_t string_bytes(const Value& value) {
    if (value.is<std::string>()) return value.as<std::string>().size();
    if (!value.is<TimedString>()) return 0;
    std::size_t n = 0;
    for (const auto& piece : value.as<TimedString>().pieces) n += sizeof piece + piece.text.size();
    return n;
}
inline std::size_t element_bytes(const Value& value) {
    return sizeof(Value) + 2 * sizeof(void*) + string_bytes(value);
}
// Dimensions are int; the memory limit is the one that binds first.
inline constexpr long long kMaxArrayElements = 2147483647;

// "float", "vector", "object" ... for messages.
std::string type_name(const Value& value);

}  // namespace hexant::language
