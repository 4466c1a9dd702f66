#include "runtime/texture/texture_evaluator.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <type_traits>

#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "runtime/objects/object_error.hpp"
#include "runtime/texture/pattern/kinds/average.hpp"

namespace hexant::runtime {

namespace {

// The transforms after a pattern's last warp, then the texture's.
Transform head_transform(const Transform& last, const Transform& texture) {
    Transform t = last;
    t.append(texture);
    return t;
}

}  // namespace

struct TextureEvaluator::Shared {
    std::map<const Texture*, std::shared_ptr<const CompiledTexture>> textures;
    std::map<const Pigment*, std::shared_ptr<const CompiledPigment>> pigments;
    std::map<const Normal*, std::shared_ptr<const CompiledNormal>> normals;
    // The entry compiled from `record` (in its pattern's space: nothing
    // outside it), once.
    template <class Compiled, class Record, class... Extra>
    std::shared_ptr<const Compiled> entry(
        std::map<const Record*, std::shared_ptr<const Compiled>>& done, const Record& record,
        const Extra&... extra) {
        auto& slot = done[&record];
        if (!slot) slot = std::make_shared<const Compiled>(record, Transform{}, extra..., *this);
        return slot;
    }
};

TextureEvaluator::CompiledColour TextureEvaluator::compile(const ColourFunction& colour) {
    CompiledColour out;
    if (!colour.depends_on_time()) {
        for (std::size_t i = 0; i < 5; ++i) out.constant[i] = colour.c[i].constant();
        return out;
    }
    out.tape = std::make_shared<const TimeTape>(
        TimeTape::compile({colour.c[0], colour.c[1], colour.c[2], colour.c[3], colour.c[4]}));
    return out;
}

std::shared_ptr<const TextureEvaluator::CompiledFinish> TextureEvaluator::compile(
    const Finish& f, const std::optional<Interior>& interior) {
    const ColourFunction most = f.reflection_max ? *f.reflection_max : f.reflection;
    const auto make = [&] {
        return std::make_shared<const CompiledFinish>(CompiledFinish{
            {CompiledScalar(f.ambient[0]), CompiledScalar(f.ambient[1]),
             CompiledScalar(f.ambient[2])},
            CompiledScalar(f.diffuse),
            CompiledScalar(f.diffuse_back),
            CompiledScalar(f.brilliance),
            CompiledScalar(f.phong),
            CompiledScalar(f.phong_size),
            CompiledScalar(f.specular),
            CompiledScalar(f.roughness),
            {CompiledScalar(f.emission[0]), CompiledScalar(f.emission[1]),
             CompiledScalar(f.emission[2])},
            CompiledScalar(f.crand),
            CompiledScalar(f.metallic),
            CompiledScalar(f.reflection_metallic),
            interior ? CompiledScalar(interior->ior) : CompiledScalar(1.0),
            {CompiledScalar(f.reflection.c[0]), CompiledScalar(f.reflection.c[1]),
             CompiledScalar(f.reflection.c[2])},
            {CompiledScalar(most.c[0]), CompiledScalar(most.c[1]), CompiledScalar(most.c[2])},
            CompiledScalar(f.reflection_falloff),
            CompiledScalar(f.reflection_exponent),
            CompiledScalar(f.irid),
            CompiledScalar(f.irid_thickness),
            CompiledScalar(f.irid_turbulence),
            f.reflection_fresnel,
            f.conserve_energy});
    };
    using Key = std::array<double, 30>;
    Key key{};
    std::size_t n = 0;
    const auto keep = [&](const TimeFunction& value) {
        if (!value.is_constant()) return false;
        key[n++] = value.constant();
        return true;
    };
    for (const Finish::Scalar& scalar : f.scalars())
        if (!keep(*scalar.value)) return make();
    for (int c = 0; c < 3; ++c)
        if (!keep(f.reflection.c[c]) || !keep(most.c[c])) return make();
    if (interior && !interior->ior.is_constant()) return make();
    key[n++] = interior ? interior->ior.constant() : 1.0;
    key[n++] = f.reflection_fresnel ? 1.0 : 0.0;
    key[n] = f.conserve_energy ? 1.0 : 0.0;
    // Finishes of constants, shared while some texture holds them. Objects
    // are made on several threads at once in tests, so the table is locked
    // (once per object, while the scene is being set up).
    static std::mutex mutex;
    static std::map<Key, std::weak_ptr<const CompiledFinish>> shared;
    const std::lock_guard lock(mutex);
    auto& slot = shared[key];
    if (auto kept = slot.lock()) return kept;
    static std::size_t prune_at = 64;
    if (shared.size() > prune_at) {  // forget finishes no texture holds any more
        std::erase_if(shared, [](const auto& entry) { return entry.second.expired(); });
        prune_at = std::max<std::size_t>(64, 2 * shared.size());  // amortized: linear in all
    }
    auto made = make();
    shared[key] = made;
    return made;
}

TextureEvaluator::CompiledTurbulence TextureEvaluator::compile(const pattern::Turbulence& t) {
    return {{CompiledScalar(t.amount.c[0]), CompiledScalar(t.amount.c[1]),
             CompiledScalar(t.amount.c[2])},
            CompiledScalar(t.octaves),
            CompiledScalar(t.omega),
            CompiledScalar(t.lambda)};
}

pattern::Octaves TextureEvaluator::CompiledTurbulence::at(double t) const {
    return pattern::octaves_of(octaves.at(t), omega.at(t), lambda.at(t));
}

TextureEvaluator::CompiledPattern::CompiledPattern(const pattern::Pattern& source,
                                                   const Transform& last, const Transform& texture,
                                                   Shared& shared)
    : kind(source.kind), head(std::make_shared<const Motion>(head_transform(last, texture))) {
    for (int i = 0; i < 3; ++i)
        vector[static_cast<std::size_t>(i)] = CompiledScalar(source.vector.c[i]);
    for (std::size_t i = 0; i < 2; ++i) number[i] = CompiledScalar(source.number[i]);
    for (int i = 0; i < 3; ++i)
        vector2[static_cast<std::size_t>(i)] = CompiledScalar(source.vector2.c[i]);
    for (std::size_t i = 0; i < more.size(); ++i) more[i] = CompiledScalar(source.more[i]);
    // (pigment_pattern's pigment lives in this pattern's space.)
    if (source.pigment) pigment = shared.entry(shared.pigments, *source.pigment);
    function = source.function;
    density_file = source.density_file;
    image = source.image;
    if (source.turbulence) turbulence = compile(*source.turbulence);
    frequency = CompiledScalar(source.frequency);
    phase = CompiledScalar(source.phase);
    exponent = CompiledScalar(source.exponent);
    wave = source.wave;
    if (source.noise_generator != 0) noise_generator = source.noise_generator;
    if (source.number_of_waves != 0) number_of_waves = source.number_of_waves;
    for (const pattern::Warp& w : source.warps) {
        CompiledWarp c;
        if (w.transform)
            c.transform = std::make_shared<const Motion>(*w.transform);
        else if (w.point)
            c.point = std::make_shared<const pattern::CompiledPointWarp>(*w.point);
        else
            c.turbulence = compile(w.turbulence);
        warps.push_back(std::move(c));
    }
    const bool still = !source.vector.depends_on_time() && !source.number[0].depends_on_time() &&
                       !source.number[1].depends_on_time() && !source.frequency.depends_on_time() &&
                       !source.phase.depends_on_time() && !source.exponent.depends_on_time() &&
                       !source.vector2.depends_on_time() &&
                       std::none_of(source.more.begin(), source.more.end(),
                                    [](const TimeFunction& n) { return n.depends_on_time(); }) &&
                       !(source.turbulence && source.turbulence->depends_on_time());
    if (still) {
        fixed = values_at(0.0);
        fixed_exponent = pattern::single(exponent.at(0.0));
    }
}

pattern::Values TextureEvaluator::CompiledPattern::values(const pattern::Hit& hit) const {
    pattern::Values v = fixed ? *fixed : values_at(hit.t);
    v.hit = &hit;
    v.pigment = pigment.get();
    v.function = function.get();
    v.density_file = density_file.get();
    v.image = image.get();
    return v;
}

pattern::Values TextureEvaluator::CompiledPattern::values_at(double t) const {
    // (POV-Ray keeps frequency, phase and the kinds' numbers in single
    // precision: pattern::single.)
    pattern::Values v;
    v.vector = {vector[0].at(t), vector[1].at(t), vector[2].at(t)};
    v.number = {number[0].at(t), number[1].at(t)};
    v.vector2 = {vector2[0].at(t), vector2[1].at(t), vector2[2].at(t)};
    for (std::size_t i = 0; i < more.size(); ++i) v.more[i] = more[i].at(t);
    if (kind != nullptr && kind->single_numbers)
        v.number = {pattern::single(v.number[0]), pattern::single(v.number[1])};
    v.frequency = pattern::single(frequency.at(t));
    v.phase = pattern::single(phase.at(t));
    v.noise_generator = noise_generator;
    v.number_of_waves = number_of_waves;
    if (turbulence) {
        v.has_turbulence = true;
        v.turbulence = {turbulence->amount[0].at(t), turbulence->amount[1].at(t),
                        turbulence->amount[2].at(t)};
        v.octaves = turbulence->at(t);
    }
    return v;
}

template <class OnMap>
glm::dvec3 TextureEvaluator::CompiledPattern::walk(const glm::dvec3& world, double t,
                                                   const pattern::Values& v, OnMap on_map) const {
    const auto q = head->to_object<double>({world.x, world.y, world.z}, t);
    glm::dvec3 p(q[0], q[1], q[2]);
    constexpr bool maps = !std::is_same_v<OnMap, NoMaps>;
    if constexpr (maps) on_map(head->jacobian_at(p, t));
    for (auto w = warps.rbegin(); w != warps.rend(); ++w) {
        if (w->transform) {
            const auto r = w->transform->to_object<double>({p.x, p.y, p.z}, t);
            p = {r[0], r[1], r[2]};
            if constexpr (maps) on_map(w->transform->jacobian_at(p, t));
        } else if (w->point) {
            p = w->point->apply(p, t);
        } else {
            const CompiledTurbulence& turb = w->turbulence;
            p = pattern::apply_turbulence(
                p, {turb.amount[0].at(t), turb.amount[1].at(t), turb.amount[2].at(t)}, turb.at(t));
        }
    }
    if (v.has_turbulence && (kind == nullptr || !kind->own_turbulence))
        p = pattern::apply_turbulence(p, v.turbulence, v.octaves);
    return p;
}

bool TextureEvaluator::CompiledPattern::depends_on_time() const {
    return !head->is_static();
}

// The pattern-to-outside linear parts of a walk, outside first: a normal
// goes in by the transpose of each (POV-Ray's MInvTransNormal of the
// inverse), out by their inverse transposes, in reverse.
class TextureEvaluator::NormalMaps {
  public:
    void push(const glm::dmat3& m) {
        if (count_ < kOnStack)
            stack_[count_] = m;
        else
            heap_.push_back(m);
        ++count_;
    }
    bool empty() const { return count_ == 0; }
    glm::dvec3 into(glm::dvec3 n) const {
        for (std::size_t i = 0; i < count_; ++i) n = glm::transpose(at(i)) * n;
        return n;
    }
    glm::dvec3 out_of(glm::dvec3 n) const {
        for (std::size_t i = count_; i-- > 0;) n = glm::transpose(glm::inverse(at(i))) * n;
        return n;
    }

