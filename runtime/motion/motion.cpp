#include "runtime/motion/motion.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include <glm/matrix.hpp>

#include "runtime/time/time_tape.hpp"
#include "runtime/work_counts.hpp"

namespace hexant::runtime {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

// Rotation by `degrees` about principal axis `axis`, as transform.cpp's
// axis_rotation (POV-Ray's Compute_Rotation_Transform): a' = a c - b s,
// b' = a s + b c for the two other axes a, b.
template <class N>
AffineMap<N> axis_rotation(int axis, const N& degrees) {
    using std::cos;
    using std::sin;
    const N angle = degrees * N(kDegree);
    const N s = sin(angle), c = cos(angle);
    AffineMap<N> m = AffineMap<N>::identity();
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    m.m[a][a] = c;
    m.m[a][b] = -s;
    m.m[b][a] = s;
    m.m[b][b] = c;
    return m;
}

// A scale factor as POV-Ray uses it: exactly 0 becomes 1 (POV-Ray 3.7
// warns "Scale X by 0.0. Changed to 1.0" and renders; parser_expressions.cpp).
// A factor that moves through 0 is therefore 1 at that one instant, as a
// frame POV-Ray renders there shows it, and itself at every other; the
// interval form holds both (its factors, and 1 where 0 is among them).
inline double scale_factor(double v) {
    return v == 0.0 ? 1.0 : v;
}
inline Interval scale_factor(const Interval& v) {
    return v.lo <= 0.0 && v.hi >= 0.0 ? hull(v, Interval(1.0)) : v;
}
inline Dual scale_factor(const Dual& v) {
    return v.v == 0.0 ? Dual(1.0, 0.0) : v;
}
// A factor that may pass through 0 jumps there: no linear form.
inline IntervalJet scale_factor(const IntervalJet& v) {
    if (v.v.lo - v.r <= 0.0 && v.v.hi + v.r >= 0.0) return IntervalJet::unknown(scale_factor(v.v));
    return v;
}

// The inverse of a general affine map by its adjugate; a singular map (a
// scene's `matrix` with a zero determinant) divides by zero, which the
// interval type turns into entire() and doubles into Inf, kept out of the
// tracer by the callers' finite checks.
template <class N>
AffineMap<N> inverse_of(const AffineMap<N>& a) {
    const auto& m = a.m;
    AffineMap<N> r;
    r.m[0][0] = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    r.m[0][1] = m[0][2] * m[2][1] - m[0][1] * m[2][2];
    r.m[0][2] = m[0][1] * m[1][2] - m[0][2] * m[1][1];
    r.m[1][0] = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    r.m[1][1] = m[0][0] * m[2][2] - m[0][2] * m[2][0];
    r.m[1][2] = m[0][2] * m[1][0] - m[0][0] * m[1][2];
    r.m[2][0] = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    r.m[2][1] = m[0][1] * m[2][0] - m[0][0] * m[2][1];
    r.m[2][2] = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    const N det = m[0][0] * r.m[0][0] + m[0][1] * r.m[1][0] + m[0][2] * r.m[2][0];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.m[i][j] = r.m[i][j] / det;
    for (int i = 0; i < 3; ++i)
        r.m[i][3] = -(r.m[i][0] * m[0][3] + r.m[i][1] * m[1][3] + r.m[i][2] * m[2][3]);
    return r;
}

// k x for a constant k, as the product N(k) * x, without a general product
// where the number type has a cheaper exact-constant form.
template <class N>
N times_constant(double k, const N& x) {
    return N(k) * x;
}
inline Interval times_constant(double k, const Interval& x) {
    if (k == 0.0) return Interval(0.0);
    if (k == 1.0) return x;
    if (k == -1.0) return -x;
    return interval_detail::scaled(x, k);
}
inline IntervalJet times_constant(double k, const IntervalJet& x) {
    return scaled(x, k);
}

// a * b for a constant map a: the same sums in the same order as
// AffineMap<N>::from(a) * b, each product by a constant entry formed as one.
template <class N>
AffineMap<N> fixed_times(const AffineMap<double>& a, const AffineMap<N>& b) {
    if constexpr (std::is_same_v<N, double> || std::is_same_v<N, Dual>) {
        return AffineMap<N>::from(a) * b;
    } else {
        AffineMap<N> r;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 4; ++j) {
                r.m[i][j] = times_constant(a.m[i][0], b.m[0][j]) +
                            times_constant(a.m[i][1], b.m[1][j]) +
                            times_constant(a.m[i][2], b.m[2][j]);
                if (j == 3) r.m[i][j] = r.m[i][j] + N(a.m[i][3]);
            }
        }
        return r;
    }
}

