#include "runtime/texture_evaluator.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <type_traits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "runtime/object_error.hpp"

namespace hexant::runtime {

namespace {

// The transforms after a pattern's last warp, then the texture's.
Transform head_transform(const Transform& last, const Transform& texture) {
    Transform t = last;
    t.append(texture);
    return t;
}

}  // namespace

TextureEvaluator::CompiledColour TextureEvaluator::compile(const ColourFunction& colour) {
    CompiledColour out;
    for (int i = 0; i < 5; ++i) out.c[i] = CompiledScalar(colour.c[i]);
    return out;
}

std::shared_ptr<const TextureEvaluator::CompiledFinish> TextureEvaluator::compile(
    const Finish& f, const std::optional<Interior>& interior) {
    const auto make = [&] {
        return std::make_shared<const CompiledFinish>(CompiledFinish{
            CompiledScalar(f.ambient), CompiledScalar(f.diffuse), CompiledScalar(f.brilliance),
            CompiledScalar(f.phong), CompiledScalar(f.phong_size), CompiledScalar(f.specular),
            CompiledScalar(f.roughness), CompiledScalar(f.emission),
            interior ? CompiledScalar(interior->ior) : CompiledScalar(1.0),
            {CompiledScalar(f.reflection.c[0]), CompiledScalar(f.reflection.c[1]),
             CompiledScalar(f.reflection.c[2])}});
    };
    using Key = std::array<double, 12>;
    Key key{};
    std::size_t n = 0;
    for (const TimeFunction* value :
         {&f.ambient, &f.diffuse, &f.brilliance, &f.phong, &f.phong_size, &f.specular,
          &f.roughness, &f.emission, &f.reflection.c[0], &f.reflection.c[1], &f.reflection.c[2]}) {
        if (!value->is_constant()) return make();
        key[n++] = value->constant();
    }
    if (interior && !interior->ior.is_constant()) return make();
    key[n] = interior ? interior->ior.constant() : 1.0;
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
    return {{CompiledScalar(t.amount.c[0]), CompiledScalar(t.amount.c[1]), CompiledScalar(t.amount.c[2])},
            CompiledScalar(t.octaves),
            CompiledScalar(t.omega),
            CompiledScalar(t.lambda)};
}

pattern::Octaves TextureEvaluator::CompiledTurbulence::at(double t) const {
    return pattern::octaves_of(octaves.at(t), omega.at(t), lambda.at(t));
}

TextureEvaluator::CompiledPattern::CompiledPattern(const pattern::Pattern& source, const Transform& last,
                                                   const Transform& texture)
    : kind(source.kind), head(std::make_shared<const Motion>(head_transform(last, texture))) {
    if (kind == nullptr) throw std::logic_error("TextureEvaluator: a pattern without its kind");
    for (int i = 0; i < 3; ++i) vector[static_cast<std::size_t>(i)] = CompiledScalar(source.vector.c[i]);
    for (std::size_t i = 0; i < 2; ++i) number[i] = CompiledScalar(source.number[i]);
    if (source.turbulence) turbulence = compile(*source.turbulence);
    frequency = CompiledScalar(source.frequency);
    phase = CompiledScalar(source.phase);
    exponent = CompiledScalar(source.exponent);
    wave = source.wave;
    if (source.noise_generator != 0) noise_generator = source.noise_generator;
    for (const pattern::Warp& w : source.warps) {
        CompiledWarp c;
        if (w.transform) c.transform = std::make_shared<const Motion>(*w.transform);
        else c.turbulence = compile(w.turbulence);
        warps.push_back(std::move(c));
    }
    const bool still = !source.vector.depends_on_time() && !source.number[0].depends_on_time() &&
                       !source.number[1].depends_on_time() && !source.frequency.depends_on_time() &&
                       !source.phase.depends_on_time() && !source.exponent.depends_on_time() &&
                       !(source.turbulence && source.turbulence->depends_on_time());
    if (still) {
        fixed = values_at(0.0);
        fixed_exponent = pattern::single(exponent.at(0.0));
    }
}

pattern::Values TextureEvaluator::CompiledPattern::values_at(double t) const {
    // (POV-Ray keeps frequency, phase and the kinds' numbers in single
    // precision: pattern::single.)
    pattern::Values v;
    v.vector = {vector[0].at(t), vector[1].at(t), vector[2].at(t)};
    v.number = {number[0].at(t), number[1].at(t)};
    if (kind->single_numbers) v.number = {pattern::single(v.number[0]), pattern::single(v.number[1])};
    v.frequency = pattern::single(frequency.at(t));
    v.phase = pattern::single(phase.at(t));
    v.noise_generator = noise_generator;
    if (turbulence) {
        v.has_turbulence = true;
        v.turbulence = {turbulence->amount[0].at(t), turbulence->amount[1].at(t), turbulence->amount[2].at(t)};
        v.octaves = turbulence->at(t);
    }
    return v;
}

template <class OnMap>
glm::dvec3 TextureEvaluator::CompiledPattern::walk(const glm::dvec3& world, double t, const pattern::Values& v,
                                                   OnMap on_map) const {
    const auto q = head->to_object<double>({world.x, world.y, world.z}, t);
    glm::dvec3 p(q[0], q[1], q[2]);
    constexpr bool maps = !std::is_same_v<OnMap, NoMaps>;
    if constexpr (maps) on_map(head->jacobian_at(p, t));
    for (auto w = warps.rbegin(); w != warps.rend(); ++w) {
        if (w->transform) {
            const auto r = w->transform->to_object<double>({p.x, p.y, p.z}, t);
            p = {r[0], r[1], r[2]};
            if constexpr (maps) on_map(w->transform->jacobian_at(p, t));
        } else {
            const CompiledTurbulence& turb = w->turbulence;
            p = pattern::apply_turbulence(p, {turb.amount[0].at(t), turb.amount[1].at(t), turb.amount[2].at(t)},
                                          turb.at(t));
        }
    }
    if (v.has_turbulence && !kind->own_turbulence) p = pattern::apply_turbulence(p, v.turbulence, v.octaves);
    return p;
}

bool TextureEvaluator::CompiledPattern::depends_on_time() const { return !head->is_static(); }

TextureEvaluator::TextureEvaluator(const Texture& texture, const std::optional<Interior>& interior)
    : pattern_(texture.pigment.pattern), finish_(compile(texture.finish, interior)) {
    const Pigment& pigment = texture.pigment;
    if (pattern_ == Pigment::Pattern::Unsupported)
        throw ObjectError(pigment.unsupported_place,
                          "pigment pattern '" + pigment.unsupported_name +
                              "' is not supported by hexant's tracer");
    if (pattern_ == Pigment::Pattern::Solid) {
        if (pigment.colours.empty()) throw std::logic_error("TextureEvaluator: a solid pigment without its colour");
        colours_.push_back(compile(pigment.colours.front()));
        depends_on_time_ = pigment.colours.front().depends_on_time();
    } else {
        auto p = std::make_shared<const CompiledPigment>(pigment, texture.transform);
        depends_on_time_ = pigment.depends_on_time() || p->pattern->depends_on_time();
        pigment_ = std::move(p);
    }
    if (texture.normal) {
        const Normal& n = *texture.normal;
        if (!n.unsupported_name.empty())
            throw ObjectError(n.unsupported_place,
                              "normal pattern '" + n.unsupported_name + "' is not supported by hexant's tracer");
        if (n.patterned.kind == nullptr) throw std::logic_error("TextureEvaluator: a normal without its pattern");
        normal_ = std::make_shared<const CompiledNormal>(
            CompiledNormal{CompiledPattern(n.patterned, n.transform, texture.transform), CompiledScalar(n.amount),
                           CompiledScalar(n.accuracy), n.no_bump_scale});
        depends_on_time_ = depends_on_time_ || n.depends_on_time() || normal_->pattern.depends_on_time();
    }
    const Finish& f = texture.finish;
    for (const TimeFunction* value :
         {&f.ambient, &f.diffuse, &f.brilliance, &f.phong, &f.phong_size, &f.specular,
          &f.roughness, &f.emission, &f.reflection.c[0], &f.reflection.c[1], &f.reflection.c[2]})
        depends_on_time_ = depends_on_time_ || value->depends_on_time();
    if (interior) depends_on_time_ = depends_on_time_ || interior->ior.depends_on_time();
}

TextureEvaluator::CompiledPigment::CompiledPigment(const Pigment& pigment, const Transform& texture) {
    if (pigment.pattern == Pigment::Pattern::Unsupported)
        throw ObjectError(pigment.unsupported_place,
                          "pigment pattern '" + pigment.unsupported_name + "' is not supported by hexant's tracer");
    if (pigment.pattern == Pigment::Pattern::Solid) {
        if (pigment.colours.empty()) throw std::logic_error("TextureEvaluator: a solid pigment without its colour");
        solid = compile(pigment.colours.front());
        return;
    }
    pattern.emplace(pigment.patterned, pigment.transform, texture);
    if (!pigment.pigment_map.empty()) {
        // (Each in the space of this pattern: no texture transform of its own.)
        for (const auto& e : pigment.pigment_map)
            pigments.push_back({CompiledScalar(e.value), std::make_shared<const CompiledPigment>(*e.pigment, Transform{})});
        return;
    }
    const ColourMap& map = pigment.colour_map;
    if (map.entries.empty()) {
        fixed_map = pigment.patterned.kind->default_map;
    } else if (!map.depends_on_time()) {
        for (const auto& e : map.entries) {
            pattern::MapEntry entry{pattern::single(e.value.constant()), {}};
            for (std::size_t i = 0; i < 5; ++i) entry.colour[i] = e.colour.c[i].constant();
            fixed_map.push_back(entry);
        }
    } else {
        for (const auto& e : map.entries) this->map.push_back({CompiledScalar(e.value), compile(e.colour)});
    }
}

std::array<double, 5> TextureEvaluator::CompiledPigment::colour(const glm::dvec3& where, double t) const {
    if (solid) return {solid->c[0].at(t), solid->c[1].at(t), solid->c[2].at(t), solid->c[3].at(t), solid->c[4].at(t)};
    const CompiledPattern& p = *pattern;
    const pattern::Values v = p.values(t);
    const glm::dvec3 point = p.point(where, t, v);
    const double value = pattern::evaluate(*p.kind, point, v, p.wave, p.exponent_at(t));
    if (!pigments.empty()) {
        // POV-Ray's Compute_Pigment with a pigment map: the neighbouring
        // entries' pigments at this pattern's point, blended linearly.
        // (Search_Blend_Map over the entries' values, read as it goes.)
        const auto at = [&](std::size_t i) { return pattern::single(pigments[i].first.at(t)); };
        std::size_t cur = 0, prev = 0;
        if (value >= at(pigments.size() - 1)) {
            prev = cur = pigments.size() - 1;
        } else {
            while (value > at(cur)) prev = cur++;
        }
        if (value == at(cur)) prev = cur;
        // (A sub-pigment sees the point warped by this pattern, but not
        // moved by turbulence that marble and wood read themselves.)
        const auto c = pigments[cur].second->colour(point, t);
        if (prev == cur) return c;
        const auto b = pigments[prev].second->colour(point, t);
        const double f = (value - at(prev)) / (at(cur) - at(prev));
        std::array<double, 5> out;
        for (std::size_t i = 0; i < 5; ++i) out[i] = b[i] + f * (c[i] - b[i]);
        return out;
    }
    if (map.empty()) return pattern::map_colour(fixed_map, value);
    std::vector<pattern::MapEntry> entries;
    entries.reserve(map.size());
    for (const auto& [entry_value, colour] : map)
        entries.push_back({pattern::single(entry_value.at(t)), {colour.c[0].at(t), colour.c[1].at(t), colour.c[2].at(t),
                                                                colour.c[3].at(t), colour.c[4].at(t)}});
    return pattern::map_colour(entries, value);
}

glm::dvec3 TextureEvaluator::perturb(const glm::dvec3& normal, const glm::dvec3& world_point, double t) const {
    if (!normal_) return normal;
    const CompiledNormal& n = *normal_;
    const CompiledPattern& p = n.pattern;
    const pattern::Values v = p.values(t);
    // Into pattern space: a normal goes by the transpose of each linear
    // map, world to pattern, in the order the point went (POV-Ray's
    // MInvTransNormal); back by their inverse transposes, in reverse.
    const auto unit = [&](const glm::dvec3& x) {
        const double l = glm::length(x);
        return n.no_bump_scale || !(l > 0.0) || !std::isfinite(l) ? x : x / l;
    };
    // The pattern-to-world linear parts, head first (on the stack for the
    // usual few; a longer warp list in a vector), gathered on the way in.
    constexpr std::size_t kOnStack = 8;
    glm::dmat3 stack[kOnStack];
    std::vector<glm::dmat3> heap;
    std::size_t count = 0;
    const auto map = [&](std::size_t i) -> const glm::dmat3& { return i < kOnStack ? stack[i] : heap[i - kOnStack]; };
    const glm::dvec3 point = p.walk(world_point, t, v, [&](const glm::dmat3& m) {
        if (count < kOnStack) stack[count] = m;
        else heap.push_back(m);
        ++count;
    });
    glm::dvec3 pn = unit(normal);
    for (std::size_t i = 0; i < count; ++i) pn = glm::transpose(map(i)) * pn;
    pn = unit(pn);
    const double amount = pattern::single(n.amount.at(t));
    glm::dvec3 bumped;
    if (p.kind->normal != nullptr) {
        bumped = p.kind->normal(point, v, amount, pn);
    } else {
        const double delta = pattern::single(n.accuracy.at(t));
        bumped = pattern::slope_normal(*p.kind, point, v, p.wave, p.exponent_at(t), amount,
                                       delta, pn);
    }
    glm::dvec3 out = unit(bumped);
    for (std::size_t i = count; i-- > 0;) out = glm::transpose(glm::inverse(map(i))) * out;
    const double l = glm::length(out);
    // (A bump that cancels the normal, or a flat map: the normal unchanged.)
    if (!(l > 0.0) || !std::isfinite(l)) return normal;
    return out / l;
}

MaterialSample TextureEvaluator::at(const glm::dvec3& world_point, double t) const {
    MaterialSample m;
    if (pattern_ == Pigment::Pattern::Patterned) {
        const auto c = pigment_->colour(world_point, t);
        m.colour = {c[0], c[1], c[2]};
        m.filter = c[3];
        m.transmit = c[4];
    } else {
        const CompiledColour& colour = colours_.front();
        m.colour = {colour.c[0].at(t), colour.c[1].at(t), colour.c[2].at(t)};
        m.filter = colour.c[3].at(t);
        m.transmit = colour.c[4].at(t);
    }
    const CompiledFinish& f = *finish_;
    m.ambient = f.ambient.at(t);
    m.diffuse = f.diffuse.at(t);
    m.brilliance = f.brilliance.at(t);
    m.phong = f.phong.at(t);
    m.phong_size = f.phong_size.at(t);
    m.specular = f.specular.at(t);
    m.roughness = f.roughness.at(t);
    m.reflection = {f.reflection[0].at(t), f.reflection[1].at(t), f.reflection[2].at(t)};
    m.emission = f.emission.at(t);
    m.ior = f.ior.at(t);
    return m;
}

}  // namespace hexant::runtime