  private:
    static constexpr std::size_t kOnStack = 8;
    const glm::dmat3& at(std::size_t i) const {
        return i < kOnStack ? stack_[i] : heap_[i - kOnStack];
    }
    glm::dmat3 stack_[kOnStack];
    std::vector<glm::dmat3> heap_;
    std::size_t count_ = 0;
};

namespace {

// A normal's length set to one, unless no_bump_scale keeps it (or it has
// none to set).
glm::dvec3 unit_unless(bool keep, const glm::dvec3& x) {
    const double l = glm::length(x);
    return keep || !(l > 0.0) || !std::isfinite(l) ? x : x / l;
}

// The linear part, at `where` (in the space around them) and t, of the
// transforms around a uv-mapped texture: what its normals go through.
glm::dmat3 outer_jacobian(const Motion& outer, const glm::dvec3& where, double t) {
    const auto q = outer.to_object<double>({where.x, where.y, where.z}, t);
    return outer.jacobian_at(glm::dvec3(q[0], q[1], q[2]), t);
}

// A map's entries as POV-Ray's Search_Blend_Map reads them (single
// precision values).
template <class Entries>
pattern::BlendPick pick_entry(const Entries& entries, double value, double t) {
    return pattern::search_blend_map(value, entries.size(), [&](std::size_t i) {
        return pattern::single(entries[i].first.at(t));
    });
}

// A normal's pattern, or the error naming where a pattern hexant lacks was
// written.
const pattern::Pattern& supported(const Normal& n) {
    if (!n.unsupported_name.empty())
        throw ObjectError(n.unsupported_place, "normal pattern '" + n.unsupported_name +
                                                   "' is not supported by hexant's tracer");
    if (n.patterned->kind == nullptr && !n.bump_map)
        throw std::logic_error("TextureEvaluator: a normal without its pattern");
    return n.patterned;
}

}  // namespace

TextureEvaluator::TextureEvaluator(const Texture& texture, const std::optional<Interior>& interior)
    : texture_([&] {
          Shared shared;
          return std::make_shared<const CompiledTexture>(texture, Transform{}, interior, shared);
      }()),
      depends_on_time_(
          texture.depends_on_time() ||
          (interior &&
           (interior->ior.depends_on_time() || interior->fade_distance.depends_on_time() ||
            interior->fade_power.depends_on_time() || interior->fade_colour.depends_on_time() ||
            interior->caustics.depends_on_time() || interior->dispersion.depends_on_time()))),
      opaque_(texture.opaque()) {
    if (interior &&
        !(interior->fade_distance.is_constant() && interior->fade_distance.constant() == 0.0)) {
        const ColourFunction& c = interior->fade_colour;
        parts().fade = std::make_shared<const CompiledFade>(
            CompiledFade{CompiledScalar(interior->fade_distance),
                         CompiledScalar(interior->fade_power),
                         {CompiledScalar(c.c[0]), CompiledScalar(c.c[1]), CompiledScalar(c.c[2])}});
    }
    if (interior && !(interior->ior.is_constant() && interior->ior.constant() == 1.0))
        parts().ior = std::make_shared<const CompiledScalar>(interior->ior);
    if (interior && interior->ior_written &&
        !(interior->dispersion.is_constant() && interior->dispersion.constant() == 1.0))
        parts().dispersion = std::make_shared<const CompiledDispersion>(
            CompiledDispersion{CompiledScalar(interior->dispersion), interior->dispersion_samples});
    if (interior && !(interior->caustics.is_constant() && interior->caustics.constant() == 0.0))
        parts().caustics = std::make_shared<const CompiledScalar>(interior->caustics * 45.0);
}

void TextureEvaluator::set_interior_texture(const Texture& texture,
                                            const std::optional<Interior>& interior) {
    auto made = std::make_shared<TextureEvaluator>(texture, interior);
    // (The same interior: its media and key, as the outside's.)
    if (interior_) {
        made->set_media(interior_->media);
        made->set_interior_key(interior_->key);
    }
    std::shared_ptr<const TextureEvaluator> inside = std::move(made);
    depends_on_time_ = depends_on_time_ || inside->depends_on_time();
    opaque_ = opaque_ && inside->opaque();
    parts().interior_texture = std::move(inside);
}

std::optional<TextureEvaluator::Fade> TextureEvaluator::fade_at(double t) const {
    if (!interior_ || !interior_->fade) return std::nullopt;
    const CompiledFade& fade = *interior_->fade;
    Fade f;
    f.distance = fade.distance.at(t);
    f.power = fade.power.at(t);
    f.colour = {fade.colour[0].at(t), fade.colour[1].at(t), fade.colour[2].at(t)};
    // (POV-Ray's test: a distance within its EPSILON of 0 fades nothing.)
    if (!(std::fabs(f.distance) > 1e-10)) return std::nullopt;
    return f;
}

glm::dvec3 TextureEvaluator::Fade::through(double depth) const {
    const glm::dvec3 one(1.0);
    glm::dvec3 passed;
    if (power >= 1000.0) {
        passed = glm::exp(-(one - colour) * (depth / distance));
    } else {
        const double k = 1.0 + std::pow(depth / distance, power);
        passed = colour + (one - colour) / k;
    }
    // (No NaN leaves: a negative distance to a fractional power, say.)
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(passed[i])) passed[i] = 1.0;
    return passed;
}

