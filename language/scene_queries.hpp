// POV-Ray's trace() and inside(): questions a scene asks of an object while
// it is being read (parser_expressions.cpp's Parse_Trace and Parse_Inside),
// answered by the object's own intelligent object, as the renderer would.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "runtime/objects/intelligent_object.hpp"
#include "runtime/objects/shapes.hpp"
#include "runtime/time/interval.hpp"
#include "runtime/time/point_function.hpp"

namespace hexant::language {

// The intelligent objects made for queries, kept by the record they were
// made from: a scene tracing one object thousands of times (tracevines.pov)
// builds it once.
class QueriedObjects {
  public:
    // The object of `record` at rest, over `time`. Throws ValueError (naming
    // `what`) for an object whose shape, transforms or parts change with
    // clock: its answers would be functions of time, which hexant does not
    // form for these yet.
    const runtime::IntelligentObject& placed(const runtime::ObjectPtr& record,
                                             const runtime::Interval& time, const char* what);

  private:
    std::map<const runtime::ObjectRecord*,
             std::pair<runtime::ObjectPtr, runtime::IntelligentObjectPtr>>
        made_;
};

// trace(OBJECT, A, B [, N]): the first point where the ray from `origin` in
// direction `direction` (normalized here, as POV-Ray does) meets the
// object, with its outward normal (unit; turned for an `inverse` object);
// none when it misses (POV-Ray then gives <0, 0, 0> for both). A zero
// direction misses. `t`: the instant of the scene being read.
struct TraceHit {
    glm::dvec3 point, normal;
};
std::optional<TraceHit> trace_object(const runtime::IntelligentObject& object,
                                     const glm::dvec3& origin, const glm::dvec3& direction,
                                     double t);

// inside(OBJECT, P): whether P is inside the object's solid (POV-Ray's
// Inside_Object, `inverse` included).
bool inside_object(const runtime::IntelligentObject& object, const glm::dvec3& point, double t);

// The object pattern's test (runtime/texture/pattern/kinds/object.hpp): 1
// where (x, y, z) is inside the object at time t, else 0. Its intelligent
// object is made once and answers for every instant, so an object that
// moves with clock moves its pattern too. Throws what
// make_intelligent_object throws for an object it cannot make.
class InsideFunction : public runtime::PointFunction {
  public:
    InsideFunction(runtime::ObjectPtr record, bool moves);
    std::string name() const override { return "object pattern"; }
    int components() const override { return 1; }
    bool depends_on_time() const override { return moves_; }
    double at(int component, const glm::dvec3& p, double t) const override;

  private:
    runtime::ObjectPtr record_;
    std::shared_ptr<const runtime::IntelligentObject> object_;
    bool moves_;
};

}  // namespace hexant::language
