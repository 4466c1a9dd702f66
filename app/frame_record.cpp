#include "app/frame_record.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "app/version.hpp"
#include "tracer/whole_file.hpp"

namespace hexant::app {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The record's format: a reader refuses another (a newer hexant's).
constexpr int kRecordFormat = 1;
constexpr const char* kFormatKey = "hexant frame record";

// Every field of runtime::Animation changes pixels and is in
// render_settings: a field added there must be added to the record too (then
// this size with it), or a resume would keep frames made with another value.
// (The size on the machines the project builds on: x86-64, libstdc++.)
#if defined(__x86_64__) && defined(__GLIBCXX__)
static_assert(sizeof(runtime::Animation) == 120,
              "runtime::Animation changed: record its new field in render_settings "
              "(app/frame_record.cpp), then update this size");
#endif

// The shortest text that reads back as the same double.
std::string number(double v) {
    char text[32];
    const auto [end, error] = std::to_chars(text, text + sizeof text, v);
    return error == std::errc() ? std::string(text, end) : std::to_string(v);
}

std::string curve_text(const runtime::ShutterCurve& curve) {
    if (curve.is_box()) return "box";
    std::string text;
    for (const auto& key : curve.keys())
        text += (text.empty() ? "" : ",") + number(key.u) + ":" + number(key.weight);
    return text;
}

// How a difference in one setting is said: "it was made at 64x48, this
// render is 32x24".
std::string phrase(const std::string& key, const std::string& was, const std::string& now) {
    if (key == "size") return "it was made at " + was + ", this render is " + now;
    if (key == "hexant") return "it was made by hexant " + was + ", this is hexant " + now;
    if (key == "cyclic")
        return was == "yes" ? "it was made in a cyclic animation, this render's is not"
                            : "it was made in an animation that is not cyclic, this render's is";
    if (key == "declares") return "it was made with --declare " + was + ", this render with " + now;
    if (was.empty())
        return "its record says nothing of its " + key + " (this render's: " + now + ")";
    if (now.empty()) return "it was made with " + key + " " + was + ", which this render has not";
    return "its " + key + " was " + was + ", this render's is " + now;
}

}  // namespace

std::string hexant_version() {
    return version_number();
}

fs::path frame_record_path(const fs::path& frame_file) {
    return frame_file.parent_path() / ".hexant" / (frame_file.filename().string() + ".json");
}

std::vector<PixelSetting> render_settings(const Sampling& sampling, const RenderArguments& args,
                                          const runtime::Animation& a,
                                          const language::ParseOptions& options) {
    std::string declares;
    for (const auto& [name, value] : options.declares)
        declares += (declares.empty() ? "" : " ") + name + "=" + value;
    std::vector<PixelSetting> settings = {
        {"hexant", hexant_version()},
        {"size", std::to_string(a.width) + "x" + std::to_string(a.height)},
        {"frame range", std::to_string(a.initial_frame) + " to " + std::to_string(a.final_frame)},
        {"clock range", number(a.initial_clock) + " to " + number(a.final_clock)},
        {"cyclic", a.cyclic ? "yes" : "no"},
        {"clock_on", a.clock_given ? "1" : "0"},
        {"shutter", number(a.shutter)},
        {"shutter curve", curve_text(a.shutter_curve)},
        {"rolling shutter", number(a.rolling_shutter)},
        {"shutter position", a.shutter_lead() == 0.0   ? "start"
                             : a.shutter_lead() == 0.5 ? "centre"
                                                       : "end"},
        {"shutter beyond range", a.shutter_beyond_range ? "yes" : "no"},
        {"samples per pixel", std::to_string(sampling.samples)},
        // (The sequence and the estimate: frames of earlier samplers differ.)
        {"sampler", "joint sobol 21, block estimate"},
        {"target error", sampling.target_error > 0.0 ? number(sampling.target_error) : "none"},
        {"jitter", args.no_jitter ? "no" : "yes"},
        {"seed", std::to_string(args.seed)},
        {"light speed", args.light_speed && std::isfinite(*args.light_speed)
                            ? number(*args.light_speed)
                            : "instant"},
        {"declares", declares.empty() ? "none" : declares},
        {"language version",
         options.language_version ? number(*options.language_version) : "3.7 (none given)"},
        // (The file's own way of writing its format: +FN16's 16 bits, +FC's
        // run-length Targa, under the same name as the plain one.)
        {"file variant", args.output_variant.empty() ? "plain" : args.output_variant},
    };
    // (Only when asked: the records of every render made before --gi
    // existed stay valid.)
    if (args.gi_path) settings.push_back({"gi", "path"});
    return settings;
}

