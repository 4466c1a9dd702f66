// A texture compiled for the tracer: the pigment's pattern, the finish and
// the interior, evaluated at a world point and time into plain numbers.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/compiled_function.hpp"
#include "runtime/material.hpp"
#include "runtime/material_sample.hpp"
#include "runtime/motion.hpp"

namespace hexant::runtime {

class TextureEvaluator {
public:
    // `texture.transform` maps texture space to the world (the object's
    // transforms written after the texture are already appended, so the
    // texture moves with the object). Throws ObjectError, naming the place,
    // for a pattern hexant does not have.
    TextureEvaluator(const Texture& texture, const std::optional<Interior>& interior);

    MaterialSample at(const glm::dvec3& world_point, double t) const;
    bool depends_on_time() const { return depends_on_time_; }

    // Whether the texture perturbs the shading normal (normal { }).
    bool has_normal() const { return normal_ != nullptr; }
    // The unit shading normal `normal` (unit, world, already turned to face
    // the viewer, as POV-Ray perturbs it) perturbed at `world_point` and
    // time t: taken into the normal pattern's space, bumped, taken back
    // (POV-Ray's Warp_Normal, Perturb_Normal, UnWarp_Normal). A bump that
    // cancels the normal leaves it as it was.
    glm::dvec3 perturb(const glm::dvec3& normal, const glm::dvec3& world_point, double t) const;

private:
    struct CompiledColour {
        std::array<CompiledScalar, 5> c;
    };
    static CompiledColour compile(const ColourFunction& colour);

    // The finish and the interior's ior. A finish of constants is shared by
    // every texture that has the same numbers (a scene of 10^5 spheres
    // that differ in colour keeps one), so an object pays a pointer for it.
    struct CompiledFinish {
        CompiledScalar ambient, diffuse, brilliance, phong, phong_size, specular, roughness,
            emission, ior;
        std::array<CompiledScalar, 3> reflection;
    };
    static std::shared_ptr<const CompiledFinish> compile(const Finish& finish,
                                                         const std::optional<Interior>& interior);

    // A pattern's parameters, compiled (runtime/pattern/pattern.hpp).
    struct CompiledTurbulence {
        std::array<CompiledScalar, 3> amount;
        CompiledScalar octaves, omega, lambda;
        pattern::Octaves at(double t) const;
    };
    struct CompiledWarp {
        std::shared_ptr<const Motion> transform;  // else turbulence
        CompiledTurbulence turbulence;
    };
    struct CompiledPattern {
        const pattern::Kind* kind = nullptr;
        // Its last transforms, then the texture's: pattern space to world.
        std::shared_ptr<const Motion> head;
        std::array<CompiledScalar, 3> vector;
        std::array<CompiledScalar, 2> number;
        std::optional<CompiledTurbulence> turbulence;
        CompiledScalar frequency, phase, exponent;
        pattern::Wave wave = pattern::Wave::Ramp;
        int noise_generator = pattern::kDefaultNoiseGenerator;
        std::vector<CompiledWarp> warps;  // in the order written
        // The parameters, when none moves: a still pattern pays nothing per
        // hit for time.
        std::optional<pattern::Values> fixed;
        double fixed_exponent = 1.0;

        CompiledPattern(const pattern::Pattern& source, const Transform& last, const Transform& texture);
        bool depends_on_time() const;
        // The parameters at t.
        pattern::Values values(double t) const { return fixed ? *fixed : values_at(t); }
        pattern::Values values_at(double t) const;
        double exponent_at(double t) const {
            return fixed ? fixed_exponent : pattern::single(exponent.at(t));
        }
        // The world point in pattern space (POV-Ray's Warp_EPoint): the
        // last transforms first, then each earlier step, last written
        // first; classic turbulence last of all, unless the kind reads it
        // itself.
        glm::dvec3 point(const glm::dvec3& world, double t, const pattern::Values& v) const {
            return walk(world, t, v, NoMaps{});
        }
        struct NoMaps {};  // (a pigment's point: no Jacobians computed)
        // The same, handing each transform's pattern-to-world linear part
        // (head first) to on_map: what a normal goes through.
        template <class OnMap>
        glm::dvec3 walk(const glm::dvec3& world, double t, const pattern::Values& v, OnMap on_map) const;
    };
    // A pigment: a colour, or a pattern through a colour map or a
    // pigment map of pigments (each evaluated in this pattern's space).
    struct CompiledPigment {
        std::optional<CompiledColour> solid;
        std::optional<CompiledPattern> pattern;
        // The colour map: fixed when nothing in it moves, else compiled.
        std::vector<pattern::MapEntry> fixed_map;
        std::vector<std::pair<CompiledScalar, CompiledColour>> map;
        std::vector<std::pair<CompiledScalar, std::shared_ptr<const CompiledPigment>>> pigments;

        CompiledPigment(const Pigment& pigment, const Transform& texture);
        // The colour at `point` (in the space around it: the world for a
        // texture's pigment), rgb, filter, transmit.
        std::array<double, 5> colour(const glm::dvec3& point, double t) const;
    };
    struct CompiledNormal {
        CompiledPattern pattern;
        CompiledScalar amount, accuracy;
        bool no_bump_scale = false;
    };
    static CompiledTurbulence compile(const pattern::Turbulence& turbulence);

    Pigment::Pattern pattern_;
    bool depends_on_time_ = false;
    std::vector<CompiledColour> colours_;
    std::shared_ptr<const CompiledPigment> pigment_;  // shared by copies
    std::shared_ptr<const CompiledNormal> normal_;
    std::shared_ptr<const CompiledFinish> finish_;
};

}  // namespace hexant::runtime