TextureEvaluator::CompiledTexture::CompiledTexture(const Texture& texture, const Transform& outside,
                                                   const std::optional<Interior>& interior,
                                                   Shared& shared) {
    if (texture.is_patterned()) {
        if (texture.patterned->kind == nullptr)
            throw std::logic_error("TextureEvaluator: a texture_map without its pattern");
        // (A uv-mapped one: in uv space, through its own transforms alone.)
        uv = texture.uv_mapping != UvMapping::Off;
        pattern.emplace(texture.patterned, texture.transform, uv ? Transform{} : outside, shared);
        if (uv && !texture.uv_outside.empty())
            outer = std::make_shared<const Motion>(texture.uv_outside);
        // (The entries live in this pattern's space: nothing outside it.)
        for (const auto& e : texture.texture_map) {
            auto entry = shared.entry(shared.textures, *e.texture, interior);
            has_normal = has_normal || entry->has_normal;
            entries.push_back({CompiledScalar(e.value), std::move(entry)});
        }
        return;
    }
    // (A uv-mapped layer: in uv space, through its own transforms alone.)
    const auto placed = [&](const Texture& layer) {
        Transform to_world = layer.transform;
        if (layer.uv_mapping == UvMapping::Off) to_world.append(outside);
        return to_world;
    };
    const auto add = [&](const Texture& layer, const Transform& to_world) {
        CompiledLayer c;
        c.uv = layer.uv_mapping != UvMapping::Off;
        if (c.uv && layer.normal && !layer.uv_outside.empty())
            c.outer = std::make_shared<const Motion>(layer.uv_outside);
        c.pigment = std::make_shared<const CompiledPigment>(layer.pigment, to_world, shared);
        if (layer.normal) {
            c.normal = std::make_shared<const CompiledNormal>(*layer.normal, to_world, shared);
            has_normal = true;
        }
        c.finish = compile(layer.finish, interior);
        layers.push_back(std::move(c));
    };
    add(texture, placed(texture));
    // Top first (Texture::below is bottom first).
    for (auto it = texture.below.rbegin(); it != texture.below.rend(); ++it) {
        if (it->is_patterned() || !it->below.empty())
            throw std::logic_error(
                "TextureEvaluator: a layer under a texture is one plain texture");
        add(*it, placed(*it));
    }
}

