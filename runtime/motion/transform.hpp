// An object's placement as POV-Ray builds it: the ordered list of
// translate/rotate/scale/matrix steps (and hexant's deformations), each of
// whose amounts may be a function of time. Evaluating the list at t gives the
// object-to-world map at that instant.
#pragma once

#include <array>
#include <memory>
#include <stdexcept>
#include <vector>

#include <glm/mat4x4.hpp>

#include "runtime/time/limit_error.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

enum class TransformKind {
    Translate,
    Rotate,  // degrees about x, then y, then z (POV-Ray's order)
    Scale,
    Matrix,  // POV-Ray's 4x3 matrix, rows (m00 m01 m02) ... (m30 m31 m32)
    // Deformations (not affine): Barr's twist, taper and bend about an axis.
    Twist,  // amount: degrees of twist per unit along the axis
    Taper,  // amount: scale factor per unit along the axis
    Bend,   // amount: degrees of bend over a unit length along the axis
};

// A `matrix` step's twelve entries, held only where written: translate,
// rotate and scale steps (nearly all of them) keep none, which saves some
// 280 bytes per step in scenes of many objects. Reading an entry that was
// never written gives 0.
class MatrixEntries {
  public:
    MatrixEntries() = default;
    MatrixEntries(const MatrixEntries& o)
        : entries_(o.entries_ ? std::make_unique<std::array<TimeFunction, 12>>(*o.entries_)
                              : nullptr) {}
    MatrixEntries& operator=(const MatrixEntries& o) {
        if (this != &o)
            entries_ =
                o.entries_ ? std::make_unique<std::array<TimeFunction, 12>>(*o.entries_) : nullptr;
        return *this;
    }
    MatrixEntries(MatrixEntries&&) noexcept = default;
    MatrixEntries& operator=(MatrixEntries&&) noexcept = default;

    TimeFunction& operator[](std::size_t i) {
        if (!entries_) entries_ = std::make_unique<std::array<TimeFunction, 12>>();
        return (*entries_)[i];
    }
    const TimeFunction& operator[](std::size_t i) const {
        static const TimeFunction zero;
        return entries_ ? (*entries_)[i] : zero;
    }
    bool depends_on_time() const {
        if (!entries_) return false;
        for (const auto& f : *entries_)
            if (f.depends_on_time()) return true;
        return false;
    }

  private:
    std::unique_ptr<std::array<TimeFunction, 12>> entries_;
};

struct TransformStep {
    TransformKind kind;
    Vector3Function vector;  // translate, rotate, scale amounts; deformation axis
    MatrixEntries matrix;    // Matrix only
    TimeFunction amount;     // deformations only
    bool inverse = false;    // apply the inverse of this step

    bool is_deformation() const { return kind >= TransformKind::Twist; }
    bool depends_on_time() const;
    // The affine map of this step at time t; only for non-deformations.
    glm::dmat4 matrix_at(double t) const;
};

// A transform keeps the steps as written, up to kListedSteps of them (what
// `hexant dump` lists, and what its time functions need); past that, a
// constant step joins a constant step before it as one matrix, as POV-Ray
// keeps every transform as one matrix: a turtle's transform built up in a
// loop, `#declare T = transform { T translate ... }`, then costs the same
// at every turn (its steps were copied each turn: 10^4 turns took 11 s).
// Steps that depend on time cannot join; a transform of more than
// kMaxTransformSteps steps is refused (TransformTooLong) where it is made
// (such a chain is still copied at each turn: 2,000 turns take about half
// a second, 10,000 took 12 s; and every ray would evaluate each step).
inline constexpr std::size_t kListedSteps = 16;
inline constexpr std::size_t kMaxTransformSteps = 2000;
struct TransformTooLong : LimitError {
    TransformTooLong();
};

class Transform {
  public:
    void append(TransformStep step);
    void append(const Transform& other);
    // The transform that undoes this one: the steps reversed, each inverted.
    Transform inverse() const;

    const std::vector<TransformStep>& steps() const { return steps_; }
    bool empty() const { return steps_.empty(); }
    bool depends_on_time() const;
    bool has_deformation() const;

    // Object-to-world at time t, composing the steps in order. Only for
    // transforms without deformations.
    glm::dmat4 matrix_at(double t) const;

  private:
    std::vector<TransformStep> steps_;
};

}  // namespace hexant::runtime