// At most this many time-dependent amounts live on the stack per call;
// more go to the heap (a scene would need dozens of moving steps on one
// object).
constexpr std::size_t kStackAmounts = 48;

}  // namespace

// Evaluates a Motion's stages for one number type: the tape once, then each
// stage's map from the amounts.
template <class N>
struct MotionEvaluator {
    const Motion& motion;
    std::array<N, kStackAmounts> stack;  // written by the tape before it is read
    std::vector<N> heap;
    N* amounts = nullptr;

    N time;  // what the lines are evaluated at

    MotionEvaluator(const Motion& m, const N& t) : motion(m), time(t) {
        if (!m.tape_) return;
        const std::size_t count = m.tape_->output_count();
        if (count <= kStackAmounts) {
            amounts = stack.data();
        } else {
            heap.resize(count);
            amounts = heap.data();
        }
        m.tape_->evaluate(t, amounts);
    }

    N value(const Motion::Parameter& p) const {
        return p.slot < 0 ? p.line.at(time) : amounts[p.slot];
    }
    N amount(const Motion::Step& s, int i) const { return value(motion.amount_of(s, i)); }
    std::array<N, 3> vector(const Motion::Step& s) const {
        return {amount(s, 0), amount(s, 1), amount(s, 2)};
    }

    // One affine step's map (or its inverse).
    AffineMap<N> step_map(const Motion::Step& s, bool invert) const {
        const bool inverse = s.inverse != invert;
        AffineMap<N> m = AffineMap<N>::identity();
        switch (s.kind) {
            case TransformKind::Translate: {
                const auto v = vector(s);
                for (int i = 0; i < 3; ++i) m.m[i][3] = inverse ? -v[i] : v[i];
                return m;
            }
            case TransformKind::Scale: {
                const auto v = vector(s);
                for (int i = 0; i < 3; ++i) {
                    const N f = scale_factor(v[i]);
                    m.m[i][i] = inverse ? N(1.0) / f : f;
                }
                return m;
            }
            case TransformKind::Rotate: {
                const auto v = vector(s);
                if (!inverse)
                    return axis_rotation(2, v[2]) *
                           (axis_rotation(1, v[1]) * axis_rotation(0, v[0]));
                return axis_rotation(0, -v[0]) *
                       (axis_rotation(1, -v[1]) * axis_rotation(2, -v[2]));
            }
            case TransformKind::Matrix: {
                // POV-Ray's row i (glm's column i) is the image of axis i;
                // row 3 the translation.
                for (int i = 0; i < 4; ++i)
                    for (int j = 0; j < 3; ++j) m.m[j][i] = amount(s, i * 3 + j);
                return inverse ? inverse_of(m) : m;
            }
            default:
                break;
        }
        throw std::logic_error("Motion: a deformation step in an affine stage");
    }

    // m = (the stage's map) * m, forward only: a moving stage's steps
    // applied to m in place, a constant one multiplied in. The point, the
    // interval and the placement evaluations all compose this way, in this
    // order, so that the interval one encloses the others exactly.
    void compose(const Motion::Stage& stage, AffineMap<N>& m) const {
        if (stage.kind == Motion::StageKind::Fixed) {
            m = fixed_times(motion.fixed_of(stage).forward, m);
            return;
        }
        for (const auto* s = motion.steps_begin(stage); s != motion.steps_end(stage); ++s)
            apply_step(*s, false, m);
    }

