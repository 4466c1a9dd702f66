#include "runtime/objects/parameter_check.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "runtime/time/non_finite.hpp"

namespace hexant::runtime {

namespace {

std::string number(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

// The instants the renderer's time runs over.
struct Span {
    double begin, end;
    explicit Span(const Animation& a) : begin(a.time_begin()), end(a.time_end()) {
        if (end < begin) std::swap(begin, end);
    }
};

using Problem = std::optional<std::string>;

Problem check(const TimeFunction& f, const std::string& what, const Span& span) {
    const auto t = first_non_finite(f, span.begin, span.end);
    if (!t) return std::nullopt;
    const double v = f.is_constant() ? f.constant() : f(*t);
    const std::string kind = std::isnan(v) ? "NaN (not a number)" : "infinite";
    if (f.is_constant()) return what + " is " + kind;
    return what + " is " + kind + " at clock = " + number(*t);
}

template <std::size_t N>
Problem check(const std::array<TimeFunction, N>& c, const std::string& what, const Span& span) {
    for (const auto& f : c)
        if (auto p = check(f, what, span)) return p;
    return std::nullopt;
}

const char* step_name(TransformKind kind) {
    switch (kind) {
        case TransformKind::Translate:
            return "translate";
        case TransformKind::Rotate:
            return "rotate";
        case TransformKind::Scale:
            return "scale";
        case TransformKind::Matrix:
            return "matrix";
        case TransformKind::Twist:
            return "twist";
        case TransformKind::Taper:
            return "taper";
        case TransformKind::Bend:
            return "bend";
    }
    return "transform";
}

bool finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// Each step's amounts, then the whole map where it is affine: finite and
// invertible (a ray is taken into object space by its inverse) at the
// span's ends. A product of finite steps can still overflow (scale 1e200
// twice), and a `matrix` can be singular (POV-Ray: "Singular matrix").
Problem check(const Transform& transform, const std::string& whose, const Span& span) {
    for (const auto& step : transform.steps()) {
        const std::string what = whose + " " + step_name(step.kind);
        if (step.kind == TransformKind::Matrix) {
            for (std::size_t i = 0; i < 12; ++i)
                if (auto p = check(step.matrix[i], what, span)) return p;
        } else if (auto p = check(step.vector.c, what, span)) {
            return p;
        }
        if (step.is_deformation())
            if (auto p = check(step.amount, what, span)) return p;
    }
    if (transform.empty() || transform.has_deformation()) return std::nullopt;
    for (const double t : {span.begin, span.end}) {
        const glm::dmat4 m = transform.matrix_at(t);
        const std::string at = transform.depends_on_time() ? " at clock = " + number(t) : "";
        if (!finite(m))
            return whose + " transform is infinite" + at + " (its steps together overflow)";
        const double det = glm::determinant(glm::dmat3(m));
        if (!(std::fabs(det) > 0.0) || !std::isfinite(det))
            return whose + " transform is singular" + at +
                   " (it flattens space: no inverse to take rays into it)";
        if (!finite(glm::inverse(m))) return whose + " transform's inverse is infinite" + at;
    }
    return std::nullopt;
}

Problem check(const Texture& texture, const std::string& whose, const Span& span) {
    for (const auto& colour : texture.pigment.colours)
        if (auto p = check(colour.c, whose + " pigment's colour", span)) return p;
    for (const auto& entry : texture.pigment.colour_map.entries)
        if (auto p = check(entry.colour.c, whose + " colour map's colour", span)) return p;
    if (auto p = check(texture.pigment.transform, whose + " pigment's", span)) return p;
    const Finish& f = texture.finish;
    for (const Finish::Scalar& scalar : f.scalars())
        if (auto p = check(*scalar.value, whose + " finish's " + scalar.name, span)) return p;
    if (auto p = check(f.reflection.c, whose + " finish's reflection", span)) return p;
    if (f.reflection_max)
        if (auto p = check(f.reflection_max->c, whose + " finish's reflection maximum", span))
            return p;
    if (auto p = check(texture.uv_outside, whose + " texture's", span)) return p;
    return check(texture.transform, whose + " texture's", span);
}

// Each kind's parameters (runtime/objects/shape_kind.hpp), by type.
struct ShapeParameters {
    const Span& span;
    const std::string whose;
    Problem first;

    void operator()(const char*, const char* phrase, const TimeFunction& x) {
        if (!first) first = check(x, whose + " " + phrase, span);
    }
    void operator()(const char*, const char* phrase, const Vector3Function& x) {
        if (!first) first = check(x.c, whose + " " + phrase, span);
    }
    void operator()(const char*, const char* phrase, const Vector2Function& x) {
        if (!first) first = check(x.c, whose + " " + phrase, span);
    }
    void operator()(const char*, const char* phrase, const Transform& x) {
        if (!first) first = check(x, whose + " " + phrase, span);
    }
    template <typename T>
    void operator()(const char* name, const char* phrase, const std::vector<T>& items) {
        for (const auto& item : items) (*this)(name, phrase, item);
    }
    // Flags, strings and described parameters: nothing to evaluate.
    template <typename T>
    void operator()(const char*, const char*, const T&) {}
};

// 1 / |a - b|^2 as a time function: infinite exactly where a and b meet
// (in doubles: where the renderer's difference is the zero vector).
TimeFunction meeting(const Vector3Function& a, const Vector3Function& b) {
    TimeFunction sum(0.0);
    for (int i = 0; i < 3; ++i) {
        const TimeFunction d = a.c[i] - b.c[i];
        sum = sum + d * d;
    }
    return TimeFunction(1.0) / sum;
}

}  // namespace

std::optional<std::string> bad_parameter(const ObjectRecord& object, const Animation& animation) {
    const Span span(animation);
    const std::string whose = std::string("the ") + shape_name(object.shape) + "'s";
    ShapeParameters parameters{span, whose, std::nullopt};
    for_each_parameter(object.shape, parameters);
    if (parameters.first) return parameters.first;
    if (auto p = check(object.transform, whose, span)) return p;
    if (object.texture)
        if (auto p = check(*object.texture, whose, span)) return p;
    if (object.interior_texture)
        if (auto p = check(*object.interior_texture, whose + " interior_texture's", span)) return p;
    if (object.interior)
        if (auto p = check(object.interior->ior, whose + " interior's ior", span)) return p;
    return std::nullopt;
}

std::optional<std::string> bad_parameter(const Texture& texture, const std::string& whose,
                                         const Animation& animation) {
    return check(texture, whose, Span(animation));
}

std::optional<std::string> bad_parameter(const LightRecord& light, const Animation& animation) {
    const Span span(animation);
    if (auto p = check(light.position.c, "the light's position", span)) return p;
    if (auto p = check(light.colour.c, "the light's colour", span)) return p;
    if (auto p = check(light.point_at.c, "the light's point_at", span)) return p;
    for (const auto& [value, name] :
         {std::pair{&light.radius, "radius"}, std::pair{&light.falloff, "falloff"},
          std::pair{&light.tightness, "tightness"},
          std::pair{&light.fade_distance, "fade_distance"},
          std::pair{&light.fade_power, "fade_power"}})
        if (auto p = check(*value, std::string("the light's ") + name, span)) return p;
    if (light.area) {
        if (auto p = check(light.area->axis1.c, "the area_light's first axis", span)) return p;
        if (auto p = check(light.area->axis2.c, "the area_light's second axis", span)) return p;
        // (POV-Ray's rule: a circular grid maps its square shells to rings.)
        if (light.circular && (light.area->size1 <= 1 || light.area->size2 <= 1))
            return std::string("a circular area_light needs more than 1 light along each axis");
    }
    return check(light.transform, "the light's", span);
}

std::optional<std::string> bad_parameter(const CameraRecord& camera, const Animation& animation) {
    const Span span(animation);
    using K = CameraItem::Kind;
    const CameraItem *location = nullptr, *look_at = nullptr, *direction = nullptr;
    Transform transform;  // its steps, composed in order
    for (const CameraItem& item : camera.items) {
        switch (item.kind) {
            case K::Angle:
                if (auto p = check(item.angle, "the camera's angle", span)) return p;
                break;
            case K::Aperture:
                if (auto p = check(item.angle, "the camera's aperture", span)) return p;
                break;
            case K::BlurSamples:
                if (auto p = check(item.angle, "the camera's blur_samples", span)) return p;
                break;
            case K::FocalPoint:
                if (auto p = check(item.vector.c, "the camera's focal_point", span)) return p;
                break;
            case K::Transform:
                transform.append(item.step);
                break;
            case K::VerticalAngle:
                if (auto p = check(item.angle, "the camera's vertical angle", span)) return p;
                break;
            case K::Type:  // (a type's own meshes are checked as objects)
                break;
            case K::Location:
            case K::LookAt:
            case K::Direction:
            case K::Right:
            case K::Up:
            case K::Sky: {
                static const char* const names[] = {"location", "look_at", "direction",
                                                    "right",    "up",      "sky"};
                if (auto p = check(
                        item.vector.c,
                        std::string("the camera's ") + names[static_cast<int>(item.kind)], span))
                    return p;
                if (item.kind == K::Location) location = &item;
                if (item.kind == K::LookAt) look_at = &item;
                if (item.kind == K::Direction) direction = &item;
            }
        }
    }
    if (auto p = check(transform, "the camera's", span)) return p;
    // Where the renderer's camera would have no direction: found by the
    // same interval search, so an instant between the frames counts too.
    if (direction) {
        const Vector3Function zero{};
        if (const auto t = first_non_finite(meeting(direction->vector, zero), span.begin, span.end))
            return "the camera's direction is the zero vector" +
                   (direction->vector.depends_on_time() ? " at clock = " + number(*t) : "");
    }
    if (look_at) {
        const Vector3Function origin{};
        const Vector3Function& from = location ? location->vector : origin;
        if (const auto t = first_non_finite(meeting(look_at->vector, from), span.begin, span.end))
            return "the camera's look_at is its location" +
                   (camera.depends_on_time() ? " at clock = " + number(*t) : "") +
                   ": it looks nowhere";
    }
    // The rest of its rules (the angle's range, a transform that flattens
    // it) at each frame's clock and the span's end.
    std::vector<double> instants{span.end};
    if (camera.depends_on_time())
        for (int k = animation.initial_frame; k <= animation.final_frame; ++k)
            instants.push_back(animation.clock_of_frame(k));
    else
        instants = {span.begin};
    for (const double t : instants) {
        const std::string at = camera.depends_on_time() ? " at clock = " + number(t) : "";
        try {
            const CameraFrame frame = camera.evaluate(t);
            for (const auto& v : {frame.location, frame.direction, frame.right, frame.up})
                if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                    return "the camera is not finite" + at +
                           " (its vectors overflow, or its transform is singular)";
            if (!(glm::length(frame.direction) > 0.0))
                return "the camera's direction is the zero vector" + at;
        } catch (const std::domain_error& e) {
            std::string message = e.what();
            if (message.rfind("camera: ", 0) == 0) message = "the camera's " + message.substr(8);
            return message + at;
        }
    }
    return std::nullopt;
}

}  // namespace hexant::runtime
