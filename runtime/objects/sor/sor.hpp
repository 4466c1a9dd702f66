// POV-Ray's sor { N, <P0>, ..., <PN-1> [open] [sturm] }: a surface of
// revolution about y whose squared radius is a cubic in the height. The
// object kind (runtime/objects/shape_kind.hpp); `sturm` is a modifier the
// language reads for every object.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "runtime/objects/shape_kind.hpp"
#include "runtime/objects/sor/sor_geometry.hpp"
#include "runtime/time/vector_function.hpp"

namespace hexant::runtime {

namespace objects {
class SorModel;
}  // namespace objects

struct Sor {
    static constexpr std::string_view keyword = "sor";
    static constexpr std::array<std::string_view, 1> settings{"open"};
    using Model = objects::SorModel;

    std::vector<Vector2Function> points;
    bool open = false;

    static Sor read(const objects::ShapeArguments& a);
    void set(std::string_view, const objects::ShapeArguments& value) {
        open = objects::flag(value);
    }
    template <class F>
    void parameters(F&& f) const {
        f("points", "point", points);
        f("open", "open", open);
    }
};

}  // namespace hexant::runtime

#include "runtime/objects/sor/sor_model.hpp"
