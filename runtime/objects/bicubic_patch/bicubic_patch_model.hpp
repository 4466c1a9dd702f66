// The bicubic_patch's time functions: its control points and uv_vectors,
// and the placement's linear part, in which POV-Ray measures its flatness
// and normals (bicubic_patch_geometry.hpp).
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include <glm/mat3x3.hpp>

#include "runtime/motion/transform.hpp"
#include "runtime/objects/bicubic_patch/bicubic_patch.hpp"
#include "runtime/objects/bicubic_patch/bicubic_patch_geometry.hpp"
#include "runtime/objects/model_support.hpp"
#include "runtime/objects/triangle/triangle_model.hpp"

namespace hexant::runtime::objects {

class BicubicPatchModel {
  public:
    using Geometry = geometry::BicubicPatchGeometry;
    static constexpr bool kSolid = false;
    static constexpr bool kUvMapping = true;  // POV-Ray's BicubicPatch::UVCoord

    // `to_world`: the object's whole placement (the factory passes it).
    BicubicPatchModel(const BicubicPatch& patch, const Transform& to_world)
        : flatness_(patch.flatness), u_steps_(patch.u_steps), v_steps_(patch.v_steps) {
        for (std::size_t k = 0; k < 16; ++k) points_.v[k] = CompiledVector3(patch.points[k]);
        for (std::size_t k = 0; k < 4; ++k)
            uv_[k] = CompiledVector3(Vector3Function{
                {patch.uv_corners[k].c[0], patch.uv_corners[k].c[1], TimeFunction(0.0)}});
        // A deformed object is measured in object space (hexant's
        // deformations have no POV-Ray counterpart); otherwise in the world,
        // at each instant where the linear part moves.
        if (!to_world.has_deformation()) {
            measure_moves_ = linear_part_moves(to_world);
            if (measure_moves_)
                placement_ = to_world;
            else
                measure_ = glm::dmat3(to_world.matrix_at(0.0));
        }
    }

    bool is_static() const {
        bool fixed = points_.is_static() && !measure_moves_;
        for (const auto& uv : uv_) fixed = fixed && uv.is_constant();
        return fixed;
    }
    // The patch at t; a patch that never changes keeps its subdivision.
    Geometry at(double t) const {
        Geometry g;
        for (std::size_t k = 0; k < 16; ++k) g.points[k] = points_.v[k].at(t);
        g.measure = measure_moves_ ? glm::dmat3(placement_.matrix_at(t)) : measure_;
        g.flatness = flatness_;
        g.u_steps = u_steps_;
        g.v_steps = v_steps_;
        for (std::size_t k = 0; k < 4; ++k) {
            const glm::dvec3 uv = uv_[k].at(t);
            g.uv_corners[k] = {uv.x, uv.y};
        }
        if (is_static()) geometry::keep_subdivision(g);
        return g;
    }
    // The control points' hull holds every piece's corners.
    IntervalBox box_over(const Interval& t) const { return points_.box_over(t); }
    // With no flatness test the pieces are fixed blends of the control
    // points (each halving takes midpoints), so no point of them moves
    // farther than the farthest control point. With one, another instant
    // may cut the patch otherwise: both surfaces lie in the box over t,
    // whose diagonal bounds how far apart they are.
    double surface_motion(const Interval& t, const Geometry& mid) const {
        if (!(flatness_ > 0.0)) return points_.motion(t, mid.points);
        const IntervalBox box = box_over(t);
        double sum = 0.0;
        for (int i = 0; i < 3; ++i) {
            const double w = box[i].hi - box[i].lo;
            sum += w * w;
        }
        return std::nextafter(std::sqrt(sum) * (1.0 + 8.0 * 1.1102230246251565e-16),
                              std::numeric_limits<double>::infinity());
    }
    static double volume(const Geometry&) { return 0.0; }

  private:
    // Whether a step other than a translation depends on time.
    static bool linear_part_moves(const Transform& t) {
        for (const TransformStep& step : t.steps())
            if (step.kind != TransformKind::Translate && step.depends_on_time()) return true;
        return false;
    }

    CompiledVertices<16> points_;
    std::array<CompiledVector3, 4> uv_;
    double flatness_;
    int u_steps_, v_steps_;
    bool measure_moves_ = false;
    glm::dmat3 measure_{1.0};
    Transform placement_;  // kept only when the measure moves
};

}  // namespace hexant::runtime::objects
