#include "language/scene_queries.hpp"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "language/object_extent.hpp"
#include "language/value_ops.hpp"
#include "runtime/objects/object_factory.hpp"
#include "runtime/texture/material.hpp"

namespace hexant::language {

const runtime::IntelligentObject& QueriedObjects::placed(const runtime::ObjectPtr& record,
                                                         const runtime::Interval& time,
                                                         const char* what) {
    auto found = made_.find(record.get());
    if (found != made_.end()) return *found->second.second;
    if (changes_with_clock(*record, time))
        throw ValueError(std::string(what) +
                         " of an object whose shape, transforms or parts change with clock: "
                         "its answer would change with time, which hexant does not form for " +
                         what + " yet (ask of the object before it moves, then move it)");
    auto made = runtime::make_intelligent_object(*record, runtime::Texture{});
    const runtime::IntelligentObject& object = *made;
    made_.emplace(record.get(), std::pair{record, std::move(made)});
    return object;
}

std::optional<TraceHit> trace_object(const runtime::IntelligentObject& object,
                                     const glm::dvec3& origin, const glm::dvec3& direction,
                                     double t) {
    const double length = glm::length(direction);
    if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
    runtime::Ray4 ray;
    ray.origin = runtime::Event(origin, t);
    ray.direction = runtime::Event(direction / length, 0.0);
    const auto hit = object.intersect(ray, 0.0, std::numeric_limits<double>::infinity());
    if (!hit) return std::nullopt;
    const runtime::SurfacePoint surface = object.complete(ray, *hit);
    return TraceHit{glm::dvec3(surface.event), surface.geometric_normal};
}

bool inside_object(const runtime::IntelligentObject& object, const glm::dvec3& point, double t) {
    return object.inside(runtime::Event(point, t));
}

InsideFunction::InsideFunction(runtime::ObjectPtr record, bool moves)
    : record_(std::move(record)),
      object_(runtime::make_intelligent_object(*record_, runtime::Texture{})),
      moves_(moves) {}

double InsideFunction::at(int, const glm::dvec3& p, double t) const {
    return object_->inside(runtime::Event(p, t)) ? 1.0 : 0.0;
}

}  // namespace hexant::language
