// Actions of global_settings' light transport blocks: radiosity { }
// (runtime/scene/radiosity_settings.hpp) and photons { }
// (runtime/scene/photon_settings.hpp), read as POV-Ray 3.7's
// Parse_Global_Settings reads them, with its limits and messages.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "language/actions/action.hpp"

namespace hexant::language {

// ---- radiosity { } (runtime/scene/radiosity_settings.hpp): POV-Ray 3.7's
// Parse_Global_Settings, its limits and its messages.
template <>
struct action<g::radiosity_open> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        st.require_whole_time(in.position(), "radiosity { }");
        st.scene.global.radiosity.enabled = true;
    }
};
// The block's settings together, as POV-Ray checks them after parsing:
// pretrace_end no larger than pretrace_start, and maximum_reuse
// well above minimum_reuse (the one not written moved, with a warning).
template <>
struct action<g::global_radiosity> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        runtime::RadiositySettings& r = st.scene.global.radiosity;
        if (r.pretrace_end > r.pretrace_start)
            throw ValueError(
                "radiosity's pretrace_end must be smaller than or equal to its "
                "pretrace_start");
        if (!(r.minimum_reuse > r.maximum_reuse * 0.5)) return;
        if (!r.minimum_reuse_set) {
            r.minimum_reuse = r.maximum_reuse * 0.5;
            st.warn(in.position(),
                    "radiosity's maximum_reuse should be well above its "
                    "minimum_reuse: minimum_reuse lowered to " +
                        std::to_string(r.minimum_reuse) + ", as POV-Ray does");
        } else if (!r.maximum_reuse_set) {
            r.maximum_reuse = r.minimum_reuse * 2.0;
            st.warn(in.position(),
                    "radiosity's maximum_reuse should be well above its "
                    "minimum_reuse: maximum_reuse raised to " +
                        std::to_string(r.maximum_reuse) + ", as POV-Ray does");
        } else if (r.minimum_reuse >= r.maximum_reuse) {
            throw ValueError("radiosity's maximum_reuse must be larger than its minimum_reuse");
        } else {
            st.warn(in.position(),
                    "radiosity's maximum_reuse should be well above its minimum_reuse");
        }
    }
};
template <>
struct action<g::radiosity_setting> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        std::vector<Value> given = st.values.close_frame();
        const std::string name = st.values.pop_name();
        runtime::RadiositySettings& r = st.scene.global.radiosity;
        const bool two = name == "count" || name == "nearest_count";
        if (given.size() > 1 && !two) throw ValueError("radiosity's " + name + " takes one value");
        if (name == "load_file" || name == "save_file") {
            (void)to_string_value(given.at(0), "radiosity's " + name);
            // (POV-Ray 3.7 ignores both too, with this advice.)
            st.warn(in.position(), "radiosity's " + name +
                                       " is ignored, as POV-Ray 3.7 ignores it (there it is a "
                                       "command-line option); hexant keeps no radiosity file");
            return;
        }
        const double x = to_constant(given.at(0), "radiosity's " + name);
        if (!std::isfinite(x)) throw ValueError("radiosity's " + name + " must be finite");
        const auto positive = [&](double& into) {
            if (!(x > 0.0)) throw ValueError("radiosity's " + name + " must be a positive number");
            into = x;
        };
        if (name == "always_sample")
            r.always_sample = static_cast<int>(x) != 0;
        else if (name == "normal")
            r.normal = static_cast<int>(x) != 0;
        else if (name == "media")
            r.media = static_cast<int>(x) != 0;
        else if (name == "subsurface")
            r.subsurface = static_cast<int>(x) != 0;
        else if (name == "brilliance")
            r.brilliance = static_cast<int>(x) != 0;
        else if (name == "pretrace_start" || name == "pretrace_end") {
            if (!(x > 0.0 && x <= 1.0))
                throw ValueError("radiosity's " + name +
                                 " must be greater than 0 and no higher than 1");
            (name == "pretrace_start" ? r.pretrace_start : r.pretrace_end) = x;
        } else if (name == "brightness")
            positive(r.brightness);
        else if (name == "error_bound")
            positive(r.error_bound);
        else if (name == "low_error_factor")
            positive(r.low_error_factor);
        else if (name == "maximum_reuse") {
            positive(r.maximum_reuse);
            r.maximum_reuse_set = true;
        } else if (name == "adc_bailout")
            positive(r.adc_bailout);
        else if (name == "max_sample")
            r.max_sample = x;
        else if (name == "gray_threshold") {
            if (!(x >= 0.0 && x <= 1.0))
                throw ValueError("radiosity's gray_threshold must be from 0 to 1");
            r.gray_threshold = x;
        } else if (name == "minimum_reuse") {
            if (!(x >= 0.0)) throw ValueError("radiosity's minimum_reuse must not be negative");
            r.minimum_reuse = x;
            r.minimum_reuse_set = true;
        } else if (name == "recursion_limit") {
            r.recursion_limit = static_cast<int>(
                checked_integer(x, name, 1, runtime::RadiositySettings::kMostRecursion));
        } else if (name == "count") {
            const long long count = checked_integer(x, name, 1, 1 << 20);
            long long pool = std::max<long long>(1600, count);
            if (given.size() > 1)
                pool =
                    checked_integer(to_constant(given[1], "radiosity's count"), name, 1, 1 << 20);
            if (pool < count)
                throw ValueError(
                    "radiosity's count can not be more than its direction pool "
                    "(count's second value)");
            r.count = static_cast<int>(count);
            r.direction_pool = static_cast<int>(pool);
        } else {  // nearest_count
            r.nearest_count = static_cast<int>(
                checked_integer(x, name, 1, runtime::RadiositySettings::kMostNearestCount));
            r.nearest_count_pretrace = 0;
            if (given.size() > 1) {
                const long long apt = checked_integer(
                    to_constant(given[1], "radiosity's nearest_count"), name, 0, 1 << 20);
                if (apt >= r.nearest_count)
                    throw ValueError(
                        "radiosity's nearest_count for the adaptive pretrace (its "
                        "second value) must be smaller than the first");
                r.nearest_count_pretrace = static_cast<int>(apt);
            }
        }
    }
};
// ---- photons { } (runtime/scene/photon_settings.hpp): POV-Ray 3.7's
// Parse_Global_Settings, its defaults, limits and messages.
template <>
struct action<g::photons_global_open> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        st.require_whole_time(in.position(), "photons { }");
        st.scene.global.photons = runtime::PhotonSettings{};
    }
};
template <>
struct action<g::global_photons> {
    template <typename ActionInput>
    static void apply(const ActionInput&, Interpreter& st) {
        runtime::PhotonSettings& ph = st.scene.global.photons;
        // (A gather maximum of 0 means no photon maps, as in POV-Ray.)
        ph.enabled = ph.gather_max > 0;
        if (!ph.enabled) return;
        if (ph.gather_min < 0) throw ValueError("photons' min_gather_count cannot be negative");
        if (ph.gather_min > ph.gather_max)
            throw ValueError("photons' min_gather_count must be less than max_gather_count");
        if (ph.count <= 0 && !(ph.spacing > 0.0))
            throw ValueError("photons' spacing must be greater than 0");
    }
};
template <>
struct action<g::photons_setting> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, Interpreter& st) {
        std::vector<Value> given = st.values.close_frame();
        const std::string name = st.values.pop_name();
        runtime::PhotonSettings& ph = st.scene.global.photons;
        const std::size_t most =
            name == "radius"                                                     ? 4
            : name == "gather" || name == "media" || name == "expand_thresholds" ? 2
                                                                                 : 1;
        if (given.size() > most)
            throw ValueError("photons' " + name + " takes at most " + std::to_string(most) +
                             " value" + (most == 1 ? "" : "s"));
        if (name == "load_file" || name == "save_file") {
            if (given.empty()) throw ValueError("photons' " + name + " takes a file name");
            (void)to_string_value(given.at(0), "photons' " + name);
            st.warn(in.position(), "photons' " + name +
                                       " is ignored: hexant shoots the photons of every frame "
                                       "anew and keeps no photon file");
            return;
        }
        std::vector<double> x;
        for (const Value& v : given) {
            x.push_back(to_constant(v, "photons' " + name));
            if (!std::isfinite(x.back())) throw ValueError("photons' " + name + " must be finite");
        }
        if (x.empty() && name != "radius") throw ValueError("photons' " + name + " takes a value");
        if (name == "spacing") {
            if (!(x[0] > 0.0)) throw ValueError("photons' spacing must be greater than 0");
            ph.spacing = x[0];
        } else if (name == "count") {
            ph.count = checked_integer(std::trunc(x[0]), "photons' count", 0, 1LL << 32);
        } else if (name == "gather") {
            if (x.size() < 2) throw ValueError("photons' gather takes two values: MIN, MAX");
            ph.gather_min = int(checked_integer(std::trunc(x[0]), "photons' gather", -1, 1 << 20));
            ph.gather_max = int(checked_integer(std::trunc(x[1]), "photons' gather", -1, 1 << 20));
        } else if (name == "media") {
            if (x[0] < 0.0)
                throw ValueError("photons' media: max media steps must be non-negative");
            ph.media_max_steps =
                int(checked_integer(std::trunc(x[0]), "photons' media", 0, 1 << 20));
            if (x.size() > 1) {
                if (!(x[1] > 0.0))
                    throw ValueError("photons' media spacing factor must be greater than zero");
                ph.media_spacing_factor = x[1];
            }
        } else if (name == "jitter") {
            ph.jitter = x[0];
        } else if (name == "max_trace_level") {
            ph.max_trace_level =
                int(checked_integer(std::trunc(x[0]), "photons' max_trace_level", 0, 256));
        } else if (name == "adc_bailout") {
            ph.adc_bailout = x[0];
        } else if (name == "autostop") {
            ph.autostop = x[0];
        } else if (name == "expand_thresholds") {
            ph.expand_tolerance = x[0];
            if (ph.expand_tolerance < 0.0) {
                st.warn(in.position(),
                        "the first parameter of expand_thresholds must be greater than or equal "
                        "to 0; set to 0, as POV-Ray does");
                ph.expand_tolerance = 0.0;
            }
            if (x.size() > 1) {
                ph.expand_min = int(std::max(0.0, std::min(x[1], double(1 << 20))));
                if (x[1] < 0.0)
                    st.warn(in.position(),
                            "the second parameter of expand_thresholds must be greater than or "
                            "equal to 0; set to 0, as POV-Ray does");
            }
        } else {  // radius [GATHER [, FACTOR [, MEDIA [, MEDIA FACTOR]]]]
            if (x.size() > 0) ph.radius = x[0];
            if (x.size() > 1) ph.radius_factor = x[1];
            if (x.size() > 2) ph.media_radius = x[2];
            if (x.size() > 3) ph.media_radius_factor = x[3];
        }
    }
};
}  // namespace hexant::language
