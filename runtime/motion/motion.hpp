// An object's Transform compiled for the tracer: object-to-world and back at
// a time (double), over a time interval (Interval bounds) and with
// derivatives (Dual), for affine steps and Barr's deformations alike.
//
// The steps become a chain of stages. Consecutive affine steps collapse into
// one stage: a constant stage keeps its matrix and inverse, computed once; a
// moving stage keeps its steps, whose amounts come from one time tape shared
// by the whole chain. Each deformation is a stage of its own. A transform
// that is constant and affine is one matrix and nothing else: to_world is an
// inline matrix product, with no tape, allocation or indirect call.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "runtime/motion/deformation.hpp"
#include "runtime/motion/transform.hpp"
#include "runtime/time/clock_line.hpp"
#include "runtime/time/dual.hpp"
#include "runtime/time/interval.hpp"
#include "runtime/time/interval_jet.hpp"
#include "runtime/time/interval_matrix.hpp"

namespace hexant::runtime {

class TimeTape;

class Motion {
  public:
    Motion() = default;  // the identity
    explicit Motion(const Transform& transform);
    Motion(const Motion& other);
    // A motion moved from is the identity (its block went with the move).
    Motion(Motion&& other) noexcept;
    Motion& operator=(const Motion& other);
    Motion& operator=(Motion&& other) noexcept;
    ~Motion() = default;

    // Nothing depends on time.
    bool is_static() const { return !moving_; }
    // No deformation: one matrix at each time.
    bool is_affine() const { return affine_; }
    bool is_identity() const { return identity_; }

    // The motion frozen at one instant: every amount a constant, each moving
    // stage one matrix, and a deformation whose amount is 0 at t (a twist
    // starting from none, say) left out, so that what is affine at t is
    // affine. For a ray at one instant this is the same map with nothing
    // evaluated per point but the maps themselves.
    Motion at_instant(double t) const;

    // Object to world at t, and back; only when is_affine().
    glm::dmat4 matrix_at(double t) const;
    // The same map as a 3x4 matrix, without glm's 4x4 on the way (the
    // sweeps' placed boxes take one per piece end).
    AffineMap<double> map_at(double t) const;
    glm::dmat4 inverse_at(double t) const;
    // Both at once, from one evaluation of the time functions (a moving
    // object's intersection needs the inverse for the ray and the matrix
    // for the hit).
    struct Placement {
        glm::dmat4 to_world, to_object;
    };
    Placement placement_at(double t) const;
    // Entries that hold the matrix's entries at every time in t; only when
    // is_affine(). Rotations use interval sines and cosines of the interval
    // angle, so a short interval gives a thin enclosure.
    IntervalAffine matrix_over(const Interval& t) const;
    // The same entries as interval jets over t (interval_jet.hpp): ranges,
    // first and second derivatives' ranges and the double evaluation's
    // rounding radii, for sweeps by chords; only when is_affine().
    AffineMap<IntervalJet> matrix_jet_over(const Interval& t) const;

    // Object to world and back, for N = double, Interval (enclosing every
    // value over the boxes p and t) and Dual (p and t carrying derivatives
    // with respect to one common parameter). to_object undoes to_world
    // exactly where the deformations are one to one (see deformation.hpp).
    template <class N>
    std::array<N, 3> to_world(const std::array<N, 3>& p, const N& t) const {
        if (fixed_affine_) return fixed_map().forward.apply(p);
        return to_world_general(p, t);
    }
    template <class N>
    std::array<N, 3> to_object(const std::array<N, 3>& p, const N& t) const {
        if (fixed_affine_) return fixed_map().backward.apply(p);
        return to_object_general(p, t);
    }
    glm::dvec3 to_world(const glm::dvec3& p, double t) const {
        const auto r = to_world(std::array<double, 3>{p.x, p.y, p.z}, t);
        return {r[0], r[1], r[2]};
    }
    glm::dvec3 to_object(const glm::dvec3& p, double t) const {
        const auto r = to_object(std::array<double, 3>{p.x, p.y, p.z}, t);
        return {r[0], r[1], r[2]};
    }

    // A twist keeps every point's distance from its axis. For each stage,
    // how far from that twist's axis the points of object_box can be when
    // they reach it, at any time in t (rounded up past the double maps'
    // drift); infinity for stages that are not twists about a fixed axis.
    // Empty when the motion has no such twist.
    std::vector<double> twist_reaches(const IntervalBox& object_box, const Interval& t) const;
    // to_object for a box, or nothing when the box lies beyond a twist's
    // reach (twist_reaches of a box holding the object): then no point of
    // the object maps into it, which the box alone, turned into object
    // space, cannot show (a stiff twist's box comes out around the axis).
    std::optional<IntervalBox> to_object_within(const IntervalBox& p, const Interval& t,
                                                const std::vector<double>& reaches) const;

    // A box holding the images of all points of object_box at all times in
    // t. For deformations the box is also cut into a few pieces, and the
    // tighter of the two answers' intersection is returned.
    IntervalBox world_box(const IntervalBox& object_box, const Interval& t) const;

    // d(world)/d(object) at an object point, from the analytic derivatives
    // of each stage. A world normal is inverse-transpose(J) times the object
    // normal.
    glm::dmat3 jacobian_at(const glm::dvec3& object_point, double t) const;

