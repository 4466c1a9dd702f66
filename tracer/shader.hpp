// POV-Ray 3.7's lighting at a surface event, at the event's own time: for
// each plain texture the texture's patterns pick there (texture_map), and
// each of its layers, top first, seen through the ones above: ambient
// (times the global ambient_light) and emission, then per point light
// diffuse with brilliance, phong and specular highlights, with a hard
// shadow ray cast at the same time, once per light at the hit (shadowless
// lights cast none and, as POV-Ray's fill lights, add no highlights); then
// transmission through every layer (filter, transmit, refraction by ior)
// and each layer's reflection by recursion up to max_trace_level; the
// plain textures' colours blended by their weights. Colours are linear
// (assumed_gamma 1.0). Lights as POV-Ray's (tracer/light.hpp): spotlights
// and cylinders attenuate, fade with distance, and an area light's shadow
// ray aims at one point of its grid per sample.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "runtime/geometry/spacetime.hpp"
#include "runtime/scene/scene.hpp"
#include "runtime/texture/texture_evaluator.hpp"
#include "tracer/light.hpp"
#include "tracer/light_travel.hpp"
#include "tracer/media.hpp"
#include "tracer/photon_map.hpp"
#include "tracer/radiosity_cache.hpp"
#include "tracer/ray_query.hpp"
#include "tracer/reflectivity.hpp"
#include "tracer/thread_state.hpp"

namespace hexant::tracer {

class Shader {
  public:
    // `travel`: how rays run back in time as they go (light_travel.hpp;
    // the default, instant light, as before).
    // `filtering`: whether some object that casts shadows may let light
    // through (IntelligentObject::filters_light); without one, a shadow ray
    // asks only whether it is blocked.
    Shader(const runtime::SceneDescription& scene, const RayQuery& query, LightTravel travel = {},
           bool filtering = false);

    // The objects a camera ray may start inside that matter to it (those
    // with media, and with fog or an atmosphere the non-hollow ones; when
    // light passes through some object (`refracting`), every one, for the
    // refraction list): each camera ray starts in those whose solid holds
    // its origin, as POV-Ray's InitRayContainerState finds them (in the
    // order of the scene's objects, where POV-Ray takes its bounding
    // tree's). Objects whose extent cannot hold the eye may be left out.
    static bool matters_to_camera(const runtime::SceneDescription& scene,
                                  const runtime::IntelligentObject& object, bool refracting);
    void set_camera_interiors(std::vector<const runtime::IntelligentObject*> objects) {
        camera_interiors_ = std::move(objects);
    }

    // The colour seen along a primary ray.
    glm::dvec3 trace(const runtime::Ray4& ray, ThreadState& state) const {
        ++state.counters.primary_rays;
        return radiance(ray, 1, 1.0, runtime::kSightImage,
                        camera_interiors_.empty() ? Inside{} : inside_at(ray.origin), state);
    }

    // Radiosity (global_settings { radiosity { } }): the frame's cache and
    // the eye its reuse distances are measured from, set before each frame
    // (null: none). Between the pretrace's passes the cache is only read.
    bool radiosity_enabled() const { return radiosity_.enabled; }
    const runtime::RadiositySettings& radiosity_settings() const { return radiosity_; }
    void set_radiosity_cache(const RadiosityCache* cache, const glm::dvec3& eye) {
        radiosity_cache_ = cache;
        radiosity_eye_ = eye;
    }
    // --gi path: each sample gathers one ray per bounce at its own time
    // (Shader::radiosity_path), no cache.
    void set_radiosity_path(bool path) { radiosity_path_ = path; }
    // How far a query of each bounce may reuse a record, in its harmonic
    // means (RadiosityCache's `reach`).
    std::vector<double> radiosity_reach() const;