    // A moving stage's map: its steps in order (or undone in reverse order).
    AffineMap<N> stage_map(const Motion::Stage& stage, bool invert) const {
        AffineMap<N> m = AffineMap<N>::identity();
        const Motion::Step* first = motion.steps_begin(stage);
        const Motion::Step* last = motion.steps_end(stage);
        if (!invert) {
            for (const auto* s = first; s != last; ++s) apply_step(*s, false, m);
        } else {
            for (const auto* s = last; s != first;) apply_step(*--s, true, m);
        }
        return m;
    }

    // m = (the step's map, or its inverse) * m, without forming the step's
    // matrix: a translation adds to the last column, a scale scales rows, a
    // rotation turns two rows per axis and skips axes whose angle is a
    // constant 0 (the same products as step_map's, minus multiplications by
    // exact ones and zeros). Moving objects pay this per ray.
    void apply_step(const Motion::Step& s, bool invert, AffineMap<N>& m) const {
        const bool inverse = s.inverse != invert;
        switch (s.kind) {
            case TransformKind::Translate:
                for (int i = 0; i < 3; ++i) {
                    const N v = amount(s, i);
                    m.m[i][3] = m.m[i][3] + (inverse ? -v : v);
                }
                return;
            case TransformKind::Scale:
                for (int i = 0; i < 3; ++i) {
                    const N v = scale_factor(amount(s, i));
                    const N f = inverse ? N(1.0) / v : v;
                    for (int j = 0; j < 4; ++j) m.m[i][j] = f * m.m[i][j];
                }
                return;
            case TransformKind::Rotate:
                if (!inverse) {
                    for (int axis = 0; axis < 3; ++axis)
                        rotate_rows(axis, motion.amount_of(s, axis), false, m);
                } else {
                    for (int axis = 2; axis >= 0; --axis)
                        rotate_rows(axis, motion.amount_of(s, axis), true, m);
                }
                return;
            default:
                m = step_map(s, invert) * m;
                return;
        }
    }

    // m = (rotation about `axis` by the parameter's degrees, negated if
    // asked) * m, as axis_rotation(axis, degrees) * m.
    void rotate_rows(int axis, const Motion::Parameter& p, bool negate, AffineMap<N>& m) const {
        using std::cos;
        using std::sin;
        if (p.is_constant() && p.line.constant_value() == 0.0) return;  // the identity, exactly
        const N degrees = negate ? -value(p) : value(p);
        const N angle = degrees * N(kDegree);
        const N sn = sin(angle), cs = cos(angle);
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        for (int j = 0; j < 4; ++j) {
            const N ra = m.m[a][j], rb = m.m[b][j];
            m.m[a][j] = cs * ra - sn * rb;
            m.m[b][j] = sn * ra + cs * rb;
        }
    }

    std::array<N, 3> deform(const Motion::Stage& stage, const std::array<N, 3>& p,
                            bool invert) const {
        ++this_thread_work.deformation_maps;
        const Motion::Deformation& d = motion.deformation_of(stage);
        const N amount = value(d.amount);
        if (stage.fixed_frame)
            return deform_in(stage.kind, d.frame, p, amount, invert != stage.inverse);
        const std::array<N, 3> axis{value(d.axis[0]), value(d.axis[1]), value(d.axis[2])};
        return deform_in(stage.kind, deformation_frame(axis), p, amount, invert != stage.inverse);
    }

    template <class M>
    static std::array<N, 3> deform_in(Motion::StageKind kind, const DeformationFrame<M>& f,
                                      const std::array<N, 3>& p, const N& amount, bool inverse) {
        switch (kind) {
            case Motion::StageKind::Twist:
                return inverse ? untwist(p, f, amount) : twist(p, f, amount);
            case Motion::StageKind::Taper:
                return inverse ? untaper(p, f, amount) : taper(p, f, amount);
            case Motion::StageKind::Bend:
                return inverse ? unbend(p, f, amount) : bend(p, f, amount);
            default:
                break;
        }
        return p;
    }

