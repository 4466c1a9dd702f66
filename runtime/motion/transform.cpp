#include "runtime/motion/transform.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

namespace hexant::runtime {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

// Rotation about one principal axis by `degrees`, as POV-Ray's
// Compute_Rotation_Transform defines it (x, then y, then z).
glm::dmat4 axis_rotation(int axis, double degrees) {
    const double s = std::sin(degrees * kDegree), c = std::cos(degrees * kDegree);
    glm::dmat4 m(1.0);
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    // column-vector form: a' = a c - b s, b' = a s + b c
    m[a][a] = c;
    m[b][a] = -s;
    m[a][b] = s;
    m[b][b] = c;
    return m;
}

}  // namespace

bool TransformStep::depends_on_time() const {
    if (vector.depends_on_time() || amount.depends_on_time()) return true;
    return kind == TransformKind::Matrix && matrix.depends_on_time();
}

glm::dmat4 TransformStep::matrix_at(double t) const {
    glm::dmat4 m(1.0);
    switch (kind) {
        case TransformKind::Translate: {
            glm::dvec3 v = vector(t);
            m = glm::translate(glm::dmat4(1.0), inverse ? -v : v);
            return m;
        }
        case TransformKind::Scale: {
            glm::dvec3 v = vector(t);
            // POV-Ray's rule for a factor of exactly 0 (motion.cpp, scale_factor).
            for (int i = 0; i < 3; ++i)
                if (v[i] == 0.0) v[i] = 1.0;
            m = glm::scale(glm::dmat4(1.0), inverse ? 1.0 / v : v);
            return m;
        }
        case TransformKind::Rotate: {
            glm::dvec3 v = vector(t);
            if (!inverse)
                return axis_rotation(2, v.z) * axis_rotation(1, v.y) * axis_rotation(0, v.x);
            return axis_rotation(0, -v.x) * axis_rotation(1, -v.y) * axis_rotation(2, -v.z);
        }
        case TransformKind::Matrix: {
            // glm's column i holds POV-Ray's row i (POV-Ray multiplies row vectors).
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 3; ++j) m[i][j] = matrix[i * 3 + j](t);
            return inverse ? glm::inverse(m) : m;
        }
        default:
            break;
    }
    throw std::logic_error("a deformation has no matrix");
}

TransformTooLong::TransformTooLong()
    : LimitError("a transform of more than " + std::to_string(kMaxTransformSteps) +
                 " steps that depend on clock (built up in a loop?)") {}

namespace {

bool is_constant_affine(const TransformStep& step) {
    return !step.is_deformation() && !step.depends_on_time();
}

}  // namespace

void Transform::append(TransformStep step) {
    if (steps_.size() >= kListedSteps && is_constant_affine(step) &&
        is_constant_affine(steps_.back())) {
        // One matrix: the new step after the old (column vectors, glm).
        const glm::dmat4 m = step.matrix_at(0.0) * steps_.back().matrix_at(0.0);
        TransformStep joined;
        joined.kind = TransformKind::Matrix;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 3; ++j) joined.matrix[i * 3 + j] = m[i][j];
        steps_.back() = std::move(joined);
        return;
    }
    if (steps_.size() >= kMaxTransformSteps) throw TransformTooLong();
    steps_.push_back(std::move(step));
}

void Transform::append(const Transform& other) {
    if (&other == this) {
        const Transform copy = other;
        append(copy);
        return;
    }
    for (const TransformStep& step : other.steps_) append(step);
}

Transform Transform::inverse() const {
    Transform result;
    for (auto it = steps_.rbegin(); it != steps_.rend(); ++it) {
        TransformStep step = *it;
        step.inverse = !step.inverse;
        result.append(std::move(step));
    }
    return result;
}

bool Transform::depends_on_time() const {
    for (const auto& s : steps_)
        if (s.depends_on_time()) return true;
    return false;
}

bool Transform::has_deformation() const {
    for (const auto& s : steps_)
        if (s.is_deformation()) return true;
    return false;
}

glm::dmat4 Transform::matrix_at(double t) const {
    glm::dmat4 m(1.0);
    for (const auto& s : steps_) m = s.matrix_at(t) * m;
    return m;
}

}  // namespace hexant::runtime
