// POV-Ray's user functions, `#declare F = function(x, y, z) { ... }`: a
// float function of its parameters and of time (clock keeps its meaning in
// a body, as in every other expression). The body is a time function whose
// Argument(k) nodes stand for parameter k; a call substitutes the call's
// arguments (substitute_arguments), so calls inline and a function calling
// functions is one tape. functions.inc's internal(N) functions are bodies
// built from the same operations (language/function_internals.cpp), and
// SpaceFunction compiles a body of (x, y, z) for the tracer: one tape, with
// point, interval and derivative evaluators (runtime/time/time_tape.hpp).
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/time/dual.hpp"
#include "runtime/time/interval.hpp"
#include "runtime/time/time_function.hpp"
#include "runtime/time/time_tape.hpp"

namespace hexant::runtime {

struct UserFunction {
    std::vector<std::string> parameters;  // names in order; x, y, z unless given
    TimeFunction body;                    // Argument(k) is parameters[k]
    // A function of a vector's value (a pigment function's five channels,
    // runtime/texture/pigment_function.hpp): its components, each a body;
    // `body` is then unused. Empty for a float function.
    std::vector<TimeFunction> components;
    // functions.inc's f_noise3d and f_noise_generator: POV-Ray's noise, with
    // the scene's generator (read where the function is called) or the
    // call's fourth argument (language/actions/literals.hpp,
    // call_user_function). `body` is the noise of the default generator.
    enum class Noise { None, SceneGenerator, ArgumentGenerator } noise = Noise::None;
    // Set for an internal function hexant lacks ("f_boy_surface"): the
    // declaration reads (functions.inc declares them all), a call is an error.
    std::string unimplemented;
    // Set for an internal function whose body depends on the values of its
    // arguments (f_ridged_mf's octaves: a loop's count): the body made for
    // a call's arguments (language/function_internals.cpp). `unimplemented`
    // then says what happens where it is used without a call.
    std::function<TimeFunction(const std::vector<TimeFunction>&)> at_call;
};

// A user function of (x, y, z) and time compiled to a tape. Copies share it.
class SpaceFunction {
  public:
    SpaceFunction() = default;
    // body's arguments 0, 1, 2 are x, y, z; it may read no others.
    explicit SpaceFunction(const TimeFunction& body)
        : tape_(std::make_shared<const TimeTape>(TimeTape::compile({body}))) {}

    bool depends_on_time() const { return tape_->reads_time(); }
    // Null, or a function it calls that has no interval bound (a pigment):
    // then over() is no bound.
    const PointFunction* unbounded_part() const { return tape_->unbounded_point_function(); }
    std::size_t size() const { return tape_->size(); }

    // f(p) at time t.
    double at(const glm::dvec3& p, double t) const {
        const double args[3] = {p.x, p.y, p.z};
        return run(t, args);
    }
    // A range holding f over a box of points and an interval of times.
    Interval over(const IntervalBox& box, const Interval& t) const { return run(t, box.data()); }
    // The gradient of f at p at time t, by forward-mode differentiation
    // (one pass per axis: the value is the point value bit for bit).
    glm::dvec3 gradient(const glm::dvec3& p, double t) const {
        glm::dvec3 g;
        for (int axis = 0; axis < 3; ++axis) {
            Dual args[3] = {Dual(p.x), Dual(p.y), Dual(p.z)};
            args[axis].d = 1.0;
            g[axis] = run(Dual(t), args).d;
        }
        return g;
    }

  private:
    template <class Number>
    Number run(Number t, const Number* args) const {
        constexpr std::size_t kOnStack = 128;
        Number out;
        if (tape_->size() <= kOnStack) {
            Number scratch[kOnStack];
            tape_->evaluate_with(t, args, &out, scratch);
        } else {
            std::vector<Number> scratch(tape_->size());
            tape_->evaluate_with(t, args, &out, scratch.data());
        }
        return out;
    }

    std::shared_ptr<const TimeTape> tape_;
};

}  // namespace hexant::runtime
