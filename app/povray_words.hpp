// POV-Ray's words on hexant's command line. A POV-Ray user types
//   povray +Iscene.pov +W640 +H480 -D res.ini Declare=Speed=2
// and hexant takes the same words after `render`, or with no subcommand at
// all. Words beginning with + and `Key=Value` words reach a subcommand's
// positionals as they are (app/command_line.cpp reads them in order with
// the .ini files); a switch beginning with - (-D, -KC, -A) would be taken
// for a flag of hexant's, so it is marked before CLI11 reads the line.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace hexant::app {

// The words after the program's name, as the subcommands are to read them:
// `render` put first when the first word is a scene (.pov), an .ini file,
// a POV-Ray switch or a POV-Ray `Key=Value` option (`hexant scene.pov
// +W64` is `hexant render scene.pov +W64`), and the POV-Ray switches
// beginning with - after check, dump, render or bench error-time marked
// (mark_minus_switches).
std::vector<std::string> command_line_words(int argc, const char* const* argv);

// Marks each word that is a POV-Ray 3.7 switch beginning with - (-D, -KC,
// -A0.3, -WT2, -w640) so that CLI11 takes it as a positional. hexant's own
// short flags keep their meaning: -W and -H with a number or none (the
// number then follows), -L, -o and -h; they mean what POV-Ray's do, but
// apply after every .ini file and switch, as hexant's flags do.
void mark_minus_switches(std::vector<std::string>& words);

// The switch ("-KC") a marked word is; none for any other word.
std::optional<std::string> minus_switch(const std::string& word);

}  // namespace hexant::app