  private:
    // A step's amount: a constant or a line in clock (clock_line.hpp),
    // which needs no tape, or else output `slot` of the tape.
    struct Parameter {
        ClockLine line;
        int slot = -1;
        bool is_constant() const { return slot < 0 && line.is_constant(); }
    };
    // A moving affine step; its amounts are parameters()[first ..] (three,
    // a vector's; twelve for a Matrix).
    struct Step {
        TransformKind kind = TransformKind::Translate;
        bool inverse = false;
        std::uint32_t first = 0;
    };
    enum class StageKind : std::uint8_t { Fixed, Moving, Twist, Taper, Bend };
    // A stage names its data in the motion's own arrays, by kind: a Fixed
    // one fixed()[index]; a Moving one steps()[index, index + count); a
    // deformation deformations()[index]. Kept apart, and the five arrays in
    // one block, a moving sphere's motion is about 360 bytes (48 in the
    // object, 312 in its block) where stages holding every kind's fields
    // took about 1,050 and five separate arrays about 470 (docs/benchmarks.md, "Scale: the swarm").
    struct FixedMaps {
        AffineMap<double> forward = AffineMap<double>::identity();
        AffineMap<double> backward = AffineMap<double>::identity();
    };
    struct Deformation {
        std::array<Parameter, 3> axis;
        Parameter amount;
        DeformationFrame<double> frame;  // when the stage's fixed_frame
    };
    struct Stage {
        StageKind kind = StageKind::Fixed;
        bool inverse = false;     // deformations
        bool fixed_frame = true;  // deformations: the axis is constant, its frame kept
        std::uint32_t index = 0;
        std::uint32_t count = 0;  // Moving: its steps
    };
    // The arrays while a motion is made; pack() then puts them in one block.
    struct Arrays {
        std::vector<Stage> stages;
        std::vector<FixedMaps> fixed;
        std::vector<Step> steps;
        std::vector<Parameter> parameters;
        std::vector<Deformation> deformations;
    };
    // The block's parts, in this order (the widest alignment first): fixed
    // maps, deformations, parameters, stages, steps.
    std::size_t deformations_offset() const { return fixed_count_ * sizeof(FixedMaps); }
    std::size_t parameters_offset() const {
        return deformations_offset() + deformation_count_ * sizeof(Deformation);
    }
    std::size_t stages_offset() const {
        return parameters_offset() + parameter_count_ * sizeof(Parameter);
    }
    std::size_t steps_offset() const { return stages_offset() + stage_count_ * sizeof(Stage); }
    std::size_t block_bytes() const { return steps_offset() + step_count_ * sizeof(Step); }
    template <class T>
    std::span<const T> part(std::size_t offset, std::uint32_t count) const {
        return {reinterpret_cast<const T*>(block_.get() + offset), count};
    }
    std::span<const FixedMaps> fixed() const { return part<FixedMaps>(0, fixed_count_); }
    std::span<const Deformation> deformations() const {
        return part<Deformation>(deformations_offset(), deformation_count_);
    }
    std::span<const Parameter> parameters() const {
        return part<Parameter>(parameters_offset(), parameter_count_);
    }
    std::span<const Stage> stages() const { return part<Stage>(stages_offset(), stage_count_); }
    std::span<const Step> steps() const { return part<Step>(steps_offset(), step_count_); }

    const FixedMaps& fixed_of(const Stage& s) const { return fixed()[s.index]; }
    // A constant affine motion's map: its one Fixed stage's (consecutive
    // constant steps merge into one), or the identity. Not a copy kept
    // beside the stages: a moving object would carry its 192 bytes unused.
    const FixedMaps& fixed_map() const { return fixed_count_ == 0 ? kIdentityMaps : fixed()[0]; }
    // A namespace-lifetime constant, not a function's static: to_world and
    // to_object read it per ray, and a local static pays a guard check.
    static const FixedMaps kIdentityMaps;
    const Deformation& deformation_of(const Stage& s) const { return deformations()[s.index]; }
    const Step* steps_begin(const Stage& s) const { return steps().data() + s.index; }
    const Step* steps_end(const Stage& s) const { return steps().data() + s.index + s.count; }
    const Parameter& amount_of(const Step& s, int i) const { return parameters()[s.first + i]; }

    template <class N>
    friend struct MotionEvaluator;

    // Appends a constant affine stage to `a`, merged with a constant stage
    // before it.
    void append_fixed(Arrays& a, const AffineMap<double>& forward,
                      const AffineMap<double>& backward);
    // Moves the arrays into the block and sets fixed_affine_.
    void finish_stages(const Arrays& a);

    template <class N>
    std::array<N, 3> to_world_general(const std::array<N, 3>& p, const N& t) const;
    template <class N>
    std::array<N, 3> to_object_general(const std::array<N, 3>& p, const N& t) const;

    bool moving_ = false;       // some amount depends on time (a line or the tape)
    bool fixed_affine_ = true;  // constant and affine: fixed_map() is the map
    bool affine_ = true;
    bool identity_ = true;
    std::uint32_t stage_count_ = 0, fixed_count_ = 0, step_count_ = 0, parameter_count_ = 0,
                  deformation_count_ = 0;
    std::unique_ptr<std::byte[]> block_;    // the five arrays (their offsets above); null if none
    std::shared_ptr<const TimeTape> tape_;  // the amounts that are not lines; often null
};

extern template std::array<double, 3> Motion::to_world_general(const std::array<double, 3>&,
                                                               const double&) const;
extern template std::array<Interval, 3> Motion::to_world_general(const std::array<Interval, 3>&,
                                                                 const Interval&) const;
extern template std::array<Dual, 3> Motion::to_world_general(const std::array<Dual, 3>&,
                                                             const Dual&) const;
extern template std::array<double, 3> Motion::to_object_general(const std::array<double, 3>&,
                                                                const double&) const;
extern template std::array<Interval, 3> Motion::to_object_general(const std::array<Interval, 3>&,
                                                                  const Interval&) const;
extern template std::array<Dual, 3> Motion::to_object_general(const std::array<Dual, 3>&,
                                                              const Dual&) const;

}  // namespace hexant::runtime
