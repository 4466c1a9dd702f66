// A mesh's model: nothing moves in object space (its transforms move it);
// its hierarchy's nodes are the pieces of its bound.
#pragma once

#include "runtime/objects/mesh/mesh.hpp"
#include "runtime/objects/mesh/mesh_geometry.hpp"
#include "runtime/objects/model_support.hpp"

namespace hexant::runtime::objects {

class MeshModel {
  public:
    using Geometry = geometry::MeshGeometry;
    static constexpr bool kSolid = true;      // with an inside_vector; inside() says
    static constexpr bool kUvMapping = true;  // POV-Ray 3.7 maps it (primitive.hpp)

    explicit MeshModel(const Mesh& mesh) : data_(mesh.data) {}

    bool is_static() const { return true; }
    Geometry at(double) const { return {data_}; }
    IntervalBox box_over(const Interval&) const {
        return data_->hierarchy.empty() ? empty_interval_box()
                                        : to_interval_box(data_->hierarchy.box());
    }
    double surface_motion(const Interval&, const Geometry&) const { return 0.0; }
    static double volume(const Geometry&) { return -1.0; }

    // The texture of the face a hit found (hit.part), or -1: the object's.
    int texture_of(int part) const {
        if (part < 0 || static_cast<std::size_t>(part) >= data_->faces.size()) return -1;
        return data_->faces[static_cast<std::size_t>(part)].texture;
    }

    // The paper's star cluster: calls emit(box) for object-space boxes that
    // together hold the surface; refine(box) says what to do with a node's
    // box: 0 skip it (it misses the region), 1 emit it, 2 look at its
    // children (a leaf's box is emitted).
    template <class Refine, class Emit>
    void pieces(Refine&& refine, Emit&& emit) const {
        data_->hierarchy.descend([&](const BoxHierarchy::Node& node) {
            const IntervalBox box = to_interval_box(node.box);
            const int what = refine(box);
            if (what == 0) return false;
            if (what == 1 || node.count > 0) {
                emit(box);
                return false;
            }
            return true;
        });
    }

  private:
    std::shared_ptr<const MeshData> data_;
};

}  // namespace hexant::runtime::objects