TextureEvaluator::CompiledNormal::CompiledNormal(const Normal& n, const Transform& texture,
                                                 Shared& shared)
    : pattern(supported(n), n.transform, n.uv_mapping != UvMapping::Off ? Transform{} : texture,
              shared),
      amount(n.amount),
      accuracy(n.accuracy),
      no_bump_scale(n.no_bump_scale),
      uv(n.uv_mapping != UvMapping::Off),
      bump_map(n.bump_map) {
    // (Each entry of a normal map in the space of this pattern.)
    for (const auto& e : n.normal_map)
        normals.push_back({CompiledScalar(e.value), shared.entry(shared.normals, *e.normal)});
    const bool still =
        std::all_of(n.slope_map.begin(), n.slope_map.end(), [](const SlopeMapEntry& e) {
            return e.value.is_constant() && e.height.is_constant() && e.slope.is_constant();
        });
    for (const auto& e : n.slope_map) {
        if (still)
            fixed_slopes.push_back(
                {pattern::single(e.value.constant()), e.height.constant(), e.slope.constant()});
        else
            slopes.push_back(
                {CompiledScalar(e.value), CompiledScalar(e.height), CompiledScalar(e.slope)});
    }
}

TextureEvaluator::CompiledPigment::CompiledPigment(const Pigment& pigment, const Transform& texture,
                                                   Shared& shared) {
    if (pigment.pattern == Pigment::Pattern::Unsupported)
        throw ObjectError(pigment.unsupported_place, "pigment pattern '" +
                                                         pigment.unsupported_name +
                                                         "' is not supported by hexant's tracer");
    if (pigment.pattern == Pigment::Pattern::Solid) {
        if (pigment.colours.empty())
            throw std::logic_error("TextureEvaluator: a solid pigment without its colour");
        solid = compile(pigment.colours.front());
        return;
    }
    // (A uv-mapped one: in uv space, through its own transforms alone.)
    uv = pigment.uv_mapping != UvMapping::Off;
    Patterned& p =
        patterned.emplace(pigment.patterned, pigment.transform, uv ? Transform{} : texture, shared);
    if (pigment.pattern == Pigment::Pattern::Image) {
        p.image = pigment.image_map;
        p.filter_all = CompiledScalar(p.image->filter_all);
        p.transmit_all = CompiledScalar(p.image->transmit_all);
        return;
    }
    if (p.pattern.kind == nullptr)
        throw std::logic_error("TextureEvaluator: a pattern without its kind");
    if (!pigment.pigment_map.empty()) {
        // (Each in the space of this pattern: no texture transform of its own.)
        for (const auto& e : pigment.pigment_map)
            p.pigments.push_back(
                {CompiledScalar(e.value), shared.entry(shared.pigments, *e.pigment)});
        return;
    }
    const ColourMap& written = pigment.colour_map;
    if (written.entries.empty()) {
        p.fixed_map = pattern::default_map(pigment.patterned);
    } else if (!written.depends_on_time()) {
        for (const auto& e : written.entries) {
            pattern::MapEntry entry{pattern::single(e.value.constant()), {}};
            for (std::size_t i = 0; i < 5; ++i) entry.colour[i] = e.colour.c[i].constant();
            p.fixed_map.push_back(entry);
        }
    } else {
        for (const auto& e : written.entries)
            p.map.push_back({CompiledScalar(e.value), compile(e.colour)});
    }
}

