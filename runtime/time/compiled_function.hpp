// A time function (or a vector of three) ready for the tracer: a number when
// it is constant, which every evaluator returns at once, and a tape
// otherwise. Copies share the tape.
#pragma once

#include <array>
#include <memory>

#include <glm/vec3.hpp>

#include "runtime/time/dual.hpp"
#include "runtime/time/interval.hpp"
#include "runtime/time/time_function.hpp"
#include "runtime/time/time_tape.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

class CompiledScalar {
  public:
    CompiledScalar(double constant = 0.0) : constant_(constant) {}  // NOLINT: implicit
    explicit CompiledScalar(const TimeFunction& f) {
        if (f.is_constant())
            constant_ = f.constant();
        else
            tape_ = std::make_shared<const TimeTape>(TimeTape::compile({f}));
    }

    bool is_constant() const { return tape_ == nullptr; }
    // The value when is_constant().
    double constant() const { return constant_; }

    double at(double t) const {
        if (!tape_) return constant_;
        double out;
        tape_->evaluate(t, &out);
        return out;
    }
    Interval over(const Interval& t) const {
        if (!tape_) return constant_;
        Interval out;
        tape_->evaluate(t, &out);
        return out;
    }
    Dual with_derivative(double t) const {
        if (!tape_) return {constant_, 0.0};
        Dual out;
        tape_->evaluate(Dual::variable(t), &out);
        return out;
    }

  private:
    double constant_ = 0.0;
    std::shared_ptr<const TimeTape> tape_;  // null when constant
};

class CompiledVector3 {
  public:
    CompiledVector3(const glm::dvec3& constant = glm::dvec3(0.0))  // NOLINT: implicit
        : constant_(constant) {}
    explicit CompiledVector3(const Vector3Function& f) {
        if (!f.depends_on_time()) {
            constant_ = {f.c[0].constant(), f.c[1].constant(), f.c[2].constant()};
        } else {
            tape_ = std::make_shared<const TimeTape>(TimeTape::compile({f.c[0], f.c[1], f.c[2]}));
        }
    }

    bool is_constant() const { return tape_ == nullptr; }
    // The value when is_constant().
    const glm::dvec3& constant() const { return constant_; }

    glm::dvec3 at(double t) const {
        if (!tape_) return constant_;
        double out[3];
        tape_->evaluate(t, out);
        return {out[0], out[1], out[2]};
    }
    std::array<Interval, 3> over(const Interval& t) const {
        if (!tape_) return {Interval(constant_.x), Interval(constant_.y), Interval(constant_.z)};
        std::array<Interval, 3> out;
        tape_->evaluate(t, out.data());
        return out;
    }
    std::array<Dual, 3> with_derivative(double t) const {
        if (!tape_) return {Dual(constant_.x), Dual(constant_.y), Dual(constant_.z)};
        std::array<Dual, 3> out;
        tape_->evaluate(Dual::variable(t), out.data());
        return out;
    }

  private:
    glm::dvec3 constant_{0.0};
    std::shared_ptr<const TimeTape> tape_;  // null when constant
};

}  // namespace hexant::runtime