    std::array<N, 3> through(const Motion::Stage& stage, const std::array<N, 3>& p,
                             bool invert) const {
        switch (stage.kind) {
            case Motion::StageKind::Fixed:
                return invert ? motion.fixed_of(stage).backward.apply(p)
                              : motion.fixed_of(stage).forward.apply(p);
            case Motion::StageKind::Moving:
                return stage_map(stage, invert).apply(p);
            default:
                return deform(stage, p, invert);
        }
    }
};

Motion::Motion(const Transform& transform) {
    Arrays a;
    std::vector<TimeFunction> outputs;
    auto parameter = [&](const TimeFunction& f) {
        Parameter p;
        if (const auto line = ClockLine::of(f)) {
            p.line = *line;
            moving_ = moving_ || !line->is_constant();
        } else {
            p.slot = static_cast<int>(outputs.size());
            outputs.push_back(f);
            moving_ = true;
        }
        return p;
    };

    for (const TransformStep& step : transform.steps()) {
        if (step.is_deformation()) {
            Stage stage;
            stage.kind = step.kind == TransformKind::Twist   ? StageKind::Twist
                         : step.kind == TransformKind::Taper ? StageKind::Taper
                                                             : StageKind::Bend;
            stage.inverse = step.inverse;
            Deformation d;
            for (int i = 0; i < 3; ++i) d.axis[i] = parameter(step.vector.c[i]);
            d.amount = parameter(step.amount);
            stage.fixed_frame = !step.vector.depends_on_time();
            if (stage.fixed_frame) d.frame = deformation_frame(step.vector(0.0));
            stage.index = static_cast<std::uint32_t>(a.deformations.size());
            a.deformations.push_back(d);
            a.stages.push_back(stage);
            affine_ = false;
            identity_ = false;
            continue;
        }
        if (!step.depends_on_time()) {
            // A constant step joins a preceding constant stage.
            const AffineMap<double> m = AffineMap<double>::from(step.matrix_at(0.0));
            if (a.stages.empty() || a.stages.back().kind != StageKind::Fixed) {
                Stage stage;
                stage.index = static_cast<std::uint32_t>(a.fixed.size());
                a.fixed.emplace_back();
                a.stages.push_back(stage);
            }
            FixedMaps& maps = a.fixed[a.stages.back().index];
            maps.forward = m * maps.forward;
            maps.backward = to_glm(maps.forward) == glm::dmat4(1.0)
                                ? AffineMap<double>::identity()
                                : AffineMap<double>::from(glm::inverse(to_glm(maps.forward)));
            identity_ = identity_ && to_glm(maps.forward) == glm::dmat4(1.0);
            continue;
        }
        Step s;
        s.kind = step.kind;
        s.inverse = step.inverse;
        s.first = static_cast<std::uint32_t>(a.parameters.size());
        if (step.kind == TransformKind::Matrix) {
            for (int i = 0; i < 12; ++i) a.parameters.push_back(parameter(step.matrix[i]));
        } else {
            for (int i = 0; i < 3; ++i) a.parameters.push_back(parameter(step.vector.c[i]));
        }
        // A moving stage's steps are consecutive: it is the last stage.
        if (a.stages.empty() || a.stages.back().kind != StageKind::Moving) {
            Stage stage;
            stage.kind = StageKind::Moving;
            stage.index = static_cast<std::uint32_t>(a.steps.size());
            a.stages.push_back(stage);
        }
        a.steps.push_back(s);
        ++a.stages.back().count;
        identity_ = false;
    }

    if (!outputs.empty()) tape_ = std::make_shared<const TimeTape>(TimeTape::compile(outputs));
    finish_stages(a);
}

const Motion::FixedMaps Motion::kIdentityMaps{};