std::array<double, 5> TextureEvaluator::CompiledPigment::colour(const glm::dvec3& where,
                                                                const pattern::Hit& hit) const {
    const double t = hit.t;
    if (solid) return solid->at(t);
    // (Named, not unpacked: a lambda below reads pigments, which clang
    // before 16 cannot capture from a structured binding.)
    const Patterned& parts = *patterned;
    const CompiledPattern& p = parts.pattern;
    const auto& pigments = parts.pigments;
    const auto& image = parts.image;
    const pattern::Values v = p.values(hit);
    const glm::dvec3 point = p.point(uv ? glm::dvec3(hit.uv, 0.0) : where, t, v);
    if (image)
        return pattern::image_colour(*image, point, t, parts.filter_all.at(t),
                                     parts.transmit_all.at(t));
    if (p.kind->average) {
        // POV-Ray's Do_Average_Pigments: every entry at this pattern's
        // point, weighted by its value.
        std::array<double, 5> out{};
        pattern::kinds::average_entries(
            pigments.size(),
            [&](std::size_t i) { return pattern::single(pigments[i].first.at(t)); },
            [&](std::size_t i, double share) {
                const auto c = pigments[i].second->colour(point, hit);
                for (std::size_t k = 0; k < 5; ++k) out[k] += c[k] * share;
            });
        return out;
    }
    const double value = p.value(point, t, v);
    if (!pigments.empty()) {
        // POV-Ray's Compute_Pigment with a pigment map: the neighbouring
        // entries' pigments at this pattern's point, blended linearly.
        // (A sub-pigment sees the point warped by this pattern, but not
        // moved by turbulence that marble and wood read themselves.)
        const pattern::BlendPick pick = pick_entry(pigments, value, t);
        const auto c = pigments[pick.cur].second->colour(point, hit);
        if (pick.prev == pick.cur) return c;
        const auto b = pigments[pick.prev].second->colour(point, hit);
        std::array<double, 5> out;
        for (std::size_t i = 0; i < 5; ++i) out[i] = b[i] + pick.f * (c[i] - b[i]);
        return out;
    }
    if (parts.map.empty()) return pattern::map_colour(parts.fixed_map, value);
    std::vector<pattern::MapEntry> entries;
    entries.reserve(parts.map.size());
    for (const auto& [entry_value, colour] : parts.map)
        entries.push_back({pattern::single(entry_value.at(t)), colour.at(t)});
    return pattern::map_colour(entries, value);
}

