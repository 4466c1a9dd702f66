#include "app/farm_command.hpp"

#include <cstdio>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "app/command_line.hpp"
#include "app/render_command.hpp"
#include "language/interpreter.hpp"
#include "tracer/whole_file.hpp"

namespace hexant::app {

namespace fs = std::filesystem;

std::string shell_quote(const std::string& word) {
    std::string quoted = "'";
    for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

FarmArguments split_farm_arguments(const std::vector<std::string>& words) {
    FarmArguments a;
    for (std::size_t i = 0; i < words.size(); ++i) {
        const std::string& w = words[i];
        const auto eq = w.find('=');
        const std::string flag = w.rfind("--", 0) == 0 ? w.substr(0, eq) : w;
        const auto value = [&]() -> std::string {
            if (eq != std::string::npos) return w.substr(eq + 1);
            if (i + 1 >= words.size()) throw std::runtime_error(flag + " needs a value");
            return words[++i];
        };
        if (flag == "--windows") {
            const std::string v = value();
            std::size_t used = 0;
            try {
                a.windows = std::stoi(v, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used != v.size() || a.windows < 1)
                throw std::runtime_error("--windows needs a whole number of windows, at least 1, not '" + v + "'");
        } else if (flag == "--partition") {
            a.partition = value();
        } else if (flag == "--time") {
            a.time_limit = value();
        } else if (flag == "--farm-dir") {
            a.folder = value();
        } else if (flag == "--contact-sheet") {
            a.contact_sheet = value();
        } else if (flag == "--animation") {
            a.animation = value();
        } else if (flag == "--submit") {
            a.submit = true;
        } else if (flag == "--stats-json") {
            throw std::runtime_error("--stats-json: each window writes its own (window_I.json in the farm's folder)");
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
    std::vector<std::string> reversed(args.render.rbegin(), args.render.rend());
    try {
        render.parse(reversed);
    } catch (const CLI::ParseError& e) {
        throw std::runtime_error(std::string("the render flags: ") + e.what());
    }
    ResolvedScene resolved = resolve(parsed.scene);
    language::parse_scene_file(resolved.scene, resolved.options);
    scene_stem = resolved.scene.stem().string();
}

std::string header(const FarmArguments& args, const std::string& name, const std::string& log) {
    std::ostringstream s;
    s << "#!/bin/bash\n"
      << "#SBATCH --job-name=" << name << "\n"
      << "#SBATCH --chdir=" << fs::current_path().string() << "\n"
      << "#SBATCH --output=" << log << "\n";
    if (args.partition) s << "#SBATCH --partition=" << *args.partition << "\n";
    if (args.time_limit) s << "#SBATCH --time=" << *args.time_limit << "\n";
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
        const fs::path folder = fs::absolute(args.folder.empty() ? "out/" + stem + "/farm" : args.folder);
        const std::string n = std::to_string(args.windows);

        std::ostringstream array;
        array << header(args, "hexant-" + stem, (folder / "window_%a.log").string())
              << "#SBATCH --array=0-" << args.windows - 1 << "\n"
              << "# Window $SLURM_ARRAY_TASK_ID of " << n << ": its frames, with a hierarchy over its own\n"
              << "# time; --resume lets a requeued or rerun task finish what the last run left.\n"
              << render_line(args) << " --window \"${SLURM_ARRAY_TASK_ID}/" << n << "\" --resume --stats-json "
              << shell_quote((folder / "window_").string()) << "\"${SLURM_ARRAY_TASK_ID}\"'.json'\n";

        std::ostringstream join;
        join << header(args, "hexant-" + stem + "-join", (folder / "join.log").string())
             << "# After every window: what needs all the frames (read back; any frame still\n"
             << "# missing is rendered here).\n"
             << "set -e\n"
             << render_line(args).substr(5) << " --resume";  // (not exec: the statistics follow)
        if (args.contact_sheet) join << " --contact-sheet " << shell_quote(*args.contact_sheet);
        if (args.animation) join << " --animation " << shell_quote(*args.animation);
        join << "\n# The windows' statistics as one run's.\n"
             << "exec " << shell_quote(args.hexant) << " merge-stats";
        for (int w = 0; w < args.windows; ++w)
            join << " " << shell_quote((folder / ("window_" + std::to_string(w) + ".json")).string());
        join << " -o " << shell_quote((folder / "stats.json").string()) << "\n";

        const fs::path array_path = folder / "array.sbatch", join_path = folder / "join.sbatch";
        const fs::path submit_path = folder / "submit.sh";
        std::ostringstream submit;
        submit << "#!/bin/bash\n"
               << "# The array, then the join once every task of it succeeded.\n"
               << "set -euo pipefail\n"
               << "array=$(sbatch --parsable " << shell_quote(array_path.string()) << ")\n"
               << "array=${array%%;*}\n"
               << "join=$(sbatch --parsable --dependency=afterok:$array " << shell_quote(join_path.string())
               << ")\n"
               << "echo \"array job $array, join job ${join%%;*}\"\n";
        tracer::write_text_file(array_path, array.str());
        tracer::write_text_file(join_path, join.str());
        tracer::write_text_file(submit_path, submit.str());

        const std::string command = "bash " + shell_quote(submit_path.string());
        if (!args.submit) {
            out << "array: " << array_path.string() << " (" << n << " windows)\njoin: " << join_path.string()
                << "\nsubmit with: " << command << "\n";
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