namespace {

template <class T>
std::uint32_t count_of(const std::vector<T>& v) {
    if (v.size() > std::numeric_limits<std::uint32_t>::max())
        throw std::length_error("Motion: more than 2^32 - 1 steps");
    return static_cast<std::uint32_t>(v.size());
}

template <class T>
void copy_into(std::byte* block, std::size_t offset, const std::vector<T>& v) {
    if (!v.empty()) std::memcpy(block + offset, v.data(), v.size() * sizeof(T));
}

}  // namespace

void Motion::finish_stages(const Arrays& a) {
    // The block holds its arrays as raw bytes: each type must be plain data.
    static_assert(std::is_trivially_copyable_v<FixedMaps> &&
                  std::is_trivially_copyable_v<Deformation> &&
                  std::is_trivially_copyable_v<Parameter> && std::is_trivially_copyable_v<Stage> &&
                  std::is_trivially_copyable_v<Step>);
    fixed_count_ = count_of(a.fixed);
    deformation_count_ = count_of(a.deformations);
    parameter_count_ = count_of(a.parameters);
    stage_count_ = count_of(a.stages);
    step_count_ = count_of(a.steps);
    block_.reset();
    if (const std::size_t bytes = block_bytes(); bytes > 0) {
        block_ = std::make_unique_for_overwrite<std::byte[]>(bytes);
        copy_into(block_.get(), 0, a.fixed);
        copy_into(block_.get(), deformations_offset(), a.deformations);
        copy_into(block_.get(), parameters_offset(), a.parameters);
        copy_into(block_.get(), stages_offset(), a.stages);
        copy_into(block_.get(), steps_offset(), a.steps);
    }
    fixed_affine_ = affine_ && !moving_;
    // Constant and affine: only Fixed stages exist, and consecutive ones
    // were merged, so there is at most one (fixed_map()).
    if (fixed_affine_ && fixed_count_ > 1) throw std::logic_error("Motion: unmerged fixed stages");
}

Motion::Motion(const Motion& o)
    : moving_(o.moving_),
      fixed_affine_(o.fixed_affine_),
      affine_(o.affine_),
      identity_(o.identity_),
      stage_count_(o.stage_count_),
      fixed_count_(o.fixed_count_),
      step_count_(o.step_count_),
      parameter_count_(o.parameter_count_),
      deformation_count_(o.deformation_count_),
      tape_(o.tape_) {
    if (o.block_) {
        block_ = std::make_unique_for_overwrite<std::byte[]>(o.block_bytes());
        std::memcpy(block_.get(), o.block_.get(), o.block_bytes());
    }
}

Motion::Motion(Motion&& o) noexcept
    : moving_(std::exchange(o.moving_, false)),
      fixed_affine_(std::exchange(o.fixed_affine_, true)),
      affine_(std::exchange(o.affine_, true)),
      identity_(std::exchange(o.identity_, true)),
      stage_count_(std::exchange(o.stage_count_, 0)),
      fixed_count_(std::exchange(o.fixed_count_, 0)),
      step_count_(std::exchange(o.step_count_, 0)),
      parameter_count_(std::exchange(o.parameter_count_, 0)),
      deformation_count_(std::exchange(o.deformation_count_, 0)),
      block_(std::move(o.block_)),
      tape_(std::move(o.tape_)) {}

Motion& Motion::operator=(Motion&& o) noexcept {
    if (this != &o) {
        Motion moved(std::move(o));
        std::swap(moving_, moved.moving_);
        std::swap(fixed_affine_, moved.fixed_affine_);
        std::swap(affine_, moved.affine_);
        std::swap(identity_, moved.identity_);
        std::swap(stage_count_, moved.stage_count_);
        std::swap(fixed_count_, moved.fixed_count_);
        std::swap(step_count_, moved.step_count_);
        std::swap(parameter_count_, moved.parameter_count_);
        std::swap(deformation_count_, moved.deformation_count_);
        std::swap(block_, moved.block_);
        std::swap(tape_, moved.tape_);
    }
    return *this;
}