glm::dvec3 TextureEvaluator::CompiledNormal::perturb(const glm::dvec3& normal,
                                                     const glm::dvec3& where,
                                                     const pattern::Hit& hit) const {
    const std::optional<glm::dvec3> out = perturb_scaled(normal, where, hit);
    // (A bump that cancels the normal, or a flat map: the normal unchanged.)
    if (!out) return normal;
    return *out / glm::length(*out);
}

std::optional<glm::dvec3> TextureEvaluator::CompiledNormal::perturb_scaled(
    const glm::dvec3& normal, const glm::dvec3& where, const pattern::Hit& hit) const {
    const double t = hit.t;
    const CompiledPattern& p = pattern;
    const pattern::Values v = p.values(hit);
    NormalMaps maps;
    // (uv-mapped: POV-Ray perturbs the normal as it is at (u, v, 0): no
    // map between uv space and the surface's tangents.)
    const glm::dvec3 start = uv ? glm::dvec3(hit.uv, 0.0) : where;
    const glm::dvec3 point = p.walk(start, t, v, [&](const glm::dmat3& m) { maps.push(m); });
    const glm::dvec3 pn = unit_unless(no_bump_scale, maps.into(unit_unless(no_bump_scale, normal)));
    glm::dvec3 bumped;
    if (bump_map) {
        bumped = pattern::bump_map_normal(*bump_map, point, t, pattern::single(amount.at(t)), pn);
    } else if (p.kind->average) {
        // POV-Ray's Do_Average_Normals: every entry's normal (as its own
        // Perturb_Normal leaves it) at this pattern's point, weighted by
        // its value.
        bumped = glm::dvec3(0.0);
        pattern::kinds::average_entries(
            normals.size(), [&](std::size_t i) { return pattern::single(normals[i].first.at(t)); },
            [&](std::size_t i, double share) {
                bumped += share * normals[i].second->perturb_scaled(pn, point, hit).value_or(pn);
            });
    } else if (!normals.empty()) {
        // POV-Ray's normal_map: the neighbouring entries' normals, each
        // perturbing this one in this pattern's space, blended linearly.
        const pattern::BlendPick pick = pick_entry(normals, p.value(point, t, v), t);
        bumped = normals[pick.cur].second->perturb(pn, point, hit);
        if (pick.prev != pick.cur) {
            const glm::dvec3 other = normals[pick.prev].second->perturb(pn, point, hit);
            bumped = (1.0 - pick.f) * other + pick.f * bumped;
        }
    } else if (p.kind->normal != nullptr) {
        bumped = p.kind->normal(point, v, pattern::single(amount.at(t)), pn);
    } else {
        std::vector<pattern::SlopeEntry> moving;
        for (const auto& [value, height, slope] : slopes)
            moving.push_back({pattern::single(value.at(t)), height.at(t), slope.at(t)});
        const auto* slope_map = !fixed_slopes.empty() ? &fixed_slopes
                                : !moving.empty()     ? &moving
                                                      : nullptr;
        bumped = pattern::slope_normal(*p.kind, point, v, p.wave, p.exponent_at(t),
                                       pattern::single(amount.at(t)),
                                       pattern::single(accuracy.at(t)), pn, slope_map);
    }
    const glm::dvec3 out = maps.out_of(unit_unless(no_bump_scale, bumped));
    const double l = glm::length(out);
    if (!(l > 0.0) || !std::isfinite(l)) return std::nullopt;
    return no_bump_scale ? out : out / l;
}