    // Photons (global_settings { photons { } }, tracer/shader_photons.cpp):
    // the frame's map, set before each frame (null: none, or none made),
    // which every surface shaded gathers from.
    bool photons_enabled() const { return photons_.enabled; }
    const runtime::PhotonSettings& photon_settings() const { return photons_; }
    void set_photon_map(const PhotonMap* map) {
        photon_map_ = map != nullptr && !map->empty() ? map : nullptr;
    }
    // The frame's media photons (null: none), which media samples gather
    // (POV-Ray's mediaPhotonMap).
    void set_media_photon_map(const PhotonMap* map) {
        media_photon_map_ = map != nullptr && !map->empty() ? map : nullptr;
    }
    const std::vector<ShadedLight>& lights() const { return lights_; }
    // One photon being shot: its light (an index in lights()), the target
    // it is shot at (ObjectFlags::photon_group) and the spread of the
    // photons, the area each stands for being spread^2 times the distance
    // travelled^2 (spread^2 alone for a parallel light): POV-Ray's
    // photonSpread.
    struct PhotonShot {
        std::size_t light = 0;
        std::int32_t target = -1;
        double spread = 0.0;
    };
    // Traces a photon of `colour` along `ray` (from its light), appending
    // the photons it leaves on surfaces to `out` and in media to
    // `media_out`. Returns whether it met its target.
    bool shoot_photon(const PhotonShot& shot, const runtime::Ray4& ray, const glm::dvec3& colour,
                      std::vector<Photon>& out, std::vector<Photon>& media_out,
                      ThreadState& state) const;

