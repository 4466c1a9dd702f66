// A texture compiled for the tracer: its patterns, layers, maps, finishes
// and the interior, evaluated at a world point and time into plain numbers.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "runtime/motion/motion.hpp"
#include "runtime/texture/material.hpp"
#include "runtime/texture/material_sample.hpp"
#include "runtime/time/compiled_function.hpp"

namespace hexant::runtime {

class MediaVolume;  // runtime/scene/media_volume.hpp

// What a texture shows at one surface event: the plain textures its
// patterns pick there (texture_map), each with its weight in the blend, and
// each plain texture's layers, top first, with the material and the
// shading normal (perturbed by the layer's normal { }) of each. The shader
// lights every plain texture on its own and blends the colours by weight
// (POV-Ray's ComputeOneTextureColour, ComputeLightedTexture). Reused from
// hit to hit: clear() keeps the storage.
struct TextureSample {
    struct Layer {
        MaterialSample material;
        glm::dvec3 normal{0.0};  // unit, world
    };
    struct Plain {
        double weight = 1.0;
        std::size_t first = 0, count = 0;  // layers[first, first + count)
    };
    std::vector<Layer> layers;
    std::vector<Plain> plains;
    void clear() {
        layers.clear();
        plains.clear();
    }
};

class TextureEvaluator {
  public:
    // `texture.transform` maps texture space to the world (the object's
    // transforms written after the texture are already appended, so the
    // texture moves with the object). Throws ObjectError, naming the place,
    // for a pattern hexant does not have.
    TextureEvaluator(const Texture& texture, const std::optional<Interior>& interior);

    // The texture at `world_point` and time t, seen with the shading
    // normal `normal` (unit, world, already turned to face the viewer, as
    // POV-Ray perturbs it): appends each plain texture picked there, its
    // layers and their perturbed normals, to `out`. The weights sum to
    // `weight` (a blob's blend gives each texture its share).
    // `uv`: the surface's (u, v) there (SurfacePoint::uv), which a
    // uv-mapped pigment, normal or texture reads as the point (u, v, 0).
    void sample(const glm::dvec3& world_point, const glm::dvec2& uv, double t,
                const glm::dvec3& normal, TextureSample& out, double weight = 1.0) const;

    // Whether the texture is one plain layer (no texture_map, no layers
    // under it): then sample_layer gives its one layer, as sample would.
    bool single_layer() const { return !texture_->pattern && texture_->layers.size() == 1; }
    void sample_layer(const glm::dvec3& world_point, const glm::dvec2& uv, double t,
                      const glm::dvec3& normal, TextureSample::Layer& out) const;

    // The top layer's material of the plain texture picked at the point
    // (for a texture_map the entry at or above the pattern's value, without
    // blending): for tests and peers that read one colour.
    MaterialSample at(const glm::dvec3& world_point, const glm::dvec2& uv, double t) const;
    bool depends_on_time() const { return depends_on_time_; }
    // The interior's fading at time t (Interior::fade_distance): none
    // without an interior or with a fade_distance of 0.
    struct Fade {
        double distance = 0.0, power = 0.0;
        glm::dvec3 colour{0.0};
        // What passes `depth` (scene units) inside.
        glm::dvec3 through(double depth) const;
    };
    std::optional<Fade> fade_at(double t) const;
    // The interior's faked caustics' power at time t (Interior::caustics,
    // times 45 as POV-Ray keeps it); 0 without.
    double caustics_at(double t) const {
        return interior_ && interior_->caustics ? interior_->caustics->at(t) : 0.0;
    }
    // The interior's ior at time t (Interior::ior; 1 without).
    double ior_at(double t) const {
        return interior_ && interior_->ior ? interior_->ior->at(t) : 1.0;
    }
    // The interior's dispersion at time t and its number of bands
    // (Interior::dispersion, dispersion_samples): 1 without, or without a
    // written ior (POV-Ray's Post_Process), or where a clock-driven value
    // is not above 0.
    struct Dispersion {
        double value = 1.0;
        int samples = 7;
    };
    Dispersion dispersion_at(double t) const {
        if (!interior_ || !interior_->dispersion) return {};
        const double d = interior_->dispersion->value.at(t);
        return {d > 0.0 ? d : 1.0, interior_->dispersion->samples};
    }
    // Whether no light passes it (Texture::opaque), nor its interior
    // texture (POV-Ray's OPAQUE_FLAG wants both).
    bool opaque() const { return opaque_; }
    // The interior's media (null without): one volume shared by every
    // primitive of the object that wrote it, so that a ray knows it is
    // still inside (runtime/objects/object_factory.cpp).
    const MediaVolume* media() const { return interior_ ? interior_->media.get() : nullptr; }
    void set_media(std::shared_ptr<const MediaVolume> media) {
        if (media || interior_) parts().media = std::move(media);
    }
    // The interior's identity as refraction knows it (POV-Ray's Interior:
    // one per object, shared by the members of a CSG and the parts of a
    // mesh that have no interior { } of their own, Parser::Post_Process).
    // Null: the primitive's own, which the primitive stands for.
    const void* interior_key() const { return interior_ ? interior_->key.get() : nullptr; }
    void set_interior_key(std::shared_ptr<const void> key) {
        if (key || interior_) parts().key = std::move(key);
    }

