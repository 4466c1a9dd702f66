#include "app/farm_command.hpp"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "app/command_line.hpp"
#include "app/povray_render_options.hpp"
#include "app/povray_words.hpp"
#include "app/render_command.hpp"
#include "app/scene_reading.hpp"
#include "language/interpreter.hpp"
#include "tracer/whole_file.hpp"

namespace hexant::app {

namespace fs = std::filesystem;

std::string shell_quote(const std::string& word) {
    std::string quoted = "'";
    for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

namespace {

// A word the scripts can hold: no control character (a newline would end
// the script's line and start a command of its own).
void check_word(const std::string& word, const std::string& what) {
    for (const char c : word)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            throw std::runtime_error(what + " holds a control character (a newline?): '" + word +
                                     "'");
}

// A value on an #SBATCH line: sbatch splits its own lines at blanks and
// reads quotes and #, so such values are refused (a path is written in
// double quotes: sbatch_path).
void check_sbatch_value(const std::string& value, const std::string& flag) {
    check_word(value, flag);
    if (value.empty() || value.find_first_of(" \t'\"#\\") != std::string::npos)
        throw std::runtime_error(flag + " '" + value +
                                 "': Slurm's #SBATCH lines take no blank, quote, # or "
                                 "backslash (and not an empty value)");
}

}  // namespace

FarmArguments split_farm_arguments(const std::vector<std::string>& words) {
    FarmArguments a;
    bool windows_given = false;
    for (std::size_t i = 0; i < words.size(); ++i) {
        const std::string& w = words[i];
        check_word(w, "the farm's word " + std::to_string(i + 1));
        const auto eq = w.find('=');
        const std::string flag = w.rfind("--", 0) == 0 ? w.substr(0, eq) : w;
        const auto value = [&]() -> std::string {
            if (eq != std::string::npos) return w.substr(eq + 1);
            if (i + 1 >= words.size()) throw std::runtime_error(flag + " needs a value");
            return words[++i];
        };
        if (flag == "--windows") {
            if (windows_given) throw std::runtime_error("--windows given twice");
            windows_given = true;
            const std::string v = value();
            std::size_t used = 0;
            try {
                a.windows = std::stoi(v, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used != v.size() || a.windows < 1)
                throw std::runtime_error(
                    "--windows needs a whole number of windows, at least 1, not '" + v + "'");
        } else if (flag == "--partition") {
            a.partition = value();
            check_sbatch_value(*a.partition, "--partition");
        } else if (flag == "--time") {
            a.time_limit = value();
            check_sbatch_value(*a.time_limit, "--time");
        } else if (flag == "--farm-dir") {
            a.folder = value();
        } else if (flag == "--contact-sheet") {
            a.contact_sheet = value();
        } else if (flag == "--animation") {
            a.animation = value();
        } else if (flag == "--video") {
            a.video = value();
        } else if (flag == "--submit") {
            a.submit = true;
        } else if (flag == "--stats-json") {
            throw std::runtime_error(
                "--stats-json: each window writes its own (window_I.json in the farm's folder)");
        } else if (flag == "--compare") {
            throw std::runtime_error(
                "--compare renders every frame twice in one run; a farm's tasks render windows");
        } else if (flag == "--window" || flag == "--resume") {
            throw std::runtime_error(flag + " is the farm's to give each task; leave it out");
        } else {
            a.render.push_back(w);
        }
    }
    if (a.windows < 1) throw std::runtime_error("farm needs --windows N");
    return a;
}

namespace {

// The render words checked as `render` would check them, and the scene
// read, so that a mistake shows here and not in N tasks on a cluster.
void check_render_words(const FarmArguments& args, std::string& scene_stem) {
    CLI::App render;
    RenderArguments parsed;
    add_render_arguments(render, parsed);
    std::vector<std::string> words = args.render;
    mark_minus_switches(words);
    std::vector<std::string> reversed(words.rbegin(), words.rend());
    try {
        render.parse(reversed);
    } catch (const CLI::RequiredError&) {
        throw std::runtime_error("farm needs the scene (SCENE.pov [INI ...]) before its flags");
    } catch (const CLI::ParseError& e) {
        throw std::runtime_error(std::string("the render flags: ") + e.what());
    }
    ResolvedScene resolved = resolve(parsed.scene);
    std::vector<std::string> notes;  // (each task's render says them)
    parsed = with_povray_options(parsed, resolved, notes);
    SceneReading reading(resolved, std::cerr);
    const runtime::SceneDescription& scene = reading.scene();
    scene_stem = resolved.scene.stem().string();
    const long long frames = static_cast<long long>(scene.animation.frame_count());
    if (args.windows > frames)
        throw std::runtime_error("--windows " + std::to_string(args.windows) +
                                 ": the animation has " + std::to_string(frames) + " frame" +
                                 (frames == 1 ? "" : "s") + ", so at most that many windows");
    // What each task and the join will be asked, checked once here.
    RenderArguments task = parsed;
    task.window = "0/" + std::to_string(args.windows);
    task.resume = true;
    check_render_plan(task, resolved.scene, scene);
    RenderArguments join = parsed;
    join.resume = true;
    join.contact_sheet = args.contact_sheet;
    join.animation = args.animation;
    join.video = args.video;
    check_render_plan(join, resolved.scene, scene);
}

// A path on an #SBATCH line, in double quotes (sbatch's own quoting).
std::string sbatch_path(const std::string& path) {
    check_word(path, "the path " + path);
    if (path.find_first_of("\"\\") != std::string::npos)
        throw std::runtime_error("the path '" + path +
                                 "' holds a double quote or backslash, which an #SBATCH line "
                                 "cannot hold");
    return "\"" + path + "\"";
}

// Slurm's job name: the scene's name, what sbatch reads plainly.
std::string job_name(const std::string& stem) {
    std::string name = "hexant-";
    for (const char c : stem)
        name += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.'
                    ? c
                    : '_';
    return name;
}

// The #SBATCH lines, then the folder the render words are relative to
// (cd as well: run by hand, the script works from anywhere).
std::string header(const FarmArguments& args, const std::string& name, const std::string& log,
                   const std::string& extra = "") {
    const std::string here = fs::current_path().string();
    std::ostringstream s;
    s << "#!/bin/bash\n"
      << "#SBATCH --job-name=" << name << "\n"
      << "#SBATCH --chdir=" << sbatch_path(here) << "\n"
      << "#SBATCH --output=" << sbatch_path(log) << "\n"
      << extra;
    if (args.partition) s << "#SBATCH --partition=" << *args.partition << "\n";
    if (args.time_limit) s << "#SBATCH --time=" << *args.time_limit << "\n";
    s << "cd " << shell_quote(here) << "\n";
    return s.str();
}

std::string render_line(const FarmArguments& args) {
    std::string line = "exec " + shell_quote(args.hexant) + " render";
    for (const auto& w : args.render) line += " " + shell_quote(w);
    return line;
}

}  // namespace

int run_farm(const FarmArguments& args, std::ostream& out, std::ostream& err) {
    return run_reporting_errors(err, [&] {
        std::string stem;
        check_render_words(args, stem);
        const fs::path folder =
            fs::absolute(args.folder.empty() ? "out/" + stem + "/farm" : args.folder);
        const std::string n = std::to_string(args.windows);

        std::ostringstream array;
        array << header(args, job_name(stem), (folder / "window_%a.log").string(),
                        "#SBATCH --array=0-" + std::to_string(args.windows - 1) + "\n")
              << "# Window $SLURM_ARRAY_TASK_ID of " << n
              << ": its frames, with a hierarchy over its own\n"
              << "# time; --resume lets a requeued or rerun task finish what the last run left.\n"
              << render_line(args) << " --window \"${SLURM_ARRAY_TASK_ID}/" << n
              << "\" --resume --stats-json " << shell_quote((folder / "window_").string())
              << "\"${SLURM_ARRAY_TASK_ID}\"'.json'\n";

        std::ostringstream join;
        join << header(args, job_name(stem) + "-join", (folder / "join.log").string())
             << "# After every window: what needs all the frames (read back; any frame still\n"
             << "# missing is rendered here).\n"
             << "set -e\n"
             << render_line(args).substr(5) << " --resume";  // (not exec: the statistics follow)
        if (args.contact_sheet) join << " --contact-sheet " << shell_quote(*args.contact_sheet);
        if (args.animation) join << " --animation " << shell_quote(*args.animation);
        if (args.video) join << " --video " << shell_quote(*args.video);
        join << "\n# The windows' statistics as one run's.\n"
             << "exec " << shell_quote(args.hexant) << " merge-stats";
        for (int w = 0; w < args.windows; ++w)
            join << " "
                 << shell_quote((folder / ("window_" + std::to_string(w) + ".json")).string());
        join << " -o " << shell_quote((folder / "stats.json").string()) << "\n";

        const fs::path array_path = folder / "array.sbatch", join_path = folder / "join.sbatch";
        const fs::path submit_path = folder / "submit.sh";
        std::ostringstream submit;
        submit << "#!/bin/bash\n"
               << "# The array, then the join once every task of it succeeded.\n"
               << "set -euo pipefail\n"
               << "array=$(sbatch --parsable " << shell_quote(array_path.string()) << ")\n"
               << "array=${array%%;*}\n"
               << "join=$(sbatch --parsable --dependency=afterok:$array "
               << shell_quote(join_path.string()) << ")\n"
               << "echo \"array job $array, join job ${join%%;*}\"\n";
        tracer::write_text_file(array_path, array.str());
        tracer::write_text_file(join_path, join.str());
        tracer::write_text_file(submit_path, submit.str());

        const std::string command = "bash " + shell_quote(submit_path.string());
        if (!args.submit) {
            out << "array: " << array_path.string() << " (" << n
                << " windows)\njoin: " << join_path.string() << "\nsubmit with: " << command
                << "\n";
            return 0;
        }
        std::FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
        if (!pipe) throw std::runtime_error("cannot run " + command);
        std::string said;
        char buffer[512];
        while (std::fgets(buffer, sizeof buffer, pipe)) said += buffer;
        const int status = ::pclose(pipe);
        out << said;
        if (status != 0) {
            err << "hexant: error: submitting failed (" << command << ")\n";
            return 1;
        }
        return 0;
    });
}

}  // namespace hexant::app