FrameRecords::FrameRecords(std::vector<PixelSetting> settings, const runtime::Animation& animation,
                           const fs::path& scene)
    : settings_(std::move(settings)), animation_(animation) {
    std::error_code error;
    const fs::path real = fs::canonical(scene, error);
    folder_ = (error ? fs::absolute(scene) : real).parent_path();
}

std::vector<PixelSetting> FrameRecords::frame_settings(int frame) const {
    std::vector<PixelSetting> all = settings_;
    all.insert(all.begin() + 2, {"clock", number(animation_.clock_of_frame(frame))});
    return all;
}

FileHash FrameRecords::hash(const fs::path& path) {
    std::error_code error;
    const auto bytes = fs::file_size(path, error);
    const auto time = fs::last_write_time(path, error);
    if (error) throw std::runtime_error(path.string() + ": cannot read it: " + error.message());
    if (const auto it = hashes_.find(path);
        it != hashes_.end() && it->second.bytes == bytes && it->second.time == time)
        return it->second.hash;
    FileHash h = hash_file(path);
    hashes_[path] = {bytes, time, h};
    return h;
}

std::string FrameRecords::input_name(const fs::path& path) const {
    const fs::path relative = path.lexically_relative(folder_);
    if (!relative.empty() && *relative.begin() != ".." && relative.is_relative())
        return relative.generic_string();
    return path.generic_string();
}

fs::path FrameRecords::input_path(const std::string& name) const {
    const fs::path path(name);
    return path.is_absolute() ? path : folder_ / path;
}

FrameRecords::ReadFiles FrameRecords::hash_inputs(const std::vector<fs::path>& inputs) {
    ReadFiles files;
    for (const fs::path& input : inputs) files.push_back({input_name(input), hash(input)});
    return files;
}

void FrameRecords::write(int frame, const fs::path& file, const ReadFiles& inputs) {
    json made = json::object();
    for (const auto& [key, value] : frame_settings(frame)) made[key] = value;
    json files = json::array();
    for (const auto& [name, h] : inputs)
        files.push_back({{"file", name}, {"bytes", h.bytes}, {"sha256", h.sha256}});
    // The frame's own bytes, as written: a file replaced or edited later
    // is not taken for it.
    const FileHash own = hash_file(file);
    const json record = {
        {kFormatKey, kRecordFormat},
        {"frame", frame},
        {"file",
         {{"name", file.filename().string()}, {"bytes", own.bytes}, {"sha256", own.sha256}}},
        {"made with", made},
        {"inputs", files},
    };
    tracer::write_text_file(frame_record_path(file), record.dump(2) + "\n");
}

