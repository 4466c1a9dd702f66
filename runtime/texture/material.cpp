#include "runtime/texture/material.hpp"

#include <set>
#include <utility>

namespace hexant::runtime {

namespace {

// A declared graph of maps may share entries (T1 a checker of T0 and T0
// scaled, T2 of T1 ...): each entry is looked at once. One seen before did
// not depend on time, or the search would have stopped there. (A texture
// and its pigment share an address: the kind is part of the key.)
using Seen = std::set<std::pair<int, const void*>>;
constexpr int kind_of(const Pigment*) {
    return 0;
}
constexpr int kind_of(const Normal*) {
    return 1;
}
constexpr int kind_of(const Texture*) {
    return 2;
}
bool depends(const Pigment& p, Seen& seen);
bool depends(const Normal& n, Seen& seen);
bool depends(const Texture& t, Seen& seen);
template <class Record>
bool entry_depends(const Record& r, Seen& seen) {
    return seen.insert({kind_of(&r), &r}).second && depends(r, seen);
}
// A pattern's numbers, and the pigment a pigment_pattern reads.
bool pattern_depends(const pattern::Pattern& p, Seen& seen) {
    return p.depends_on_time() || (p.pigment && entry_depends(*p.pigment, seen));
}

}  // namespace

bool ColourMap::depends_on_time() const {
    for (const auto& e : entries)
        if (e.value.depends_on_time() || e.colour.depends_on_time()) return true;
    return false;
}

namespace {

bool colour_may_filter(const ColourFunction& c) {
    for (const int k : {3, 4})
        if (!c.c[k].is_constant() || c.c[k].constant() != 0.0) return true;
    return false;
}

bool may_filter(const Pigment& p, Seen& seen) {
    using Pattern = Pigment::Pattern;
    if (p.pattern == Pattern::Solid) return colour_may_filter(p.colours.front());
    if (p.pattern == Pattern::Image) return true;
    if (p.pattern == Pattern::Unsupported) return false;
    for (const auto& e : p.colour_map.entries)
        if (colour_may_filter(e.colour)) return true;
    for (const auto& e : p.pigment_map)
        if (seen.insert({0, e.pigment.get()}).second && may_filter(*e.pigment, seen)) return true;
    return false;
}

}  // namespace

bool Pigment::may_filter() const {
    Seen seen;
    return hexant::runtime::may_filter(*this, seen);
}

bool Texture::opaque() const {
    if (is_patterned()) return false;
    if (!pigment.may_filter()) return true;
    for (const Texture& layer : below)
        if (layer.opaque()) return true;
    return false;
}

bool Pigment::depends_on_time() const {
    Seen seen;
    return depends(*this, seen);
}
bool Normal::depends_on_time() const {
    Seen seen;
    return depends(*this, seen);
}
bool Texture::depends_on_time() const {
    Seen seen;
    return depends(*this, seen);
}

namespace {

bool depends(const Pigment& p, Seen& seen) {
    using Pattern = Pigment::Pattern;
    if (p.pattern == Pattern::Solid) return p.colours.front().depends_on_time();
    if (p.pattern == Pattern::Unsupported) return false;
    if (p.pattern == Pattern::Image)
        return p.patterned->depends_on_time() || p.transform.depends_on_time() ||
               p.image_map->images.size() > 1 || p.image_map->filter_all.depends_on_time() ||
               p.image_map->transmit_all.depends_on_time();
    if (pattern_depends(p.patterned, seen) || p.colour_map.depends_on_time() ||
        p.transform.depends_on_time())
        return true;
    for (const auto& e : p.pigment_map)
        if (e.value.depends_on_time() || entry_depends(*e.pigment, seen)) return true;
    return false;
}

bool depends(const Normal& n, Seen& seen) {
    if (pattern_depends(n.patterned, seen) || n.amount.depends_on_time() ||
        n.accuracy.depends_on_time() || n.transform.depends_on_time() ||
        (n.bump_map && n.bump_map->images.size() > 1))
        return true;
    for (const auto& e : n.normal_map)
        if (e.value.depends_on_time() || entry_depends(*e.normal, seen)) return true;
    for (const auto& e : n.slope_map)
        if (e.value.depends_on_time() || e.height.depends_on_time() || e.slope.depends_on_time())
            return true;
    return false;
}

}  // namespace

void Texture::transform_by(const Transform& step) {
    (uv_mapping == UvMapping::Closed ? uv_outside : transform).append(step);
    for (Texture& layer : below) layer.transform_by(step);
}

void Texture::transform_by(const TransformStep& step) {
    (uv_mapping == UvMapping::Closed ? uv_outside : transform).append(step);
    for (Texture& layer : below) layer.transform_by(step);
}

namespace {

bool depends(const Texture& x, Seen& seen) {
    if (x.transform.depends_on_time() || x.uv_outside.depends_on_time()) return true;
    if (x.is_patterned()) {
        if (pattern_depends(x.patterned, seen)) return true;
        for (const auto& e : x.texture_map)
            if (e.value.depends_on_time() || entry_depends(*e.texture, seen)) return true;
        return false;
    }
    if (depends(x.pigment, seen) || (x.normal && depends(*x.normal, seen))) return true;
    const Finish& f = x.finish;
    for (const Finish::Scalar& scalar : f.scalars())
        if (scalar.value->depends_on_time()) return true;
    if (f.reflection.depends_on_time()) return true;
    if (f.reflection_max && f.reflection_max->depends_on_time()) return true;
    for (const Texture& layer : x.below)
        if (depends(layer, seen)) return true;
    return false;
}

}  // namespace

}  // namespace hexant::runtime
