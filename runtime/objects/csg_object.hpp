// Groups and constructive solid geometry over intelligent objects: union,
// merge, intersection and difference. The children already carry the
// group's transform (the factory composes it into each), so a group only
// combines its children's answers.
#pragma once

#include <vector>

#include "runtime/objects/intelligent_object.hpp"
#include "runtime/objects/shapes.hpp"

namespace hexant::runtime {

class CsgObject final : public IntelligentObject {
  public:
    CsgObject(Csg::Kind kind, std::vector<IntelligentObjectPtr> children, bool inverse);

    bool bounded() const override;
    bool solid_bounded() const override;
    // A union answers with its children's bounds (several, each tight); an
    // intersection with the smallest of those of its children whose solids
    // are bounded; a difference with its first child's (whose solid must
    // be bounded): every surface event of the result lies in those.
    void bound(const Box4& region, std::vector<SlabBound>& out) const override;
    // The same rule for boxes: a union's is the hull of its children's; an
    // intersection's the common part of its bounded children's; a
    // difference's its first child's.
    Box4 box_over(const Interval& t) const override;
    std::optional<ChordBound> chord_bound_over(const Interval& t) const override;
    Box4 placed_box_at(double t) const override;
    std::optional<ObjectHit> intersect(const Ray4& ray, double s_min, double s_max) const override;
    SurfacePoint complete(const Ray4& ray, const ObjectHit& hit) const override;
    bool inside(const Event& event) const override;
    double occupancy(const Box4& region) const override;
    bool moves() const override;
    bool deformed() const override;
    // A group casts a shadow where any child does (no_shadow passes down).
    bool casts_shadow() const override;
    bool filters_light() const override;
    bool casts_full_shadow() const override { return full_shadow_; }
    // (The group's media are its children's, shared: the first found.)
    const MediaVolume* interior_media() const override;
    // (Its members' shared interior: the first member's.)
    RefractiveInterior refractive_interior(double t) const override;

    Csg::Kind kind() const { return kind_; }
    const std::vector<IntelligentObjectPtr>& children() const { return children_; }

  private:
    // The children whose placed boxes and chord bounds hold the surface.
    std::vector<const IntelligentObject*> chord_children() const;
    // Is a hit on child `index` a surface of the combined solid?
    bool keeps(std::size_t index, const Event& event) const;

    Csg::Kind kind_;
    std::vector<IntelligentObjectPtr> children_;
    bool full_shadow_ = true;
    bool inverse_;
};

}  // namespace hexant::runtime
