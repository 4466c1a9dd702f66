// media { } and density { } (runtime/scene/media.hpp), read as POV-Ray
// 3.7's Parse_Media reads them, with its checks and messages.
// Part of the actions (language/actions.hpp).
#pragma once

#include "language/actions/maps.hpp"

namespace hexant::language {

// ---- density { }: a pigment (Parse_Media_Density_Pattern's Create_Pigment)

template <>
struct action<g::density_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.blocks.open(std::in_place_type<runtime::Pigment>);
    }
};
template <>
struct action<g::density_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& density = st.blocks.edit<runtime::Pigment>(in.position(), "a density");
        close_pigment(density);
        Value v{density};
        st.blocks.close();
        st.values.push(std::move(v));
    }
};
template <>
struct action<g::density_map_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        auto& density = st.blocks.edit<runtime::Pigment>(in.position(), "density_map");
        check_map_pattern(density.patterned, "density_map");
        density.pigment_map.clear();
    }
};
template <>
struct action<g::density_map_density_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        st.blocks.open(std::in_place_type<runtime::Pigment>);
    }
};
template <>
struct action<g::density_map_entry> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        close_pigment(st.blocks.edit<runtime::Pigment>(in.position(), "a density_map entry"));
        // (A density map's entries blend as a pigment map's: Blend_Map of
        // DENSITY_TYPE, evaluated by Compute_Pigment.)
        close_map_entry(st, in.position(), "density_map", &runtime::Pigment::pigment_map);
    }
};

// ---- media { }