Motion& Motion::operator=(const Motion& o) {
    if (this != &o) {
        Motion copy(o);
        *this = std::move(copy);
    }
    return *this;
}

void Motion::append_fixed(Arrays& a, const AffineMap<double>& forward,
                          const AffineMap<double>& backward) {
    if (!a.stages.empty() && a.stages.back().kind == StageKind::Fixed) {
        FixedMaps& last = a.fixed[a.stages.back().index];
        last.forward = forward * last.forward;
        last.backward = last.backward * backward;
    } else {
        Stage stage;
        stage.index = static_cast<std::uint32_t>(a.fixed.size());
        a.fixed.push_back({forward, backward});
        a.stages.push_back(stage);
    }
    identity_ = identity_ && to_glm(a.fixed[a.stages.back().index].forward) == glm::dmat4(1.0);
}

Motion Motion::at_instant(double t) const {
    if (!moving_) return *this;
    const MotionEvaluator<double> e(*this, t);
    Motion frozen;
    Arrays a;
    for (const Stage& stage : stages()) {
        switch (stage.kind) {
            case StageKind::Fixed:
                frozen.append_fixed(a, fixed_of(stage).forward, fixed_of(stage).backward);
                break;
            case StageKind::Moving:
                frozen.append_fixed(a, e.stage_map(stage, false), e.stage_map(stage, true));
                break;
            default: {
                const Deformation& d = deformation_of(stage);
                const double amount = e.value(d.amount);
                // A twist, taper or bend by 0 is the identity (deformation.hpp).
                if (amount == 0.0) break;
                Deformation fixed = d;
                fixed.amount = Parameter{ClockLine::constant(amount), -1};
                if (!stage.fixed_frame)
                    fixed.frame = deformation_frame(std::array<double, 3>{
                        e.value(d.axis[0]), e.value(d.axis[1]), e.value(d.axis[2])});
                Stage frozen_stage = stage;
                frozen_stage.fixed_frame = true;
                frozen_stage.index = static_cast<std::uint32_t>(a.deformations.size());
                a.deformations.push_back(fixed);
                a.stages.push_back(frozen_stage);
                frozen.affine_ = false;
                frozen.identity_ = false;
                break;
            }
        }
    }
    frozen.finish_stages(a);
    return frozen;
}

template <class N>
std::array<N, 3> Motion::to_world_general(const std::array<N, 3>& p, const N& t) const {
    const MotionEvaluator<N> e(*this, t);
    std::array<N, 3> q = p;
    for (const Stage& stage : stages()) q = e.through(stage, q, false);
    return q;
}

template <class N>
std::array<N, 3> Motion::to_object_general(const std::array<N, 3>& p, const N& t) const {
    const MotionEvaluator<N> e(*this, t);
    std::array<N, 3> q = p;
    for (auto it = stages().rbegin(); it != stages().rend(); ++it) q = e.through(*it, q, true);
    return q;
}

template std::array<double, 3> Motion::to_world_general(const std::array<double, 3>&,
                                                        const double&) const;
template std::array<Interval, 3> Motion::to_world_general(const std::array<Interval, 3>&,
                                                          const Interval&) const;
template std::array<Dual, 3> Motion::to_world_general(const std::array<Dual, 3>&,
                                                      const Dual&) const;
template std::array<double, 3> Motion::to_object_general(const std::array<double, 3>&,
                                                         const double&) const;
template std::array<Interval, 3> Motion::to_object_general(const std::array<Interval, 3>&,
                                                           const Interval&) const;
template std::array<Dual, 3> Motion::to_object_general(const std::array<Dual, 3>&,
                                                       const Dual&) const;

