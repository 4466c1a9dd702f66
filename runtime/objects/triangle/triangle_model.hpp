// The triangle's and smooth triangle's time functions: vertices (and the
// smooth triangle's vertex normals, which move no surface).
#pragma once

#include <algorithm>

#include "runtime/objects/model_support.hpp"
#include "runtime/objects/triangle/smooth_triangle.hpp"
#include "runtime/objects/triangle/smooth_triangle_geometry.hpp"
#include "runtime/objects/triangle/triangle.hpp"
#include "runtime/objects/triangle/triangle_geometry.hpp"

namespace hexant::runtime::objects {

// Vertices as compiled functions: the box of a flat shape over time is the
// hull of its vertices' ranges, and its surface moves no farther than its
// farthest-moving vertex (every point is a convex blend of them).
template <std::size_t N>
struct CompiledVertices {
    std::array<CompiledVector3, N> v;

    bool is_static() const {
        return std::all_of(v.begin(), v.end(), [](const auto& p) { return p.is_constant(); });
    }
    IntervalBox box_over(const Interval& t) const {
        IntervalBox box = empty_interval_box();
        for (const auto& p : v) box = hull(box, p.over(t));
        return box;
    }
    double motion(const Interval& t, const std::array<glm::dvec3, N>& mid) const {
        double m = 0.0;
        for (std::size_t i = 0; i < N; ++i) m = std::max(m, deviation(v[i], t, mid[i]));
        return m;
    }
};

class TriangleModel {
  public:
    using Geometry = geometry::TriangleGeometry;
    static constexpr bool kSolid = false;
    static constexpr bool kFlat = true;

    explicit TriangleModel(const Triangle& tri)
        : points_{{CompiledVector3(tri.points[0]), CompiledVector3(tri.points[1]),
                   CompiledVector3(tri.points[2])}} {}

    bool is_static() const { return points_.is_static(); }
    Geometry at(double t) const {
        return {points_.v[0].at(t), points_.v[1].at(t), points_.v[2].at(t)};
    }
    IntervalBox box_over(const Interval& t) const { return points_.box_over(t); }
    double surface_motion(const Interval& t, const Geometry& mid) const {
        return points_.motion(t, {mid.p1, mid.p2, mid.p3});
    }
    static double volume(const Geometry&) { return 0.0; }

  private:
    CompiledVertices<3> points_;
};

class SmoothTriangleModel {
  public:
    using Geometry = geometry::SmoothTriangleGeometry;
    static constexpr bool kSolid = false;
    static constexpr bool kFlat = true;

    explicit SmoothTriangleModel(const SmoothTriangle& tri)
        : points_{{CompiledVector3(tri.points[0]), CompiledVector3(tri.points[1]),
                   CompiledVector3(tri.points[2])}},
          normals_{{CompiledVector3(tri.normals[0]), CompiledVector3(tri.normals[1]),
                    CompiledVector3(tri.normals[2])}} {}

    bool is_static() const { return points_.is_static() && normals_.is_static(); }
    Geometry at(double t) const {
        return {points_.v[0].at(t),  normals_.v[0].at(t), points_.v[1].at(t),
                normals_.v[1].at(t), points_.v[2].at(t),  normals_.v[2].at(t)};
    }
    IntervalBox box_over(const Interval& t) const { return points_.box_over(t); }
    double surface_motion(const Interval& t, const Geometry& mid) const {
        return points_.motion(t, {mid.p1, mid.p2, mid.p3});
    }
    static double volume(const Geometry&) { return 0.0; }

  private:
    CompiledVertices<3> points_;
    CompiledVertices<3> normals_;
};

}  // namespace hexant::runtime::objects