MaterialSample TextureEvaluator::CompiledLayer::material(const glm::dvec3& point,
                                                         const pattern::Hit& hit) const {
    MaterialSample m;
    fill(m, point, hit);
    return m;
}

void TextureEvaluator::CompiledLayer::fill(MaterialSample& m, const glm::dvec3& point,
                                           const pattern::Hit& hit) const {
    const double t = hit.t;
    const auto c = pigment->colour(at(point, hit.uv), hit);
    m.colour = {c[0], c[1], c[2]};
    m.filter = c[3];
    m.transmit = c[4];
    const CompiledFinish& f = *finish;
    m.ambient = {f.ambient[0].at(t), f.ambient[1].at(t), f.ambient[2].at(t)};
    m.diffuse = f.diffuse.at(t);
    m.diffuse_back = f.diffuse_back.at(t);
    m.brilliance = f.brilliance.at(t);
    m.phong = f.phong.at(t);
    m.phong_size = f.phong_size.at(t);
    m.specular = f.specular.at(t);
    m.roughness = f.roughness.at(t);
    m.reflection = {f.reflection[0].at(t), f.reflection[1].at(t), f.reflection[2].at(t)};
    m.emission = {f.emission[0].at(t), f.emission[1].at(t), f.emission[2].at(t)};
    m.crand = f.crand.at(t);
    m.metallic = f.metallic.at(t);
    m.reflection_metallic = f.reflection_metallic.at(t);
    m.reflection_max = {f.reflection_max[0].at(t), f.reflection_max[1].at(t),
                        f.reflection_max[2].at(t)};
    m.reflection_falloff = f.reflection_falloff.at(t);
    m.reflection_power = 1.0 / f.reflection_exponent.at(t);
    m.reflection_fresnel = f.reflection_fresnel;
    m.conserve_energy = f.conserve_energy;
    m.irid = f.irid.at(t);
    m.irid_thickness = f.irid_thickness.at(t);
    m.irid_turbulence = f.irid_turbulence.at(t);
    m.ior = f.ior.at(t);
}

glm::dvec3 TextureEvaluator::CompiledLayer::perturbed(const glm::dvec3& n, const glm::dvec3& point,
                                                      const pattern::Hit& hit) const {
    if (!normal) return n;
    if (!outer) return normal->perturb(n, at(point, hit.uv), hit);
    NormalMaps maps;
    maps.push(outer_jacobian(*outer, point, hit.t));
    const glm::dvec3 back =
        maps.out_of(normal->perturb(unit_unless(false, maps.into(n)), at(point, hit.uv), hit));
    const double l = glm::length(back);
    return l > 0.0 && std::isfinite(l) ? back / l : n;
}

void TextureEvaluator::CompiledLayer::sample(TextureSample::Layer& out, const glm::dvec3& point,
                                             const glm::dvec3& shading, pattern::Hit& hit) const {
    out.normal = perturbed(shading, point, hit);
    if (normal) hit.normal = out.normal;
    fill(out.material, point, hit);
}

