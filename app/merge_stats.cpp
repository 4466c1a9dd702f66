#include "app/merge_stats.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <ostream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "app/command_line.hpp"
#include "language/source_files.hpp"
#include "tracer/whole_file.hpp"

namespace hexant::app {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Rows kept as the largest window's (memory; the objects, which every
// window builds alike), and rows recomputed from the sums.
bool is_memory(const std::string& row) {
    return row.find("(MB)") != std::string::npos || row == "objects";
}
// Rows that are counts, written as whole numbers as render writes them.
bool is_count(const std::string& row) {
    return row.find("(") == std::string::npos && row.find(" per ") == std::string::npos;
}
bool is_ratio(const std::string& row) {
    return row.find(" per ray") != std::string::npos || row == "rays per second (M)";
}

json read_json(const std::string& path) {
    // A regular file of sane size only (a FIFO blocked merge-stats forever).
    constexpr std::size_t kMostStatsBytes = std::size_t(256) << 20;
    std::string text;
    try {
        text = language::read_source_text(path, kMostStatsBytes);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(path + ": cannot be read: " + e.what());
    }
    try {
        return json::parse(text);
    } catch (const json::exception& e) {
        throw std::runtime_error(path + ": not JSON (" + e.what() + ")");
    }
}

}  // namespace

void merge_stats(const std::vector<std::string>& windows, const std::string& output) {
    if (windows.empty())
        throw std::runtime_error("merge-stats needs the windows' statistics files");
    // (A file named twice would count twice; the output must not be one
    // of the windows.)
    std::vector<fs::path> seen;
    const fs::path out_path = fs::weakly_canonical(output);
    for (const auto& w : windows) {
        const fs::path p = fs::weakly_canonical(w);
        if (std::find(seen.begin(), seen.end(), p) != seen.end())
            throw std::runtime_error(w + ": named twice (each window once)");
        if (p == out_path)
            throw std::runtime_error(output + ": the output is one of the windows' files");
        seen.push_back(p);
    }
    std::string mode;
    json merged = json::object(), per_window = json::array(), frames = json::array();
    for (std::size_t w = 0; w < windows.size(); ++w) {
        const json file = read_json(windows[w]);
        if (!file.is_object() || file.size() != 1 || !file.begin().value().is_object())
            throw std::runtime_error(windows[w] +
                                     ": not the statistics of one render (--stats-json)");
        const std::string here = file.begin().key();
        if (!mode.empty() && here != mode)
            throw std::runtime_error(windows[w] + ": a " + here + " render, the others " + mode);
        mode = here;
        const json& column = file.begin().value();
        for (auto it = column.begin(); it != column.end(); ++it) {
            if (it.key() == "per frame") {
                for (const json& f : it.value()) frames.push_back(f);
                continue;
            }
            if (it.value().is_null()) continue;  // (a row with no value)
            if (!it.value().is_number())
                throw std::runtime_error(windows[w] + ": row \"" + it.key() + "\" is not a number");
            const double v = it.value().get<double>();
            if (!merged.contains(it.key())) merged[it.key()] = 0.0;
            const double sum = merged[it.key()].get<double>();
            merged[it.key()] = is_memory(it.key()) ? std::max(sum, v) : sum + v;
        }
        json window = {{"window", w}, {"file", windows[w]}, {"frames", json::array()}};
        for (const char* row :
             {"build time (s)", "sweep time (s)", "lazy build in render (s)", "render time (s)"})
            if (column.contains(row)) window[row] = column[row];
        if (column.contains("per frame"))
            for (const json& f : column["per frame"])
                window["frames"].push_back(f.value("frame", 0));
        per_window.push_back(window);
    }
    // The ratios from the sums.
    const auto get = [&](const char* row) {
        return merged.contains(row) ? merged[row].get<double>() : 0.0;
    };
    const double rays = get("primary rays") + get("shadow rays") + get("reflected rays") +
                        get("refracted rays") + get("radiosity rays");
    for (auto it = merged.begin(); it != merged.end(); ++it) {
        if (!is_ratio(it.key())) continue;
        if (it.key() == "rays per second (M)") {
            const double seconds = get("render time (s)");
            it.value() = seconds > 0.0 ? rays / seconds * 1e-6 : 0.0;
        } else {
            const std::string count = it.key().substr(0, it.key().find(" per ray"));
            it.value() = rays > 0.0 ? get(count.c_str()) / rays : 0.0;
        }
    }
    for (auto it = merged.begin(); it != merged.end(); ++it)
        if (is_count(it.key()))
            it.value() = static_cast<std::uint64_t>(it.value().get<double>() + 0.5);
    merged["per frame"] = frames;
    merged["per window"] = per_window;
    tracer::write_text_file(output, json{{mode, merged}}.dump(2) + "\n");
}

int run_merge_stats(const std::vector<std::string>& windows, const std::string& output,
                    std::ostream& out, std::ostream& err) {
    return run_reporting_errors(err, [&] {
        merge_stats(windows, output);
        out << "merged statistics of " << windows.size() << " window"
            << (windows.size() == 1 ? "" : "s") << ": " << output << "\n";
        return 0;
    });
}

}  // namespace hexant::app