  private:
    // `sight`: the kind of ray (runtime::RaySight), which decides the
    // objects hidden from it; `inside`: the interiors it starts in (a
    // camera ray: none known; one that finds itself leaving an object
    // counts that object from its start).
    // (`distance`: where given, set to the distance to the hit, infinity
    // for none: radiosity's gathering rays.)
    glm::dvec3 radiance(const runtime::Ray4& ray, int depth, double weight, std::uint8_t sight,
                        const Inside& inside, ThreadState& state, double* distance = nullptr) const;
    // The interiors among camera_interiors_ that hold `event`.
    Inside inside_at(const runtime::Event& event) const;
    // The nearest hit along `ray` within (0, s_max), and in `on` the ray it
    // is on: `ray` itself (on is left alone: the caller sets it to ray),
    // or, for light that would run back past the floor, its held piece
    // (light_travel.hpp).
    [[gnu::always_inline]] inline std::optional<runtime::ObjectHit> nearest(
        const runtime::Ray4& ray, runtime::Ray4& on, ThreadState& state, std::uint8_t sight,
        double s_max = std::numeric_limits<double>::infinity()) const;
    // The same, not inlined: for the shader's other files.
    std::optional<runtime::ObjectHit> nearest_hit(const runtime::Ray4& ray, runtime::Ray4& on,
                                                  ThreadState& state, std::uint8_t sight) const;
    // Whether anything lies on `ray` within (0, reach], both pieces.
    [[gnu::always_inline]] inline bool blocked(const runtime::Ray4& ray, double reach,
                                               ThreadState& state) const;
    // A hit being shaded: the ray's unit direction, the event, the raw
    // normal (shading, turned to face the viewer), the geometric one (so
    // turned too), where secondary rays start, and the ray's depth and
    // weight.
    struct Hit {
        // (A constructor of its own: an aggregate's braces would first zero
        // all of it, its lists of interiors included, on every hit.)
        Hit(const runtime::Ray4& ray_, const runtime::SurfacePoint& p_, int depth_, double weight_)
            : ray(ray_), p(p_), depth(depth_), weight(weight_) {}
        const runtime::Ray4& ray;
        const runtime::SurfacePoint& p;
        int depth;
        double weight;
        glm::dvec3 d{0.0}, point{0.0}, raw{0.0}, geometric{0.0}, start{0.0};
        double time = 0.0;
        bool back = false;
        std::uint8_t sight = runtime::kSightImage;  // the ray's kind
        // double_illuminate: lit from behind its surface too; shadow rays
        // toward such lights start off that side (back_start).
        bool double_lit = false;
        glm::dvec3 back_start{0.0};
        // light_group: the innermost group the object is in (-1: none),
        // and whether the scene's other lights pass it by.
        std::int32_t light_group = -1;
        bool no_global_lights = false;
        // The interiors the ray crossed to get here (its own and, when it
        // leaves one, that one), and the object hit as one of them.
        Inside around{};
        Inside::Entry entry{};
        // The object hit, and its interior as refraction knows it
        // (TextureEvaluator::interior_key, else the object).
        const runtime::IntelligentObject* object = nullptr;
        const void* interior = nullptr;
        // The interiors a ray refracted here is in.
        // What rays from here carry on: only interiors with media (an
        // object without is known on its own segment alone: the members
        // of a CSG are objects of their own, and a ray that left through
        // one must not stay inside another).
        Inside carried() const { return around.with_media_only(); }
        // A camera ray leaving an interior its list does not hold: it
        // started inside (POV-Ray's InitRayContainerState fills a camera
        // ray's list by inside tests at the eye).
        bool started_inside() const {
            return depth == 1 && back && around.passed_count == 0 && object->inside(ray.origin);
        }
        // The relative index Fresnel reflection sees for ior `ior` here.
        double relative_ior(double ior) const {
            return around.relative_ior(interior, ior, started_inside());
        }
        // (`passed`: the refraction list it goes on with, Inside::refract.)
        Inside refracted(const Inside& passed) const {
            Inside out = back          ? carried().without(entry.key)
                         : entry.media ? carried().with(entry)
                                       : carried();
            out.passed = passed.passed;
            out.passed_count = passed.passed_count;
            return out;
        }
    };
    // Fills in what a hit knows from its object and the ray that met it
    // (`inside`: the interiors the ray was in); `h.sight` is the caller's.
    void describe(Hit& h, const runtime::IntelligentObject& object, const runtime::Ray4& ray,
                  const Inside& inside) const;
    static double fresnel_ior(const Hit& h, const runtime::MaterialSample& m);
    // The colour of one plain texture (its `count` layers, top first) at
    // the hit; `seen` keeps what is known of each light across the plain
    // textures and layers of the hit (null: one layer, nothing to keep).
    glm::dvec3 lit(const Hit& h, const runtime::TextureSample::Layer* layers, std::size_t count,
                   std::vector<ShadingScratch::Light>* seen, ThreadState& state) const;
    // Radiosity's light at the hit for a layer whose normal is `layer_normal`
    // (POV-Ray's RadiosityFunction::ComputeAmbient, times its brightness):
    // the cache's records reused, or a sample gathered. `weight`: the ray's
    // weight times the most the light can add (its error bound widens
    // below 0.25).
    glm::dvec3 radiosity_ambient(const Hit& h, const glm::dvec3& layer_normal, double brilliance,
                                 double weight, ThreadState& state) const;
    // --gi path's estimate of the same light: one gathering ray, its
    // direction the sample's own dimensions for this bounce.
    glm::dvec3 radiosity_path(const Hit& h, const glm::dvec3& layer_normal, double brilliance,
                              ThreadState& state) const;
    // One sample gathered (GatherLight): its rays' mean colour, and its
    // record kept where the path keeps them. Returns its quality.
    double gather(const Hit& h, const glm::dvec3& layer_normal, double brilliance,
                  glm::dvec3& illuminance, ThreadState& state) const;
    // A photon's path: its shot, where its photons go, the trace level,
    // POV-Ray's passThruPrev / passThruThis, the distance travelled
    // (photonDepth), and whether it met its target (for autostop).
    struct PhotonPath {
        const PhotonShot* shot = nullptr;
        std::vector<Photon>* out = nullptr;
        std::vector<Photon>* media_out = nullptr;
        int level = 0;
        bool pass_prev = true, pass_this = false;
        double depth = 0.0;
        bool hit_target = false;
    };
    void trace_photon(const runtime::Ray4& ray, const glm::dvec3& colour, double weight,
                      const Inside& inside, PhotonPath& path, ThreadState& state) const;
    // A photon's light `colour` after its way of `way` along `ray` through
    // the media of `inside` (hollow interiors), leaving media photons on
    // it where POV-Ray's PhotonTrace does: past the photon's first
    // surface, not just through a pass_through one, with photons' media
    // steps set.
    glm::dvec3 photon_media(const runtime::Ray4& ray, double way, const Inside& inside,
                            const glm::dvec3& colour, PhotonPath& path) const;
    // The photons around a hit, gathered once for its layers.
    struct PhotonGather {
        bool done = false;
        double radius = 0.0;
        PhotonMap::Found photons;
        // The last layer's estimate's variance, per channel: its photons'
        // terms squared, summed (photons as a Poisson process's points).
        glm::dvec3 variance{0.0};
    };
    // The light of the frame's photons at the hit, for a layer of material
    // `m`, normal `n` and opacity `opaque` (POV-Ray's
    // ComputePhotonDiffuseLight: each photon lights the layer as a light
    // from where it came, their sum over the gather's disc); its variance
    // left in `gather.variance`.
    glm::dvec3 photon_light(const Hit& h, const runtime::MaterialSample& m, const glm::dvec3& n,
                            double opaque, PhotonGather& gather, ThreadState& state) const;
    // Whether `object`, met by a shadow ray of light `light`, casts the
    // full shadow photon mapping wants (its caustic brings the light).
    bool photon_shadow(const runtime::IntelligentObject& object, std::size_t light) const;
    // Where a light lies from the hit, or that it does not shine there.
    [[gnu::always_inline]] inline void place(const ShadedLight& light, const Hit& h,
                                             ShadingScratch::Light& known) const;
    // What of light `index` reaches the hit along its shadow ray (an area
    // light: toward its grid point for this sample), per channel: 1 when
    // nothing is in the way, 0 when something opaque is, else the product
    // of the filters of the surfaces crossed.
    // (`behind`: the light shows through from behind the surface,
    // diffuse's second value: the ray leaves from that side.)
    [[gnu::always_inline]] inline glm::dvec3 shadow_filter(std::size_t index, const Hit& h,
                                                           const ShadingScratch::Light& known,
                                                           ThreadState& state,
                                                           bool behind = false) const;
    // POV-Ray 3.7's filtered shadows (TracePointLightShadowRay,
    // ComputeShadowColour): along a shadow ray that nothing opaque blocks,
    // each surface of an object that casts shadows, nearest first, filters
    // the light by its texture there; `depth` picks the scratch texture.
    // The ray starts in the interiors `around` (the list of the ray whose
    // hit or media sample it lights, as POV-Ray copies it) and crosses in
    // or out of each object it meets (ComputeShadowMedia); between two
    // surfaces the media of every interior it is in dim the light, when
    // all are hollow (ComputeShadowColour).
    // (`photon_light`: the light's index where photon_shadow applies to
    // the lit object (it collects photons), else -1.)
    glm::dvec3 filtered(runtime::Ray4 ray, double reach, int depth, Inside around,
                        ThreadState& state, std::ptrdiff_t photon_light = -1) const;
    // projected_through: whether `ray` toward `light` meets its object
    // before `reach`; then `reach` ends at the meeting.
    static bool projected(const ShadedLight& light, const runtime::Ray4& ray, double& reach);
    // A surface's filter: per plain texture the product over its layers of
    // colour x filter + transmit, blended by the plain textures' weights
    // (ComputeShadowTexture, ComputeOneTextureColour).
    // (`d`: the shadow ray's unit direction, for faked caustics.)
    glm::dvec3 transmittance(const runtime::SurfacePoint& p, const glm::dvec3& d, int depth,
                             ThreadState& state) const;
    // How much shows through the layers above layer `index` (POV-Ray's trans).
    static double layer_trans(const runtime::TextureSample::Layer* layers, std::size_t index);
    // A layer's highlights for light from unit `to_light` at incidence
    // `cosine`, seen along unit `d` about normal `n`: phong and specular,
    // tinted by metallic (POV-Ray's ComputePhongColour and
    // ComputeSpecularColour; shared by lights and photons).
    [[gnu::always_inline]] static glm::dvec3 highlights(const runtime::MaterialSample& m,
                                                        const glm::dvec3& d, const glm::dvec3& n,
                                                        const glm::dvec3& to_light, double cosine) {
        glm::dvec3 out(0.0);
        const glm::dvec3 tint =
            m.metallic > 0.0 ? metallic_tint(m.metallic, cosine, m.colour) : glm::dvec3(1.0);
        if (m.phong > 0.0) {
            const glm::dvec3 reflected = d - 2.0 * glm::dot(d, n) * n;
            const double c = glm::dot(reflected, to_light);
            if (c > 0.0) out += m.phong * std::pow(c, m.phong_size) * tint;
        }
        if (m.specular > 0.0) {
            const glm::dvec3 half = glm::normalize(to_light - d);
            const double c = glm::dot(half, n);
            if (c > 0.0) out += m.specular * std::pow(c, 1.0 / m.roughness) * tint;
        }
        return out;
    }
    // Heckbert's refraction of unit `d` through a surface of normal
    // `normal` for the relative index `eta` (POV-Ray's TraceRefractionRay):
    // false past the critical angle (total internal reflection); `d`
    // itself where `straight` (the same index on both sides).
    static bool refraction(const glm::dvec3& d, const glm::dvec3& normal, double eta, bool straight,
                           glm::dvec3& out) {
        double n = glm::dot(d, normal);
        const glm::dvec3 local = n <= 0.0 ? normal : -normal;
        n = std::fabs(n);
        const double k = 1.0 + eta * eta * (n * n - 1.0);
        if (k < 0.0) return false;
        out = straight ? d : eta * d + (eta * n - std::sqrt(k)) * local;
        return true;
    }
    // `c` raised to reflection { exponent }'s power (POV-Ray raises the
    // reflected light to 1 / E), negative channels taken as 0.
    static glm::dvec3 raised(glm::dvec3 c, double power) {
        if (power != 1.0)
            for (int k = 0; k < 3; ++k) c[k] = std::pow(std::max(c[k], 0.0), power);
        return c;
    }
    // The direction reflected about `normal`, kept above the surface whose
    // raw normal is `raw` (POV-Ray's ComputeReflection).
    static glm::dvec3 reflect(const glm::dvec3& d, const glm::dvec3& normal, const glm::dvec3& raw);
    // What a ray that hits nothing sees: the sky sphere over the background.
    glm::dvec3 sky(const glm::dvec3& direction, double t) const;
    // `colour` seen through the scene's fogs along `depth` of a ray in the
    // open (runtime/scene/fog.hpp).
    // (`shadow`: the light along a shadow ray, dimmed only.)
    glm::dvec3 fogged(const glm::dvec3& colour, const runtime::Ray4& ray, double depth,
                      bool shadow = false) const;
    // `colour` seen through what lies along `depth` of `ray` with the
    // interiors `around` (tracer/media.hpp): their media, then, when all
    // are hollow (POV-Ray's IsHollowRay), the atmosphere's media and fog.
    glm::dvec3 through_volume(const glm::dvec3& colour, const runtime::Ray4& ray, double depth,
                              const Inside& around, int level, ThreadState& state) const;
    // A shadow ray's light dimmed along `depth` of `ray` by the media in
    // `volumes` (media_attenuation: the atmosphere's; a surface left: its
    // interior's).
    glm::dvec3 shadow_media(const glm::dvec3& light, const runtime::Ray4& ray, double depth,
                            const runtime::MediaVolume& volume) const;
    // The same through the media of every interior in `around`, together.
    glm::dvec3 shadow_media(const glm::dvec3& light, const runtime::Ray4& ray, double depth,
                            const Inside& around) const;
    glm::dvec3 shadow_media(const glm::dvec3& light, const runtime::Ray4& ray, double depth,
                            std::vector<const runtime::MediaVolume::One*> media) const;
    // The light of light `index` arriving at `point` in media at time t,
    // after its shadow ray (MediaLightFn), which starts in the interiors
    // `around` (the viewing ray's). `collects`: whether the media sampled
    // collect photons (not all `collect off`): then a photon target that
    // refracts the light's photons shadows it fully, as for a surface
    // (POV-Ray's litObjectIgnoresPhotons, set by ComputeOneMediaSample).
    glm::dvec3 media_light(std::size_t index, const glm::dvec3& point, double t, int level,
                           const Inside& around, bool collects, glm::dvec3& to_light,
                           ThreadState& state) const;

