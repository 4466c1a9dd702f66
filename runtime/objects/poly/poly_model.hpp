// The polynomial surface's time functions: its coefficients. Unbounded:
// the tracer keeps it outside the hierarchy (its bounded_by and clipped_by
// give it a place there, runtime/objects/object_factory.cpp).
#pragma once

#include <limits>
#include <vector>

#include "runtime/objects/model_support.hpp"
#include "runtime/objects/poly/poly.hpp"
#include "runtime/objects/poly/poly_geometry.hpp"

namespace hexant::runtime::objects {

class PolyModel {
  public:
    using Geometry = geometry::PolyGeometry;
    static constexpr bool kSolid = true;
    static constexpr bool kUnbounded = true;

    explicit PolyModel(const PolySurface& s) : order_(s.order) {
        for (const TimeFunction& c : s.coefficients) coefficients_.emplace_back(c);
    }

    bool is_static() const {
        for (const auto& c : coefficients_)
            if (!c.is_constant()) return false;
        return true;
    }
    Geometry at(double t) const {
        Geometry g;
        g.order = order_;
        g.coefficients.reserve(coefficients_.size());
        for (const auto& c : coefficients_) g.coefficients.push_back(c.at(t));
        return g;
    }
    IntervalBox box_over(const Interval&) const {
        const Interval all = Interval::entire();
        return {all, all, all};
    }
    double surface_motion(const Interval&, const Geometry&) const {
        return std::numeric_limits<double>::infinity();
    }
    static double volume(const Geometry&) { return std::numeric_limits<double>::infinity(); }

  private:
    int order_;
    std::vector<CompiledScalar> coefficients_;
};

}  // namespace hexant::runtime::objects