std::vector<std::string> FrameRecords::differences(int frame, const fs::path& file,
                                                   const ReadFiles* inputs) {
    const fs::path record_file = frame_record_path(file);
    std::error_code error;
    if (!fs::exists(record_file, error))
        return {"it has no record of what made it (no " + record_file.string() +
                ": written by another program, by hand or by an older hexant, or stopped "
                "before its record was written)"};
    // The record read and checked for its shape; what is not a record of
    // this format is a reason, never a crash.
    // (Never opened when it is not a file: a FIFO there would block.)
    if (!fs::is_regular_file(record_file, error))
        return {"its record " + record_file.string() + " is not a regular file"};
    json record;
    try {
        std::ifstream in(record_file, std::ios::binary);
        if (!in) throw std::runtime_error("cannot be read");
        const std::string text{std::istreambuf_iterator<char>(in),
                               std::istreambuf_iterator<char>()};
        record = json::parse(text);
    } catch (const std::exception& e) {
        return {"its record " + record_file.string() + " is damaged (" + e.what() + ")"};
    }
    const auto foreign = [&](const std::string& why) {
        return std::vector<std::string>{"its record " + record_file.string() +
                                        " is not a hexant frame record hexant can read (" + why +
                                        ")"};
    };
    if (!record.is_object() || !record.contains(kFormatKey))
        return foreign("no \"" + std::string(kFormatKey) + "\" key");
    if (record[kFormatKey] != kRecordFormat)
        return foreign("its format is " + record[kFormatKey].dump() + ", this hexant reads " +
                       std::to_string(kRecordFormat));
    std::vector<std::string> reasons;
    try {
        if (record.at("frame").get<int>() != frame)
            reasons.push_back("its record is frame " + record.at("frame").dump() + "'s");
        const json& made = record.at("made with");
        if (!made.is_object()) return foreign("its \"made with\" is no object");
        std::set<std::string> known;
        for (const auto& [key, value] : frame_settings(frame)) {
            known.insert(key);
            const auto it = made.find(key);
            const std::string was = it == made.end() ? "" : it->get<std::string>();
            if (was != value) reasons.push_back(phrase(key, was, value));
        }
        for (const auto& [key, value] : made.items())
            if (!known.count(key)) reasons.push_back(phrase(key, value.get<std::string>(), ""));
        // The files its scene read, each as recorded, against this
        // render's (or, unknown, against the file now); then those this
        // render's scene read that its did not.
        const json& files = record.at("inputs");
        if (!files.is_array()) return foreign("its \"inputs\" is no list");
        std::map<std::string, std::string> current;
        if (inputs)
            for (const auto& [name, h] : *inputs) current[name] = h.sha256;
        std::set<std::string> recorded;
        for (std::size_t i = 0; i < files.size(); ++i) {
            const std::string name = files[i].at("file").get<std::string>();
            recorded.insert(name);
            const std::string what =
                i == 0 ? "the scene " + name : name + ", which its scene read,";
            std::string now;
            if (inputs) {
                const auto it = current.find(name);
                if (it == current.end()) {
                    reasons.push_back(i == 0 ? "it was made from another scene, " + name
                                             : "its scene read " + name +
                                                   ", which this render's does not");
                    continue;
                }
                now = it->second;
            } else {
                try {
                    now = hash(input_path(name)).sha256;
                } catch (const std::exception&) {
                    reasons.push_back(what + " is gone");
                    continue;
                }
            }
            if (now != files[i].at("sha256").get<std::string>())
                reasons.push_back(what + " has changed since");
        }
        if (inputs)
            for (const auto& [name, h] : *inputs)
                if (!recorded.count(name))
                    reasons.push_back("this render's scene reads " + name + ", which its did not");
        if (!reasons.empty()) return reasons;
        // All else alike: the file must be the one recorded.
        const json& own = record.at("file");
        const FileHash now = hash_file(file);
        if (now.bytes != own.at("bytes").get<std::uintmax_t>())
            reasons.push_back("the file was changed after it was rendered (" +
                              std::to_string(now.bytes) + " bytes, its record says " +
                              own.at("bytes").dump() + ")");
        else if (now.sha256 != own.at("sha256").get<std::string>())
            reasons.push_back(
                "the file was changed after it was rendered (its SHA-256 is not its record's)");
    } catch (const json::exception& e) {
        return foreign(e.what());
    } catch (const std::runtime_error& e) {
        reasons.push_back(e.what());
    }
    return reasons;
}

}  // namespace hexant::app