    // interior_texture { }: the texture a ray meeting the surface from
    // inside sees (POV-Ray's Interior_Texture), compiled with the same
    // interior (and media and key: set both first). Null: none, this one is seen
    // from both sides.
    void set_interior_texture(const Texture& texture, const std::optional<Interior>& interior);
    const TextureEvaluator* interior_texture() const {
        return interior_ ? interior_->interior_texture.get() : nullptr;
    }

    // Whether the top layer perturbs the shading normal (normal { }).
    bool has_normal() const;
    // The unit shading normal `normal` (unit, world, facing the viewer)
    // perturbed at `world_point` and time t by the top layer's normal { }
    // (the camera's normal: a texture of one layer, never uv-mapped: the
    // language refuses it). POV-Ray's Warp_Normal, Perturb_Normal,
    // UnWarp_Normal. A bump that cancels the normal leaves it as it was.
    glm::dvec3 perturb(const glm::dvec3& normal, const glm::dvec3& world_point, double t) const;

  private:
    // A colour's five channels (rgb, filter, transmit): their values when
    // none moves, else one tape for the five (56 bytes, not five compiled
    // scalars' 120: a colour per object is the usual case).
    struct CompiledColour {
        std::array<double, 5> constant{};
        std::shared_ptr<const TimeTape> tape;  // null when none moves
        std::array<double, 5> at(double t) const {
            if (!tape) return constant;
            std::array<double, 5> out;
            tape->evaluate(t, out.data());
            return out;
        }
    };
    static CompiledColour compile(const ColourFunction& colour);

    // The finish and the interior's ior. A finish of constants is shared by
    // every texture that has the same numbers (a scene of 10^5 spheres
    // that differ in colour keeps one), so an object pays a pointer for it.
    struct CompiledFinish {
        std::array<CompiledScalar, 3> ambient;
        CompiledScalar diffuse, diffuse_back, brilliance, phong, phong_size, specular, roughness;
        std::array<CompiledScalar, 3> emission;
        CompiledScalar crand, metallic, reflection_metallic, ior;
        std::array<CompiledScalar, 3> reflection;
        std::array<CompiledScalar, 3> reflection_max;
        CompiledScalar reflection_falloff, reflection_exponent;
        CompiledScalar irid, irid_thickness, irid_turbulence;
        bool reflection_fresnel = false, conserve_energy = false;
    };
    static std::shared_ptr<const CompiledFinish> compile(const Finish& finish,
                                                         const std::optional<Interior>& interior);

    // A pattern's parameters, compiled (runtime/texture/pattern/pattern.hpp).
    struct CompiledTurbulence {
        std::array<CompiledScalar, 3> amount;
        CompiledScalar octaves, omega, lambda;
        pattern::Octaves at(double t) const;
    };
    struct CompiledWarp {
        std::shared_ptr<const Motion> transform;  // else turbulence, or `point`
        CompiledTurbulence turbulence;
        // repeat, black_hole, a mapping warp (which turn no normal).
        std::shared_ptr<const pattern::CompiledPointWarp> point;
    };
    struct CompiledPigment;
    struct Shared;
    struct CompiledPattern {
        const pattern::Kind* kind = nullptr;  // null: an image's placement, no value of its own
        // Its last transforms, then the texture's: pattern space to the
        // space around it.
        std::shared_ptr<const Motion> head;
        std::array<CompiledScalar, 3> vector;
        std::array<CompiledScalar, 2> number;
        std::array<CompiledScalar, 3> vector2;
        std::array<CompiledScalar, 4> more;
        std::optional<CompiledTurbulence> turbulence;
        CompiledScalar frequency, phase, exponent;
        pattern::Wave wave = pattern::Wave::Ramp;
        int noise_generator = pattern::kDefaultNoiseGenerator;
        int number_of_waves = pattern::kDefaultNumberOfWaves;
        std::vector<CompiledWarp> warps;  // in the order written
        // The parameters, when none moves: a still pattern pays nothing per
        // hit for time.
        std::optional<pattern::Values> fixed;
        double fixed_exponent = 1.0;
        // pigment_pattern's pigment, in this pattern's space.
        std::shared_ptr<const CompiledPigment> pigment;
        // The function pattern's function.
        std::shared_ptr<const SpaceFunction> function;
        std::shared_ptr<const pattern::DensityFile> density_file;
        std::shared_ptr<const pattern::ImageMap> image;

