#include "runtime/texture/pattern/warps/point_warp.hpp"

#include <type_traits>

#include "runtime/texture/pattern/warps/cubic_warp.hpp"
#include "runtime/texture/pattern/warps/cylindrical_warp.hpp"
#include "runtime/texture/pattern/warps/planar_warp.hpp"
#include "runtime/texture/pattern/warps/spherical_warp.hpp"
#include "runtime/texture/pattern/warps/toroidal_warp.hpp"
#include "runtime/time/time_tape.hpp"

namespace hexant::runtime::pattern {

namespace {

// Each warp's numbers, in the order its `at` reads them.
std::vector<TimeFunction> numbers_of(const PointWarp& warp) {
    return std::visit(
        [](const auto& w) -> std::vector<TimeFunction> {
            using W = std::decay_t<decltype(w)>;
            if constexpr (std::is_same_v<W, RepeatWarp>)
                return {w.width,     w.offset.c[0], w.offset.c[1], w.offset.c[2],
                        w.flip.c[0], w.flip.c[1],   w.flip.c[2]};
            else if constexpr (std::is_same_v<W, BlackHoleWarp>)
                return black_hole_numbers(w);
            else
                return {w.orientation.c[0], w.orientation.c[1], w.orientation.c[2],
                        w.dist_exp,         w.major_radius,     w.distance};
        },
        warp);
}

}  // namespace

bool depends_on_time(const PointWarp& warp) {
    return std::visit([](const auto& w) { return w.depends_on_time(); }, warp);
}

CompiledPointWarp::CompiledPointWarp(const PointWarp& source) : source_(source) {
    const std::vector<TimeFunction> numbers = numbers_of(source);
    if (depends_on_time(source)) {
        tape_ = std::make_shared<const TimeTape>(TimeTape::compile(numbers));
        return;
    }
    std::vector<double> values;
    for (const TimeFunction& n : numbers) values.push_back(n.constant());
    fixed_ = at(values.data());
}

CompiledPointWarp::At CompiledPointWarp::at(const double* n) const {
    return std::visit(
        [n](const auto& w) -> At {
            using W = std::decay_t<decltype(w)>;
            if constexpr (std::is_same_v<W, RepeatWarp>)
                return repeat_at(w.axis, n[0], {n[1], n[2], n[3]}, {n[4], n[5], n[6]});
            else if constexpr (std::is_same_v<W, BlackHoleWarp>)
                return black_hole_at(w, n);
            else
                // (POV-Ray makes the orientation unit when it reads it.)
                return MappingAt{w.shape, unit_orientation({n[0], n[1], n[2]}), n[3], n[4], n[5]};
        },
        source_);
}

glm::dvec3 CompiledPointWarp::apply(const glm::dvec3& p, double t) const {
    At moving;
    if (tape_) {
        constexpr std::size_t kOnStack = 32;
        double numbers[kOnStack];
        std::vector<double> more;
        double* out = numbers;
        if (tape_->output_count() > kOnStack) {
            more.resize(tape_->output_count());
            out = more.data();
        }
        tape_->evaluate(t, out);
        moving = at(out);
    }
    const At& w = tape_ ? moving : fixed_;
    if (const auto* r = std::get_if<RepeatAt>(&w)) return repeat_point(*r, p);
    if (const auto* h = std::get_if<BlackHoleAt>(&w)) return black_hole_point(*h, p);
    const MappingAt& m = std::get<MappingAt>(w);
    switch (m.shape) {
        case MappingShape::Planar:
            return planar_point(m, p);
        case MappingShape::Cylindrical:
            return cylindrical_point(m, p);
        case MappingShape::Spherical:
            return spherical_point(m, p);
        case MappingShape::Toroidal:
            return toroidal_point(m, p);
        case MappingShape::Cubic:
            break;
    }
    return cubic_point(p);
}

}  // namespace hexant::runtime::pattern
