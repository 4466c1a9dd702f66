#include "app/povray_render_options.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "image/image_format.hpp"

namespace hexant::app {

namespace fs = std::filesystem;
using language::Given;
using language::PovRaySettings;

namespace {

std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

// POV-Ray clips these values (backend/scene/view.cpp); so does hexant,
// saying so.
template <class T>
T clipped(const Given<T>& given, T low, T high, std::vector<std::string>& notes) {
    const T v = std::clamp(given.value, low, high);
    if (v != given.value)
        notes.push_back(given.source + ": taken as " + number(v) + ", as POV-Ray clips it to " +
                        number(low) + " to " + number(high));
    return v;
}

// POV-Ray's output type letters (+Fx) and hexant's extensions for them.
const char* output_extension(char type) {
    switch (type) {
        case 'E':
            return ".exr";
        case 'T':
        case 'C':
            return ".tga";
        case 'P':
            return ".ppm";
        case 'B':
            return ".bmp";
        case 'H':
            return ".hdr";
        default:
            return ".png";
    }
}
char output_letter(const fs::path& name) {
    const std::string ext = image::lower_case_extension(name);
    for (const char type : {'E', 'T', 'P', 'B', 'H'})
        if (ext == output_extension(type)) return type;
    return 'N';
}

// The frames' file pattern: -o, else POV-Ray's +O and +F, else hexant's
// default with the type's extension.
void map_output(const PovRaySettings& s, const ResolvedScene& resolved, RenderArguments& a,
                std::vector<std::string>& notes) {
    if (s.output_to_file && !s.output_to_file->value)
        throw std::runtime_error(s.output_to_file->source +
                                 ": hexant writes every frame to a file (it has no display to "
                                 "render to instead)");
    // The type the frames are written in: -o's extension, else +F's.
    const char type = a.output        ? output_letter(fs::path(*a.output))
                      : s.output_type ? s.output_type->value
                                      : 'N';
    if (s.bits_per_colour) {
        // POV-Ray writes PNG (and PPM) in 5 to 16 bits per colour; hexant
        // writes PNG in 8 or 16, its other formats in 8 (HDR and OpenEXR in
        // floats).
        const int bits = s.bits_per_colour->value;
        const std::string& source = s.bits_per_colour->source;
        if (type == 'E' || type == 'H')
            notes.push_back(source + ": not used: " + (type == 'E' ? "OpenEXR" : "Radiance HDR") +
                            " frames are floats (as in POV-Ray)");
        else if (type != 'N' && bits != 8)
            notes.push_back(source + ": not used: hexant writes this format in 8 bits per colour");
        else if (bits > 16 || bits < 1)
            throw std::runtime_error(source + ": POV-Ray writes 5 to 16 bits per colour, not " +
                                     std::to_string(bits));
        else if (bits > 8) {
            a.output_variant = "16";
            if (bits < 16)
                notes.push_back(source +
                                ": written in 16 bits per colour (POV-Ray writes 16-bit samples "
                                "too, rounded to " +
                                std::to_string(bits) + " bits)");
        } else if (bits < 8)
            notes.push_back(source + ": hexant writes PNG in 8 bits per colour, not fewer");
    }
    if (type == 'C') a.output_variant = "rle";
    if (type == 'E' && s.output_type && !a.output)
        notes.push_back(s.output_type->source +
                        ": OpenEXR in 32-bit float (POV-Ray writes 16-bit half floats)");
    if (a.output) {
        for (const auto* given : {s.output_file ? &s.output_file->source : nullptr,
                                  s.output_type ? &s.output_type->source : nullptr})
            if (given) notes.push_back(*given + ": overridden by -o");
        return;
    }
    const std::string extension = output_extension(type);
    if (s.output_file) {
        const std::string name = s.output_file->value.string();
        if (name == "-" || name == "stdout" || name == "stderr")
            throw std::runtime_error(s.output_file->source +
                                     ": hexant writes frames to files, not to a stream");
        a.output = povray_frame_pattern(s.output_file->value, extension, resolved.options.animation,
                                        resolved.scene);
    } else if (s.output_type) {
        a.output = "out/" + resolved.scene.stem().string() + "/frame_####" + extension;
    }
}

void map_frames(const PovRaySettings& s, const ResolvedScene& resolved, RenderArguments& a,
                std::vector<std::string>& notes) {
    const std::optional<std::string> frames = povray_frames(s, resolved.options.animation);
    if (!frames) return;
    if (a.frames) {
        for (const auto* given : {&s.subset_start, &s.subset_end})
            if (*given) notes.push_back((*given)->source + ": overridden by --frames");
        if (s.frame_step) notes.push_back(s.frame_step->source + ": overridden by --frames");
        return;
    }
    a.frames = frames;
}

// POV-Ray's antialiasing onto hexant's sampling. POV-Ray traces one ray
// through each pixel's centre unless +A; with +A it supersamples the
// pixels whose neighbours differ by more than the threshold, on a depth by
// depth grid (method 1) or recursively (method 2). hexant samples every
// pixel over the pixel and the shutter at once, adaptively by default: a
// tile doubles its samples while its estimated error is above a target.
// So -A is one sample at the centre; +A is the adaptive sampling, its
// target scaled by the threshold and its ceiling by the depth squared, so
// that POV-Ray's defaults (0.3, 3) give hexant's (1/128 under 256).
void map_sampling(const PovRaySettings& s, const RenderArguments& given, RenderArguments& a,
                  ResolvedScene& resolved, std::vector<std::string>& notes) {
    // The options that shape antialiasing, each with what it sets.
    std::vector<std::pair<std::string, const char*>> shaping;
    const auto shape = [&](const auto& field, const char* what) {
        if (field) shaping.emplace_back(field->source, what);
    };
    shape(s.antialias_threshold, "threshold");
    shape(s.antialias_depth, "depth");
    shape(s.jitter, "jitter");
    shape(s.jitter_amount, "jitter amount");
    if (!s.antialias) {
        shape(s.sampling_method, "sampling method");
        // (What hexant does instead: its flags' sampling, the default's
        // when none is given.)
        const std::string instead =
            given.samples_per_pixel || given.target_error || given.no_jitter
                ? "hexant samples as its flags say"
                : "hexant samples as by default (adaptively, --target-error 1/128 under --spp "
                  "256)";
        for (const auto& [source, what] : shaping)
            notes.push_back(source + ": the " + what +
                            " is not used: POV-Ray antialiases only with +A or Antialias=on, and " +
                            instead);
        return;
    }
    const int method = s.sampling_method ? clipped(*s.sampling_method, 0, 2, notes) : 1;
    std::optional<int> spp;
    std::optional<double> target;
    bool no_jitter = false;
    std::string how;
    if (!s.antialias->value || method == 0) {
        // (Method 0 is POV-Ray's tracing without antialiasing.) One ray
        // through the pixel's centre at the frame's clock, as POV-Ray's:
        // the shutter closed, unless --shutter says otherwise.
        spp = 1;
        no_jitter = true;
        how = "one ray through each pixel's centre (--spp 1 --no-jitter) ";
        if (given.scene.shutter) {
            how += "at the middle of the --shutter given";
        } else {
            a.scene.shutter = 0.0;
            resolved.options.animation.shutter = 0.0;
            how += "at the frame's clock (--shutter 0)";
        }
        how += ", as POV-Ray renders without antialiasing";
        if (s.antialias->value) how = s.sampling_method->source + ": " + how;
        for (const auto& [source, what] : shaping)
            notes.push_back(source + ": the " + what + " is not used without antialiasing");
    } else {
        const double threshold =
            s.antialias_threshold ? clipped(*s.antialias_threshold, 0.0, 1.0, notes) : 0.3;
        int ceiling = kDefaultCeiling;
        std::string ceiling_how = "--spp " + std::to_string(kDefaultCeiling);
        if (s.antialias_depth) {
            const int depth = clipped(*s.antialias_depth, 1, 9, notes);
            ceiling = 2 * static_cast<int>(std::lround(kDefaultCeiling / 2.0 * depth * depth / 9));
            ceiling_how = "--spp " + std::to_string(ceiling) + " (256 x depth " +
                          std::to_string(depth) + "^2 / 3^2)";
        }
        // (A --spp given is the count or the ceiling, whatever the
        // switches say: the note names what the render will take.)
        if (given.samples_per_pixel)
            ceiling_how = "--spp " + std::to_string(*given.samples_per_pixel) + " (as given)";
        const bool jitter =
            (!s.jitter || s.jitter->value) && (!s.jitter_amount || s.jitter_amount->value > 0.0);
        if (!jitter) {
            // Adaptive sampling needs random samples to estimate its error.
            spp = ceiling;
            no_jitter = true;
            how = "every pixel sampled at the centres of " + ceiling_how +
                  " strata, unjittered (--no-jitter; a smaller --spp is faster)";
        } else if (threshold == 0.0) {
            spp = ceiling;
            how = "every pixel sampled alike, " + ceiling_how +
                  " (threshold 0: POV-Ray supersamples every pixel)";
        } else {
            target = kDefaultTargetError * threshold / 0.3;
            if (s.antialias_depth) spp = ceiling;
            how = "each frame sampled until its estimated error is below --target-error " +
                  number(*target) + " (1/128 x threshold " + number(threshold) + " / 0.3), under " +
                  ceiling_how;
        }
        if (jitter && s.jitter_amount)
            notes.push_back(s.jitter_amount->source +
                            ": hexant jitters each sample over its whole stratum (amount 1)");
        if (method == 2)
            notes.push_back(s.sampling_method->source +
                            ": hexant's one adaptive sampling serves for both of POV-Ray's "
                            "methods");
    }
    std::vector<std::string> overridden;
    if (spp) {
        if (given.samples_per_pixel)
            overridden.push_back("--spp");
        else
            a.samples_per_pixel = spp;
    }
    // A --spp given that adaptive sampling cannot use (it needs 2 or more
    // to estimate its error) is a fixed count: the switch's target is
    // dropped, not left to refuse the render.
    const bool fixed_count = given.samples_per_pixel && *given.samples_per_pixel < 2;
    if (target) {
        if (given.target_error)
            overridden.push_back("--target-error");
        else if (fixed_count)
            overridden.push_back("--spp " + std::to_string(*given.samples_per_pixel) +
                                 " (that many samples a pixel, not adaptive: adaptive "
                                 "sampling needs a --spp of 2 or more)");
        else
            a.target_error = target;
    }
    a.no_jitter = given.no_jitter || no_jitter;
    std::string note = s.antialias->source + ": " + how;
    for (std::size_t i = 0; i < overridden.size(); ++i)
        note += (i ? " and " : "; ") + overridden[i];
    if (!overridden.empty()) note += " as given wins";
    notes.push_back(note);
}

}  // namespace

std::string povray_frame_pattern(const fs::path& name, const std::string& extension,
                                 const runtime::Animation& animation, const fs::path& scene) {
    const std::string text = name.string();
    if (text.find('#') != std::string::npos) return text;
    std::string file = name.filename().string();
    if (file.empty() || file == extension) {
        file = scene.filename().string();
        if (const auto dot = file.rfind('.'); dot != std::string::npos) file.erase(dot);
    } else if (const auto dot = file.rfind('.');
               dot != std::string::npos &&
               (dot + 1 == file.size() || file.substr(dot) == extension)) {
        file.erase(dot);
    }
    if (animation.is_animation()) {
        int digits = 1;
        for (long long last = animation.final_frame + (animation.cyclic ? 1LL : 0LL); last >= 10;
             last /= 10)
            ++digits;
        file += std::string(digits, '#');
    }
    return (name.parent_path() / (file + extension)).string();
}

std::optional<std::string> povray_frames(const PovRaySettings& s, const runtime::Animation& a) {
    if (!s.subset_start && !s.subset_end && !s.frame_step) return std::nullopt;
    // POV-Ray counts a cyclic animation's frames one more (its last frame
    // is the first again, not rendered): fractions of them do too.
    const long long counted =
        static_cast<long long>(a.final_frame) + (a.cyclic ? 1 : 0) - a.initial_frame + 1;
    const auto frame_of = [&](double v) {
        v = std::clamp(v, 0.0, 2147483647.0);
        return v == 0.0 || v >= 1.0 ? static_cast<long long>(v)
                                    : static_cast<long long>(static_cast<double>(counted) * v);
    };
    long long first = a.initial_frame, last = a.final_frame;
    if (s.subset_start) first = std::max<long long>(frame_of(s.subset_start->value), first);
    if (s.subset_end) last = std::max(frame_of(s.subset_end->value), first);
    const auto past = [&](const Given<double>& given, long long frame) {
        return std::runtime_error(given.source + ": frame " + std::to_string(frame) +
                                  " lies past the animation's last, frame " +
                                  std::to_string(a.final_frame) +
                                  " (POV-Ray renders it with the clock run on past "
                                  "Final_Clock; hexant renders the animation's frames only)");
    };
    if (first > a.final_frame) throw past(*s.subset_start, first);
    if (last > a.final_frame) throw past(*s.subset_end, last);
    const int step = s.frame_step ? s.frame_step->value : 1;
    if (step < 1) throw std::runtime_error(s.frame_step->source + ": the step must be 1 or more");
    if (step == 1) return std::to_string(first) + ":" + std::to_string(last);
    std::string list;
    for (long long frame = first; frame <= last; frame += step)
        list += (list.empty() ? "" : ",") + std::to_string(frame);
    return list;
}

RenderArguments with_povray_options(const RenderArguments& given, ResolvedScene& resolved,
                                    std::vector<std::string>& notes) {
    const PovRaySettings& s = resolved.povray;
    RenderArguments a = given;
    map_output(s, resolved, a, notes);
    map_frames(s, resolved, a, notes);
    map_sampling(s, given, a, resolved, notes);
    if (s.continue_trace && s.continue_trace->value) {
        a.resume = true;
        // The checked resume, not POV-Ray's keep-anything: +C is given to
        // finish an interrupted render, and a frame another render made
        // (other flags, size, scene) is what +C users lose hours to (issue
        // 46); --resume=keep is there for the rest.
        notes.push_back(s.continue_trace->source +
                        ": the frames already written by this same render are kept (--resume); "
                        "one made with other settings or files, or cut off mid-render, is "
                        "rendered again, where POV-Ray keeps or continues it (--resume=keep "
                        "keeps any frame of the right size)");
    }
    if (s.work_threads) {
        if (s.work_threads->value < 1)
            throw std::runtime_error(s.work_threads->source + ": needs 1 thread or more");
        if (given.threads)
            notes.push_back(s.work_threads->source + ": overridden by --threads");
        else
            a.threads = s.work_threads->value;
    }
    if (s.display && s.display->value)
        notes.push_back(s.display->source +
                        ": hexant opens no display window; the frames are written to files");
    if (s.quality && s.quality->value < 9)
        notes.push_back(s.quality->source +
                        ": hexant has no quality levels: it renders all it renders, as +Q9");
    const runtime::Animation& animation = resolved.options.animation;
    if (s.clock && !given.scene.clock_range && animation.is_animation())
        notes.push_back(s.clock->source +
                        ": not used: the animation's frames set the clock (as in POV-Ray)");
    return a;
}

void note_render_only(const ResolvedScene& resolved, const std::string& command,
                      std::ostream& err) {
    const std::vector<std::string> sources = language::render_only_sources(resolved.povray);
    if (sources.empty()) return;
    err << "note: not used by " << command << " (render's options):";
    for (const auto& source : sources) err << " " << source;
    err << "\n";
}

}  // namespace hexant::app