std::vector<double> Motion::twist_reaches(const IntervalBox& object_box, const Interval& t) const {
    std::vector<double> reaches;
    const bool any = std::any_of(stages().begin(), stages().end(), [](const Stage& stage) {
        return stage.kind == StageKind::Twist && stage.fixed_frame;
    });
    if (!any) return reaches;
    // The double maps turn a point by a sine and a cosine off by kLibmUlps
    // each, round two products and a sum, and round the frame's projections
    // (a few ulps of the point's largest coordinate): the margin covers that
    // drift of a point's distance from the axis, so that the exact curve and
    // the double one agree on what is beyond reach.
    constexpr double kDrift = (deformation_detail::kRotationUlps + 16) * 0x1p-52;
    const MotionEvaluator<Interval> e(*this, t);
    IntervalBox box = object_box;
    for (const Stage& stage : stages()) {
        double reach = interval_detail::kInf;
        if (stage.kind == StageKind::Twist && stage.fixed_frame) {
            const IntervalBox local = to_local(box, deformation_of(stage).frame);
            const double far = deformation_detail::section_radius(local).hi;
            const double largest =
                std::max({local[0].magnitude(), local[1].magnitude(), local[2].magnitude()});
            if (std::isfinite(far) && std::isfinite(largest))
                reach = interval_detail::next_up(far + kDrift * (far + largest));
        }
        reaches.push_back(reach);
        box = e.through(stage, box, false);
    }
    return reaches;
}

std::optional<IntervalBox> Motion::to_object_within(const IntervalBox& p, const Interval& t,
                                                    const std::vector<double>& reaches) const {
    if (reaches.size() != stage_count_) return to_object(p, t);
    const MotionEvaluator<Interval> e(*this, t);
    IntervalBox q = p;
    for (std::size_t k = stage_count_; k-- > 0;) {
        const Stage& stage = stages()[k];
        if (stage.kind == StageKind::Twist && stage.fixed_frame &&
            deformation_detail::section_radius(to_local(q, deformation_of(stage).frame)).lo >
                reaches[k])
            return std::nullopt;
        q = e.through(stage, q, true);
    }
    return q;
}

glm::dmat4 Motion::matrix_at(double t) const {
    return to_glm(map_at(t));
}

AffineMap<double> Motion::map_at(double t) const {
    if (fixed_affine_) return fixed_map().forward;
    if (!affine_) throw std::logic_error("Motion::map_at on a deformed object");
    const MotionEvaluator<double> e(*this, t);
    AffineMap<double> m = AffineMap<double>::identity();
    for (const Stage& stage : stages()) e.compose(stage, m);
    return m;
}

glm::dmat4 Motion::inverse_at(double t) const {
    if (fixed_affine_) return to_glm(fixed_map().backward);
    if (!affine_) throw std::logic_error("Motion::inverse_at on a deformed object");
    const MotionEvaluator<double> e(*this, t);
    AffineMap<double> m = AffineMap<double>::identity();
    for (auto it = stages().rbegin(); it != stages().rend(); ++it)
        m = (it->kind == StageKind::Fixed ? fixed_of(*it).backward : e.stage_map(*it, true)) * m;
    return to_glm(m);
}

Motion::Placement Motion::placement_at(double t) const {
    if (fixed_affine_) return {to_glm(fixed_map().forward), to_glm(fixed_map().backward)};
    if (!affine_) throw std::logic_error("Motion::placement_at on a deformed object");
    const MotionEvaluator<double> e(*this, t);
    AffineMap<double> forward = AffineMap<double>::identity();
    for (const Stage& stage : stages()) e.compose(stage, forward);
    // The inverse from the matrix itself (its adjugate over its
    // determinant), not from the steps again: a moving object pays one
    // evaluation of its sines and cosines per ray, not two. Each entry is
    // within a few ulps of the steps' own inverse, relative to the map's
    // condition (a singular `matrix` divides by zero as inverse_at does).
    return {to_glm(forward), to_glm(inverse_of(forward))};
}