template <>
struct action<g::media_open> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        (void)in;
        // POV-Ray 3.5 made method 3 with one interval and 10 samples the
        // default; a scene of an older #version keeps the old ones.
        st.blocks.open(st.version < 3.5 ? runtime::Media::legacy() : runtime::Media());
    }
};
template <>
struct action<g::media_base> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        if (!v.is<runtime::Media>())
            throw ValueError("media { } starts with a media, not a " + type_name(v));
        st.blocks.edit<runtime::Media>(in.position(), "a media") = v.as<runtime::Media>();
    }
};
template <>
struct action<g::media_setting_name> : name_action {};
// A whole number of at least `least` (POV-Ray truncates).
inline int media_count(const Value& v, const std::string& name, int least, const char* message) {
    const double x = to_constant(v, name);
    if (!(std::fabs(x) < 1.0e9))
        throw ValueError(name + " must be a whole number, not " + std::to_string(x));
    const int n = static_cast<int>(x);
    if (n < least) throw ValueError(message);
    return n;
}
template <>
struct action<g::media_setting_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const std::string name = st.values.pop_name();
        auto& media = st.blocks.edit<runtime::Media>(in.position(), name.c_str());
        if (name == "intervals") {
            media.intervals = media_count(
                v, name, 1, "at least one interval is needed in media (POV-Ray's rule)");
            // (POV-Ray keeps up to the largest count among a ray's media;
            // a runaway number is a runaway render.)
            if (media.intervals > 1000)
                throw ValueError("intervals above 1000 in media (each ray would sample them all)");
        } else if (name == "method") {
            media.method = media_count(v, name, 1, "media's sample method is 1, 2 or 3");
            if (media.method > 3) throw ValueError("media's sample method is 1, 2 or 3");
        } else if (name == "jitter") {
            media.jitter = to_constant(v, name);
        } else if (name == "aa_threshold") {
            media.aa_threshold = to_constant(v, name);
            if (!(media.aa_threshold > 0.0))
                throw ValueError("aa_threshold in media must be greater than zero");
        } else if (name == "aa_level") {
            media.aa_level = media_count(v, name, 1, "aa_level in media must be at least one");
            // (Each level may double an interval's samples: 2^16 is as many
            // as a ray can afford; POV-Ray's scenes use 3 to 6.)
            if (media.aa_level > 16) throw ValueError("aa_level in media above 16");
        } else if (name == "absorption") {
            media.absorption = to_colour(v, name);
        } else if (name == "emission") {
            media.emission = to_colour(v, name);
        } else if (name == "confidence") {
            media.confidence = to_constant(v, name);
            if (!(media.confidence >= 0.0 && media.confidence < 1.0))
                throw ValueError("confidence in media is from 0 up to (not including) 1");
        } else if (name == "variance") {
            media.variance = to_constant(v, name);
        } else {
            media.ratio = to_constant(v, name);
        }
    }
};
template <>
struct action<g::media_samples> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const std::vector<Value> given = st.values.close_frame();
        auto& media = st.blocks.edit<runtime::Media>(in.position(), "samples");
        const char* least = "at least one sample per interval is needed in media";
        media.min_samples = media_count(given.at(0), "samples", 1, least);
        media.max_samples =
            given.size() > 1 ? media_count(given[1], "samples", 1, least) : media.min_samples;
        if (media.max_samples < media.min_samples)
            throw ValueError("media's maximum number of samples is below its minimum");
        if (media.max_samples > 10000) throw ValueError("samples above 10000 in media");
    }
};
template <>
struct action<g::media_collect> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const std::vector<Value> given = st.values.close_frame();
        st.blocks.edit<runtime::Media>(in.position(), "collect").collect =
            given.empty() || to_constant(given[0], "collect") > 0.0;
    }
};
template <>
struct action<g::scattering_type> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const double type = to_constant(st.values.pop(), "the scattering type");
        auto& media = st.blocks.edit<runtime::Media>(in.position(), "scattering");
        // (POV-Ray only warns of an unknown type and scatters it evenly.)
        if (type >= 1.0 && type < 6.0) {
            media.type = static_cast<runtime::Media::Scattering>(static_cast<int>(type));
        } else {
            st.warn(in.position(), "unknown scattering type " + std::to_string(type) +
                                       ": scattered evenly (type 1), as POV-Ray does");
            media.type = runtime::Media::Scattering::Isotropic;
        }
    }
};
template <>
struct action<g::scattering_colour> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.blocks.edit<runtime::Media>(in.position(), "scattering").scattering =
            to_colour(st.values.pop(), "the scattering colour");
    }
};
template <>
struct action<g::scattering_setting_name> : name_action {};
template <>
struct action<g::scattering_setting_value> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        const std::string name = st.values.pop_name();
        auto& media = st.blocks.edit<runtime::Media>(in.position(), name.c_str());
        if (name == "eccentricity") {
            if (media.type != runtime::Media::Scattering::HenyeyGreenstein)
                throw ValueError(
                    "eccentricity goes only with scattering type 5 "
                    "(Henyey-Greenstein), as in POV-Ray");
            media.eccentricity = to_float(v, name);
        } else {
            media.extinction = to_float(v, name);
        }
    }
};
template <>
struct action<g::media_density> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        Value v = st.values.pop();
        st.blocks.edit<runtime::Media>(in.position(), "density")
            .density.push_back(std::move(v.as<runtime::Pigment>()));
    }
};
template <>
struct action<g::media_block> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        const auto& written = st.blocks.edit<runtime::Media>(in.position(), "a media");
        // (POV-Ray's methods 1 and 2 sample further, up to the maximum,
        // while the samples' variance stays above what confidence and
        // variance allow; hexant takes the minimum.)
        if (written.method != 3 && written.max_samples > written.min_samples)
            st.warn(in.position(),
                    "'samples' is read but not rendered as POV-Ray renders it: methods 1 and 2 "
                    "take the minimum number of samples, not more by POV-Ray's variance test");
        Value v{std::move(st.blocks.edit<runtime::Media>(in.position(), "a media"))};
        st.blocks.close();
        st.values.push(std::move(v));
    }
};

// A media value where one is wanted: interior { media { } }, the scene's top.
inline runtime::Media media_value(Value v) {
    if (!v.is<runtime::Media>()) throw ValueError("expected a media, not a " + type_name(v));
    return std::move(v.as<runtime::Media>());
}
template <>
struct action<g::interior_media> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        runtime::Media media = media_value(st.values.pop());
        st.blocks.edit<runtime::Interior>(in.position(), "media").media.push_back(std::move(media));
    }
};
template <>
struct action<g::scene_media> {
    template <typename ActionInput>
    static void apply([[maybe_unused]] const ActionInput& in, [[maybe_unused]] Interpreter& st) {
        st.require_whole_time(in.position(), "the atmosphere's media");
        st.scene.atmosphere.push_back(media_value(st.values.pop()));
    }
};

}  // namespace hexant::language