    const RayQuery& query_;
    LightTravel travel_;
    bool filtering_ = false;
    std::vector<ShadedLight> lights_;
    // Each light's light_group (-1: the whole scene's), and each group's
    // parent (SceneDescription::light_groups).
    std::vector<std::int32_t> light_group_of_;
    std::vector<std::int32_t> group_parent_;
    // Whether light `index` lights the hit's object: a scene light unless
    // its group turned them off, a group's light only its members and the
    // members of groups within it (POV-Ray's ComputeDiffuseLight).
    bool lights_object(std::size_t index, const Hit& h) const {
        const std::int32_t group = light_group_of_[index];
        if (group < 0) return !h.no_global_lights;
        for (std::int32_t g = h.light_group; g >= 0; g = group_parent_[std::size_t(g)])
            if (g == group) return true;
        return false;
    }
    runtime::ColourFunction background_;
    // The sky sphere's pigments, the last written first (on top).
    std::vector<runtime::TextureEvaluator> sky_layers_;
    runtime::ColourFunction sky_emission_;
    std::vector<runtime::Fog> fogs_;
    std::vector<const runtime::IntelligentObject*> camera_interiors_;
    std::vector<runtime::Rainbow> rainbows_;
    std::shared_ptr<const runtime::MediaVolume> atmosphere_;  // media { } at the top
    int noise_generator_ = 2;  // global_settings { noise_generator } (fog, iridescence)
    runtime::ColourFunction ambient_light_;
    bool still_ambient_ = false;
    glm::dvec3 fixed_ambient_{0.0};
    int max_trace_level_;
    glm::dvec3 irid_wavelength_;  // global_settings' (iridescence.hpp)
    // Radiosity's settings and, per bounce, what POV-Ray derives from them
    // (SceneRadiositySettings::GetRecursionSettings).
    runtime::RadiositySettings radiosity_;
    struct RadiosityLevel {
        int rays = 0;         // rays a sample gathers with
        int reuse_count = 0;  // the weight of records enough to reuse (x 4)
        double factor = 1.0;  // of the error bound and the reuse distances
        int trace_level = 1;  // the level its rays start at
        double weight = 1.0;  // its rays' weight
    };
    std::vector<RadiosityLevel> radiosity_levels_;
    // With radiosity, a 3.7 scene's `ambient` lights nothing (only emission).
    bool ambient_lights_ = true;
    const RadiosityCache* radiosity_cache_ = nullptr;
    bool radiosity_path_ = false;
    glm::dvec3 radiosity_eye_{0.0};
    runtime::PhotonSettings photons_;
    const PhotonMap* photon_map_ = nullptr;
    const PhotonMap* media_photon_map_ = nullptr;
    bool legacy_sky_ = false;      // GlobalSettings::legacy_sky
    bool legacy_opacity_ = false;  // GlobalSettings::legacy_opacity
};

}  // namespace hexant::tracer
