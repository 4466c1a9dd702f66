#include "app/resume.hpp"

#include <optional>
#include <ostream>
#include <string>
#include <utility>

#include "image/image_format.hpp"
#include "tracer/image_output.hpp"
#include "tracer/whole_file.hpp"

namespace hexant::app {

namespace fs = std::filesystem;

namespace {

// The first reasons, joined: "a; b; c (and 2 more)".
std::string first_reasons(const std::vector<std::string>& reasons) {
    constexpr std::size_t kShown = 3;
    std::string text;
    for (std::size_t i = 0; i < reasons.size() && i < kShown; ++i)
        text += (i ? "; " : "") + reasons[i];
    if (reasons.size() > kShown)
        text += " (and " + std::to_string(reasons.size() - kShown) + " more)";
    return text;
}

// Why a frame file cannot be kept even as POV-Ray keeps it: it does not
// read as an image, or is of another size (one that declares more pixels
// than the frame is refused from its header). Empty when it can.
std::string unreadable(const fs::path& path, const runtime::Animation& animation) {
    try {
        const image::StoredImage stored = image::read_stored_image(
            path, std::size_t(animation.width) * std::size_t(animation.height));
        if (stored.width != animation.width || stored.height != animation.height)
            return "it is " + std::to_string(stored.width) + " by " +
                   std::to_string(stored.height) + " pixels, not " +
                   std::to_string(animation.width) + " by " + std::to_string(animation.height);
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

}  // namespace

ResumeCheck resume_check(const RenderArguments& args, const std::string& pattern,
                         const std::vector<int>& selected, const runtime::Animation& animation,
                         FrameRecords& records, const FrameRecords::ReadFiles* inputs,
                         std::ostream& err) {
    ResumeCheck check;
    // The side image (--error-image, --samples-image) a kept frame lacks:
    // those come only from a render, so the frame is rendered again.
    const auto side_missing = [&](int frame) -> std::string {
        for (const auto& [flag, side] : {std::pair<const char*, const std::optional<std::string>&>{
                                             "--error-image", args.error_image},
                                         {"--samples-image", args.samples_image}}) {
            if (!side) continue;
            const fs::path file = tracer::frame_path(*side, frame);
            std::error_code error;
            if (!fs::is_regular_file(file, error))
                return std::string("its ") + flag + " " + file.string() + " is not on disk";
        }
        return {};
    };
    // A frame or record on disk was written whole (a temporary renamed
    // over it); what a killed run left half-written is its temporaries.
    int leftovers = 0;
    std::size_t said = 0, kept_unlike = 0;
    for (const int frame : selected) {
        const fs::path path = tracer::frame_path(pattern, frame);
        leftovers += tracer::remove_leftover_temporaries(path);
        leftovers += tracer::remove_leftover_temporaries(frame_record_path(path));
        std::error_code error;
        if (!fs::is_regular_file(path, error)) {
            check.missing.push_back(frame);
            continue;
        }
        const std::string named = "frame " + std::to_string(frame) + " (" + path.string() + ")";
        if (args.resume_keep) {
            if (const std::string why = unreadable(path, animation); !why.empty()) {
                err << named << " rendered again: " << why << "\n";
                check.missing.push_back(frame);
                continue;
            }
            if (const std::string why = side_missing(frame); !why.empty()) {
                err << named << " rendered again: " << why << "\n";
                check.missing.push_back(frame);
                continue;
            }
            const std::vector<std::string> reasons = records.differences(frame, path, inputs);
            if (reasons.empty()) continue;
            if (++kept_unlike <= kResumeLinesShown)
                err << "note: " << named << " kept (--resume=keep), though "
                    << first_reasons(reasons) << "\n";
            continue;
        }
        std::vector<std::string> reasons = records.differences(frame, path, inputs);
        if (reasons.empty()) {
            const std::string why = side_missing(frame);
            if (why.empty()) continue;
            reasons.push_back(why);
        }
        if (++said <= kResumeLinesShown)
            err << named << " rendered again: " << first_reasons(reasons) << "\n";
        check.missing.push_back(frame);
    }
    if (said > kResumeLinesShown)
        err << "--resume: " << said - kResumeLinesShown
            << " more frames rendered again, not made by this render as it is set now\n";
    if (kept_unlike > 0)
        err << "note: --resume=keep kept " << kept_unlike << " frame"
            << (kept_unlike == 1 ? "" : "s")
            << " not known to be this render's: the contact sheet, GIF and video may mix two "
               "renders\n";
    // (The video's temporary lives through the whole render.)
    if (args.video) leftovers += tracer::remove_leftover_temporaries(*args.video);
    if (leftovers > 0)
        err << "--resume: removed " << leftovers << " half-written temporar"
            << (leftovers == 1 ? "y" : "ies") << "\n";
    return check;
}

}  // namespace hexant::app