        CompiledPattern(const pattern::Pattern& source, const Transform& last,
                        const Transform& texture, Shared& shared);
        bool depends_on_time() const;
        // The parameters at the hit's time, reading that hit (and the
        // pigment of a pigment_pattern).
        pattern::Values values(const pattern::Hit& hit) const;
        pattern::Values values_at(double t) const;
        double exponent_at(double t) const {
            return fixed ? fixed_exponent : pattern::single(exponent.at(t));
        }
        // The pattern's value at a point in pattern space.
        double value(const glm::dvec3& point, double t, const pattern::Values& v) const {
            return pattern::evaluate(*kind, point, v, wave, exponent_at(t));
        }
        // The point (in the space around the pattern) in pattern space
        // (POV-Ray's Warp_EPoint): the last transforms first, then each
        // earlier step, last written first; classic turbulence last of all,
        // unless the kind reads it itself.
        glm::dvec3 point(const glm::dvec3& outside, double t, const pattern::Values& v) const {
            return walk(outside, t, v, NoMaps{});
        }
        struct NoMaps {};  // (a pigment's point: no Jacobians computed)
        // The same, handing each transform's pattern-to-outside linear part
        // (head first) to on_map: what a normal goes through.
        template <class OnMap>
        glm::dvec3 walk(const glm::dvec3& outside, double t, const pattern::Values& v,
                        OnMap on_map) const;
    };
    // The linear maps a normal goes through into a pattern's space, outside
    // first (on the stack for the usual few).
    class NormalMaps;

    // (Shared: map entries compiled once each while one texture is
    // compiled: a scene may declare textures whose maps share entries (T1 a
    // checker of T0 and T0 scaled, T2 of T1 ...), a graph that is
    // exponential as a tree.)

    // A pigment: a colour, or a pattern through a colour map or a
    // pigment map of pigments (each evaluated in this pattern's space).
    struct CompiledPigment final : pattern::PigmentSource {
        std::optional<CompiledColour> solid;
        // A pattern's pigment: the pattern and its maps.
        struct Patterned {
            CompiledPattern pattern;
            // The colour map: fixed when nothing in it moves, else compiled.
            std::vector<pattern::MapEntry> fixed_map;
            std::vector<std::pair<CompiledScalar, CompiledColour>> map;
            std::vector<std::pair<CompiledScalar, std::shared_ptr<const CompiledPigment>>> pigments;
            std::shared_ptr<const pattern::ImageMap> image;  // image_map (the pattern places it)
            CompiledScalar filter_all, transmit_all;

            Patterned(const pattern::Pattern& source, const Transform& last,
                      const Transform& texture, Shared& shared)
                : pattern(source, last, texture, shared) {}
        };
        // (Boxed: a compiled pattern and its maps are about 0.8 KB, and a
        // solid pigment, the usual one, has none; inline, each of 10^5
        // spheres paid them. A solid pigment is 88 bytes.)
        BoxedOptional<Patterned> patterned;
        bool uv = false;  // uv_mapping: read at (u, v, 0), nothing around it applied

        CompiledPigment(const Pigment& pigment, const Transform& texture, Shared& shared);
        // The colour at `point` (in the space around it: the world for a
        // texture's pigment), rgb, filter, transmit, at `hit`.
        std::array<double, 5> colour(const glm::dvec3& point, const pattern::Hit& hit) const;
        std::array<double, 5> colour_at(const glm::dvec3& point,
                                        const pattern::Hit& hit) const override {
            return colour(point, hit);
        }
    };
    // A normal: a pattern's bumps or slope (through a slope map), or a
    // normal map of normals (each in this pattern's space).
    struct CompiledNormal {
        CompiledPattern pattern;
        CompiledScalar amount, accuracy;
        bool no_bump_scale = false;
        std::vector<std::pair<CompiledScalar, std::shared_ptr<const CompiledNormal>>> normals;
        // The slope map: fixed when nothing in it moves (a still map
        // builds nothing per hit), else compiled (value, height, slope).
        std::vector<pattern::SlopeEntry> fixed_slopes;
        std::vector<std::array<CompiledScalar, 3>> slopes;
        bool uv = false;  // uv_mapping: perturbs at (u, v, 0), nothing around it applied
        std::shared_ptr<const pattern::ImageMap> bump_map;  // bump_map { }: its image