IntervalAffine Motion::matrix_over(const Interval& t) const {
    if (fixed_affine_) return IntervalAffine::from(fixed_map().forward);
    if (!affine_) throw std::logic_error("Motion::matrix_over on a deformed object");
    const MotionEvaluator<Interval> e(*this, t);
    IntervalAffine m = IntervalAffine::identity();
    for (const Stage& stage : stages()) e.compose(stage, m);
    return m;
}

AffineMap<IntervalJet> Motion::matrix_jet_over(const Interval& t) const {
    if (fixed_affine_) return AffineMap<IntervalJet>::from(fixed_map().forward);
    if (!affine_) throw std::logic_error("Motion::matrix_jet_over on a deformed object");
    const MotionEvaluator<IntervalJet> e(*this, IntervalJet::variable(t));
    AffineMap<IntervalJet> m = AffineMap<IntervalJet>::identity();
    for (const Stage& stage : stages()) e.compose(stage, m);
    return m;
}

IntervalBox Motion::world_box(const IntervalBox& object_box, const Interval& t) const {
    if (fixed_affine_) return fixed_map().forward.apply(object_box);
    if (affine_) return matrix_over(t).apply(object_box);
    // Interval evaluation of a deformation over a wide box overestimates
    // (the dependency problem grows with the box); the images of the eight
    // half boxes, unioned, are often much tighter, and the true image lies
    // inside both answers.
    IntervalBox whole = to_world(object_box, t);
    IntervalBox pieces{Interval(interval_detail::kInf, -interval_detail::kInf),
                       Interval(interval_detail::kInf, -interval_detail::kInf),
                       Interval(interval_detail::kInf, -interval_detail::kInf)};
    for (int corner = 0; corner < 8; ++corner) {
        IntervalBox half;
        for (int i = 0; i < 3; ++i) {
            const Interval& b = object_box[i];
            const double m = b.mid();
            half[i] = (corner >> i & 1) ? Interval(m, b.hi) : Interval(b.lo, m);
        }
        const IntervalBox image = to_world(half, t);
        for (int i = 0; i < 3; ++i) pieces[i] = hull(pieces[i], image[i]);
    }
    for (int i = 0; i < 3; ++i) {
        const Interval both = intersect(whole[i], pieces[i]);
        whole[i] = both.is_empty() ? hull(whole[i], pieces[i]) : both;
    }
    return whole;
}

glm::dmat3 Motion::jacobian_at(const glm::dvec3& object_point, double t) const {
    if (fixed_affine_) return glm::dmat3(to_glm(fixed_map().forward));
    const MotionEvaluator<double> e(*this, t);
    glm::dmat3 j(1.0);
    std::array<double, 3> p{object_point.x, object_point.y, object_point.z};
    for (const Stage& stage : stages()) {
        glm::dmat3 step(1.0);
        if (stage.kind == StageKind::Fixed) {
            step = glm::dmat3(to_glm(fixed_of(stage).forward));
        } else if (stage.kind == StageKind::Moving) {
            step = glm::dmat3(to_glm(e.stage_map(stage, false)));
        } else {
            const Deformation& d = deformation_of(stage);
            const double amount = e.value(d.amount);
            const DeformationFrame<double> frame =
                stage.fixed_frame
                    ? d.frame
                    : deformation_frame(std::array<double, 3>{
                          e.value(d.axis[0]), e.value(d.axis[1]), e.value(d.axis[2])});
            // An inverse stage's Jacobian is the inverse of the forward one
            // at the stage's output, its preimage.
            const std::array<double, 3> at = stage.inverse ? e.through(stage, p, false) : p;
            const glm::dvec3 x(at[0], at[1], at[2]);
            switch (stage.kind) {
                case StageKind::Twist:
                    step = twist_jacobian(x, frame, amount);
                    break;
                case StageKind::Taper:
                    step = taper_jacobian(x, frame, amount);
                    break;
                default:
                    step = bend_jacobian(x, frame, amount);
                    break;
            }
            if (stage.inverse) step = glm::inverse(step);
        }
        j = step * j;
        p = e.through(stage, p, false);
    }
    return j;
}

}  // namespace hexant::runtime
