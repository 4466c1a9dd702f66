#include "runtime/texture_evaluator.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "runtime/object_error.hpp"

namespace hexant::runtime {

namespace {

Transform pattern_transform(const Texture& texture) {
    Transform t = texture.pigment.transform;
    t.append(texture.transform);
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

TextureEvaluator::TextureEvaluator(const Texture& texture, const std::optional<Interior>& interior)
    : pattern_(texture.pigment.pattern),
      pattern_to_world_(pattern_ == Pigment::Pattern::Patterned
                            ? std::make_shared<const Motion>(pattern_transform(texture))
                            : nullptr),
      finish_(compile(texture.finish, interior)) {
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
        const pattern::Pattern& source = pigment.patterned;
        if (source.kind == nullptr) throw std::logic_error("TextureEvaluator: a pattern without its kind");
        auto p = std::make_unique<CompiledPattern>();
        p->kind = source.kind;
        for (int i = 0; i < 3; ++i) p->vector[static_cast<std::size_t>(i)] = CompiledScalar(source.vector.c[i]);
        for (std::size_t i = 0; i < 2; ++i) p->number[i] = CompiledScalar(source.number[i]);
        if (source.turbulence) p->turbulence = compile(*source.turbulence);
        p->frequency = CompiledScalar(source.frequency);
        p->phase = CompiledScalar(source.phase);
        p->exponent = CompiledScalar(source.exponent);
        p->wave = source.wave;
        if (source.noise_generator != 0) p->noise_generator = source.noise_generator;
        for (const pattern::Warp& w : source.warps) {
            CompiledWarp c;
            if (w.transform) c.transform = std::make_shared<const Motion>(*w.transform);
            else c.turbulence = compile(w.turbulence);
            p->warps.push_back(std::move(c));
        }
        const ColourMap& map = pigment.colour_map;
        if (map.entries.empty()) {
            p->fixed_map = source.kind->default_map;
        } else if (!map.depends_on_time()) {
            for (const auto& e : map.entries) {
                pattern::MapEntry fixed{e.value.constant(), {}};
                for (std::size_t i = 0; i < 5; ++i) fixed.colour[i] = e.colour.c[i].constant();
                p->fixed_map.push_back(fixed);
            }
        } else {
            for (const auto& e : map.entries) p->map.push_back({CompiledScalar(e.value), compile(e.colour)});
        }
        pattern_data_ = std::move(p);
        depends_on_time_ = pigment.depends_on_time() || !pattern_to_world_->is_static();
    }
    const Finish& f = texture.finish;
    for (const TimeFunction* value :
         {&f.ambient, &f.diffuse, &f.brilliance, &f.phong, &f.phong_size, &f.specular,
          &f.roughness, &f.emission, &f.reflection.c[0], &f.reflection.c[1], &f.reflection.c[2]})
        depends_on_time_ = depends_on_time_ || value->depends_on_time();
    if (interior) depends_on_time_ = depends_on_time_ || interior->ior.depends_on_time();
}

std::array<double, 5> TextureEvaluator::pattern_colour(const glm::dvec3& world_point, double t) const {
    const CompiledPattern& p = *pattern_data_;
    // World to pattern space (POV-Ray's Warp_EPoint): the last transforms
    // first, then each earlier step, last written first; classic
    // turbulence last of all, unless the kind reads it itself.
    const auto q = pattern_to_world_->to_object<double>({world_point.x, world_point.y, world_point.z}, t);
    glm::dvec3 point(q[0], q[1], q[2]);
    for (auto w = p.warps.rbegin(); w != p.warps.rend(); ++w) {
        if (w->transform) {
            const auto r = w->transform->to_object<double>({point.x, point.y, point.z}, t);
            point = {r[0], r[1], r[2]};
        } else {
            const CompiledTurbulence& turb = w->turbulence;
            point = pattern::apply_turbulence(
                point, {turb.amount[0].at(t), turb.amount[1].at(t), turb.amount[2].at(t)}, turb.at(t));
        }
    }
    pattern::Values v;
    v.vector = {p.vector[0].at(t), p.vector[1].at(t), p.vector[2].at(t)};
    v.number = {p.number[0].at(t), p.number[1].at(t)};
    v.frequency = p.frequency.at(t);
    v.phase = p.phase.at(t);
    v.noise_generator = p.noise_generator;
    if (p.turbulence) {
        v.has_turbulence = true;
        v.turbulence = {p.turbulence->amount[0].at(t), p.turbulence->amount[1].at(t),
                        p.turbulence->amount[2].at(t)};
        v.octaves = p.turbulence->at(t);
        if (!p.kind->own_turbulence) point = pattern::apply_turbulence(point, v.turbulence, v.octaves);
    }
    const double value = pattern::evaluate(*p.kind, point, v, p.wave, p.exponent.at(t));
    if (p.map.empty()) return pattern::map_colour(p.fixed_map, value);
    std::vector<pattern::MapEntry> map;
    map.reserve(p.map.size());
    for (const auto& [at, colour] : p.map)
        map.push_back({at.at(t), {colour.c[0].at(t), colour.c[1].at(t), colour.c[2].at(t), colour.c[3].at(t),
                                  colour.c[4].at(t)}});
    return pattern::map_colour(map, value);
}

MaterialSample TextureEvaluator::at(const glm::dvec3& world_point, double t) const {
    MaterialSample m;
    if (pattern_ == Pigment::Pattern::Patterned) {
        const auto c = pattern_colour(world_point, t);
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