void TextureEvaluator::CompiledTexture::sample(const glm::dvec3& where, pattern::Hit& hit,
                                               const glm::dvec3& normal, double weight,
                                               TextureSample& out) const {
    if (!pattern) {
        out.plains.push_back({weight, out.layers.size(), layers.size()});
        for (const CompiledLayer& layer : layers)
            layer.sample(out.layers.emplace_back(), where, normal, hit);
        return;
    }
    // POV-Ray's ComputeOneTextureColour for a patterned texture: the
    // neighbouring entries at the pattern's value, each in the pattern's
    // space, their colours blended; a normal below goes through this
    // pattern's transforms too (its Warp_Normal, UnWarp_Normal).
    const double t = hit.t;
    const CompiledPattern& p = *pattern;
    const pattern::Values v = p.values(hit);
    NormalMaps maps;
    const glm::dvec3 start = uv ? glm::dvec3(hit.uv, 0.0) : where;
    if (outer && has_normal) maps.push(outer_jacobian(*outer, where, t));
    const glm::dvec3 point = has_normal
                                 ? p.walk(start, t, v, [&](const glm::dmat3& m) { maps.push(m); })
                                 : p.point(start, t, v);
    const bool turn = has_normal && !maps.empty();
    const glm::dvec3 inside = turn ? unit_unless(false, maps.into(normal)) : normal;
    const std::size_t first = out.layers.size();
    if (p.kind->average) {
        // POV-Ray's ComputeAverageTextureColours: every entry lit on its
        // own at this pattern's point, the colours weighted by the values.
        pattern::kinds::average_entries(
            entries.size(), [&](std::size_t i) { return pattern::single(entries[i].first.at(t)); },
            [&](std::size_t i, double share) {
                entries[i].second->sample(point, hit, inside, weight * share, out);
            });
    } else {
        const pattern::BlendPick pick = pick_entry(entries, p.value(point, t, v), t);
        const double share = pick.prev == pick.cur ? 1.0 : pick.f;
        entries[pick.cur].second->sample(point, hit, inside, weight * share, out);
        if (pick.prev != pick.cur)
            entries[pick.prev].second->sample(point, hit, inside, weight * (1.0 - share), out);
    }
    if (!turn) return;
    for (std::size_t i = first; i < out.layers.size(); ++i) {
        const glm::dvec3 back = maps.out_of(out.layers[i].normal);
        const double l = glm::length(back);
        out.layers[i].normal = l > 0.0 && std::isfinite(l) ? back / l : normal;
    }
}

const TextureEvaluator::CompiledLayer& TextureEvaluator::CompiledTexture::picked_top(
    const glm::dvec3& where, const pattern::Hit& hit, glm::dvec3& at) const {
    at = where;
    if (!pattern) return layers.front();
    const pattern::Values v = pattern->values(hit);
    const glm::dvec3 point = pattern->point(uv ? glm::dvec3(hit.uv, 0.0) : where, hit.t, v);
    // (An average's first entry: no one entry is its material.)
    if (pattern->kind->average) return entries.front().second->picked_top(point, hit, at);
    const pattern::BlendPick pick = pick_entry(entries, pattern->value(point, hit.t, v), hit.t);
    return entries[pick.cur].second->picked_top(point, hit, at);
}

namespace {

// The surface event a texture is evaluated at (POV-Ray's Intersection,
// PNormal starting as the viewer-facing normal).
pattern::Hit surface_hit(const glm::dvec3& world_point, const glm::dvec3& normal,
                         const glm::dvec2& uv, double t) {
    return {world_point, normal, uv, t, true};
}

}  // namespace

void TextureEvaluator::sample(const glm::dvec3& world_point, const glm::dvec2& uv, double t,
                              const glm::dvec3& normal, TextureSample& out, double weight) const {
    pattern::Hit hit = surface_hit(world_point, normal, uv, t);
    texture_->sample(world_point, hit, normal, weight, out);
}

void TextureEvaluator::sample_layer(const glm::dvec3& world_point, const glm::dvec2& uv, double t,
                                    const glm::dvec3& normal, TextureSample::Layer& out) const {
    pattern::Hit hit = surface_hit(world_point, normal, uv, t);
    texture_->layers.front().sample(out, world_point, normal, hit);
}

MaterialSample TextureEvaluator::at(const glm::dvec3& world_point, const glm::dvec2& uv,
                                    double t) const {
    // (No surface normal: a slope reads none, as POV-Ray's without an
    // Intersection.)
    const pattern::Hit hit{world_point, glm::dvec3(0.0), uv, t, false};
    glm::dvec3 point;
    const CompiledLayer& layer = texture_->picked_top(world_point, hit, point);
    return layer.material(point, hit);
}

bool TextureEvaluator::has_normal() const {
    return !texture_->pattern && texture_->layers.front().normal != nullptr;
}

glm::dvec3 TextureEvaluator::perturb(const glm::dvec3& normal, const glm::dvec3& world_point,
                                     double t) const {
    if (!has_normal()) return normal;
    // (The camera's: no surface, as POV-Ray's without an Intersection.)
    const pattern::Hit hit{world_point, normal, glm::dvec2(0.0), t, false};
    return texture_->layers.front().normal->perturb(normal, world_point, hit);
}

}  // namespace hexant::runtime
