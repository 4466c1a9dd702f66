// `hexant farm`: an animation as a Slurm job array of time windows. It
// writes two batch scripts and the line that submits them: the array, one
// task per window (`render ... --window $SLURM_ARRAY_TASK_ID/N --resume`,
// the render flags passed through as written), and a join that runs when
// every task succeeded (`--dependency=afterok`) and writes what needs all
// the frames (`render ... --resume` with the contact sheet, GIF and video:
// it reads the frames back, and renders any still missing). Slurm does the
// scheduling, retries and accounting; hexant writes no scheduler.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace hexant::app {

struct FarmArguments {
    // The scene, .ini files and render flags as written after `farm`, less
    // the farm's own flags (split_farm_arguments).
    std::vector<std::string> render;
    int windows = 0;
    std::optional<std::string> partition, time_limit;
    // Outputs that need every frame: the join's.
    std::optional<std::string> contact_sheet, animation, video;
    std::string folder;  // where the scripts go (default out/SCENE/farm)
    bool submit = false;
    std::string hexant;  // the hexant binary the scripts run (absolute)
};

// Splits the words after `farm` into the farm's flags (--windows N,
// --partition P, --time T, --submit, --farm-dir D, --contact-sheet F,
// --animation F, --video F, each as `--flag value` or `--flag=value`) and the render
// words, kept in order. std::runtime_error naming a flag without its value,
// a bad --windows, or --window/--resume given by hand.
FarmArguments split_farm_arguments(const std::vector<std::string>& words);

// Writes the array and join scripts and submit.sh into args.folder; with
// args.submit runs submit.sh (sbatch) and prints the job ids, else prints
// the scripts' paths and the command. Returns the exit status.
int run_farm(const FarmArguments& args, std::ostream& out, std::ostream& err);

// A word quoted for bash (single quotes), as the scripts hold it.
std::string shell_quote(const std::string& word);

}  // namespace hexant::app