        CompiledNormal(const Normal& normal, const Transform& texture, Shared& shared);
        // `normal` (in the space around it) perturbed at `point` (there
        // too), at `hit`: unit.
        glm::dvec3 perturb(const glm::dvec3& normal, const glm::dvec3& point,
                           const pattern::Hit& hit) const;
        // The same before its length is set to one, where no_bump_scale
        // keeps it (what an average of normals sums, POV-Ray's
        // Perturb_Normal); null where the bump cancels the normal.
        std::optional<glm::dvec3> perturb_scaled(const glm::dvec3& normal, const glm::dvec3& point,
                                                 const pattern::Hit& hit) const;
    };
    // A plain texture's layer.
    struct CompiledLayer {
        std::shared_ptr<const CompiledPigment> pigment;
        std::shared_ptr<const CompiledNormal> normal;  // null: none
        std::shared_ptr<const CompiledFinish> finish;
        bool uv = false;  // a uv-mapped texture's layer: pigment and normal at (u, v, 0)
        // Its normal goes through these transforms' linear part first (a
        // uv-mapped texture's uv_outside; null: none).
        std::shared_ptr<const Motion> outer;
        // The shading normal `normal` (in the space around it) with this
        // layer's normal { } at `point` (there too).
        glm::dvec3 perturbed(const glm::dvec3& normal, const glm::dvec3& point,
                             const pattern::Hit& hit) const;
        MaterialSample material(const glm::dvec3& point, const pattern::Hit& hit) const;
        void fill(MaterialSample& m, const glm::dvec3& point,
                  const pattern::Hit& hit) const;  // (in place)
        // Its normal, then its material, as POV-Ray's ComputeLightedTexture
        // takes them: a layer with a normal { } leaves its perturbed normal
        // in hit.normal (POV-Ray's PNormal) for its pigment and the layers
        // after it.
        void sample(TextureSample::Layer& out, const glm::dvec3& point, const glm::dvec3& shading,
                    pattern::Hit& hit) const;
        // The point its pigment and normal read.
        glm::dvec3 at(const glm::dvec3& point, const glm::dvec2& surface_uv) const {
            return uv ? glm::dvec3(surface_uv, 0.0) : point;
        }
    };
    // A texture: plain layers, or a pattern over a map of textures.
    struct CompiledTexture {
        std::vector<CompiledLayer> layers;       // plain, top first
        BoxedOptional<CompiledPattern> pattern;  // (boxed, as CompiledPigment's)
        std::vector<std::pair<CompiledScalar, std::shared_ptr<const CompiledTexture>>> entries;
        bool has_normal = false;  // a layer here or below perturbs the normal
        bool uv = false;          // a uv-mapped patterned texture: its pattern at (u, v, 0)
        std::shared_ptr<const Motion> outer;  // as CompiledLayer::outer

        CompiledTexture(const Texture& texture, const Transform& outside,
                        const std::optional<Interior>& interior, Shared& shared);
        // (hit.normal: POV-Ray's PNormal, left by each layer's normal in turn.)
        void sample(const glm::dvec3& point, pattern::Hit& hit, const glm::dvec3& normal,
                    double weight, TextureSample& out) const;
        const CompiledLayer& picked_top(const glm::dvec3& point, const pattern::Hit& hit,
                                        glm::dvec3& at) const;
    };
    static CompiledTurbulence compile(const pattern::Turbulence& turbulence);

    std::shared_ptr<const CompiledTexture> texture_;  // shared by copies
    bool depends_on_time_ = false;
    bool opaque_ = true;
    struct CompiledFade {
        CompiledScalar distance, power;
        std::array<CompiledScalar, 3> colour;
    };
    struct CompiledDispersion {
        CompiledScalar value;
        int samples = 7;
    };
    // What an interior brings, each null where it brings nothing.
    struct InteriorParts {
        std::shared_ptr<const MediaVolume> media;
        std::shared_ptr<const void> key;                           // null: the primitive's own
        std::shared_ptr<const CompiledFade> fade;                  // null: no fading
        std::shared_ptr<const CompiledScalar> caustics;            // null: none
        std::shared_ptr<const CompiledScalar> ior;                 // null: 1
        std::shared_ptr<const CompiledDispersion> dispersion;      // null: none
        std::shared_ptr<const TextureEvaluator> interior_texture;  // null: none
    };
    // (Boxed, absent without any: most objects have none, and each of
    // 10^5 spheres paid 96 bytes for them inline.)
    BoxedOptional<InteriorParts> interior_;
    InteriorParts& parts() { return interior_ ? *interior_ : interior_.emplace(); }
};

}  // namespace hexant::runtime
