// The height field's time functions: its water level (the grid is fixed
// when the scene is read). Its quadtree's nodes are the pieces of its bound.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "runtime/objects/height_field/height_field.hpp"
#include "runtime/objects/height_field/height_field_geometry.hpp"
#include "runtime/objects/model_support.hpp"

namespace hexant::runtime::objects {

class HeightFieldModel {
  public:
    using Geometry = geometry::HeightFieldGeometry;
    static constexpr bool kSolid = true;

    explicit HeightFieldModel(const HeightField& field)
        : data_(field.data), water_(field.water_level), smooth_(field.smooth) {
        if (data_ && smooth_) (void)data_->smooth_normals();  // computed now, not mid-render
    }

    bool is_static() const { return water_.is_constant(); }
    Geometry at(double t) const {
        if (!data_) return {};
        return {data_, geometry::height_field_floor(*data_, water_.at(t)), smooth_};
    }
    // The field's box with its floor at the lowest water level over t.
    IntervalBox box_over(const Interval& t) const {
        if (!data_) return empty_interval_box();
        return to_interval_box(geometry::object_bounds(Geometry{data_, lowest_floor(t), smooth_}));
    }
    // A moving water level cuts away or uncovers whole triangles: no small
    // bound holds, so the diameter of the unit box the field lies in.
    double surface_motion(const Interval& t, const Geometry&) const {
        if (water_.is_constant()) return 0.0;
        (void)t;
        return 2.0;
    }
    static double volume(const Geometry&) { return -1.0; }

    // Calls emit(box) for object-space boxes that together hold the
    // surface (the quadtree's nodes; refine: 0 skip, 1 emit, 2 descend),
    // for every water level (their floors at the lowest one).
    template <class Refine, class Emit>
    void pieces(Refine&& refine, Emit&& emit) const {
        if (!data_) return;
        const double floor =
            water_.is_constant() ? geometry::height_field_floor(*data_, water_.constant()) : -1.0;
        const double floor_height = floor * 65536.0;
        const auto& nodes = data_->nodes();
        data_->descend([&](std::uint32_t i) {
            const auto& node = nodes[i];
            if (node.hi < floor_height) return false;
            const IntervalBox box = to_interval_box(data_->node_box(node, floor));
            const int what = refine(box);
            if (what == 0) return false;
            if (what == 1 || node.count == 0) {
                emit(box);
                return false;
            }
            return true;
        });
    }

    // A smooth field's shading normal at an object-space point, its corners
    // weighted by their lengths under `to_world` (the linear map to the
    // world at the hit), as POV-Ray blends them in the world
    // (height_field_smooth_normal); nullopt for a field that is not smooth.
    std::optional<glm::dvec3> world_shading_normal(const glm::dvec3& point,
                                                   const glm::dmat3& to_world) const {
        if (!data_ || !smooth_) return std::nullopt;
        const glm::dmat3 normal_to_world = glm::transpose(glm::inverse(to_world));
        return geometry::height_field_smooth_normal(*data_, point, &normal_to_world);
    }

  private:
    double lowest_floor(const Interval& t) const {
        if (water_.is_constant()) return geometry::height_field_floor(*data_, water_.constant());
        const Interval w = water_.over(t);
        return geometry::height_field_floor(*data_, std::isfinite(w.lo) ? w.lo : 0.0);
    }

    std::shared_ptr<const HeightFieldData> data_;
    CompiledScalar water_;
    bool smooth_ = false;
};

}  // namespace hexant::runtime::objects
