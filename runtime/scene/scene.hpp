// What the language hands to the renderer: plain records, no syntax.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "runtime/objects/object.hpp"
#include "runtime/scene/animation.hpp"
#include "runtime/scene/camera.hpp"
#include "runtime/scene/fog.hpp"
#include "runtime/scene/light.hpp"
#include "runtime/scene/media.hpp"
#include "runtime/scene/photon_settings.hpp"
#include "runtime/scene/radiosity_settings.hpp"
#include "runtime/scene/rainbow.hpp"
#include "runtime/scene/sky_sphere.hpp"
#include "runtime/source_place.hpp"

namespace hexant::runtime {

struct GlobalSettings {
    double assumed_gamma = 1.0;
    // False for a scene read with POV-Ray's legacy rule (language version
    // below 3.7 and no assumed_gamma; its parser.cpp): no gamma correction
    // at all, the colours it computes are the file's values.
    bool gamma_correction = true;
    // A scene whose version ends below 3.7 layers its sky_sphere's
    // pigments as POV-Ray 3.6 did (3.7's ComputeSky keeps that rule for
    // them: the filter and transmit of all the layers multiplied together).
    bool legacy_sky = false;
    // Such a scene also dims a layer's own light by POV-Ray 3.6's opacity,
    // 1 - (filter x its largest channel + transmit), where 3.7 takes
    // 1 - filter - transmit (trace.cpp, ComputeLightedTexture's att).
    bool legacy_opacity = false;
    int max_trace_level = 5;
    ColourFunction ambient_light{{1.0, 1.0, 1.0, 0.0, 0.0}};
    // MegaPOV's global_settings { motion_blur SAMPLES, TIME }: hexant blurs
    // every render, so these are only defaults for --spp and --shutter
    // (TIME, in clock units, over the clock step; app/render_command.cpp).
    // noise_generator 1 to 3 for every pattern that names none (POV-Ray's
    // default 2); hexant applies it to the patterns written after it.
    int noise_generator = 2;
    // number_of_waves: the wave sources waves and ripples sum (POV-Ray's
    // default 10); like noise_generator, for the patterns written after it.
    int number_of_waves = 10;
    // irid_wavelength: the wavelengths iridescence works with, per channel,
    // in its units of film thickness (POV-Ray 3.7's default, scene.cpp:
    // <0.70, 0.52, 0.48>, red 700 nm, green 520, blue 480; its docs' 0.25,
    // 0.18, 0.14 are older).
    glm::dvec3 irid_wavelength{0.70, 0.52, 0.48};
    std::optional<int> motion_blur_samples;
    std::optional<double> motion_blur_time;
    // radiosity { }: with it, a 3.7 scene's ambient is not lit (only
    // emission is), as in POV-Ray's ComputeLightedTexture.
    RadiositySettings radiosity;
    // photons { } (runtime/scene/photon_settings.hpp).
    PhotonSettings photons;
    // The language version the scene ends with (3.62 without #version,
    // POV-Ray's EffectiveLanguageVersion).
    double language_version = 3.62;
};

// A branch whose condition depends on clock, as the language split it:
// where its condition was written and the instants where it switches.
struct TimeSplit {
    SourcePlace where;
    std::vector<double> instants;
};

// A light_group as the scene holds it: the group it is written in, whose
// lights light its members too (-1: none).
struct LightGroup {
    int parent = -1;
};

struct SceneDescription {
    CameraRecord camera;  // POV-Ray's default camera when the scene has none
    std::vector<LightRecord> lights;
    std::vector<ObjectPtr> objects;
    std::vector<LightGroup> light_groups;  // LightRecord::light_group, ObjectFlags::light_group
    ColourFunction background{};           // black
    std::optional<SkySphere> sky_sphere;   // over the background
    std::vector<Fog> fogs;
    std::vector<Rainbow> rainbows;  // finished (Rainbow::finish)
    // media { } written at the top: the atmosphere's, in the world
    // (runtime/scene/media.hpp).
    std::vector<Media> atmosphere;
    GlobalSettings global;
    // Every file the scene read (the scene, its includes, images, fonts,
    // #fopen'd files), canonical: an output never replaces one (issue 45).
    std::vector<std::filesystem::path> inputs;
    // The texture of objects that have none of their own (#default).
    Texture default_texture;
    Animation animation;
    std::vector<std::string> warnings;
    std::vector<TimeSplit> time_splits;
};

}  // namespace hexant::runtime
