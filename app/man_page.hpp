// hexant's manual page, hexant(1), written in roff from the same CLI11
// tables that print --help: every subcommand's description, usage, flags
// and footer, so the page cannot fall behind the program. The build runs
// the hidden `hexant man-page` to make build/hexant.1 (app/CMakeLists.txt).
#pragma once

#include <iosfwd>

#include <CLI/CLI.hpp>

namespace hexant::app {

// Writes the whole page for `program` (the top-level App with its
// subcommands; hidden ones, whose group is empty, are left out).
void write_man_page(const CLI::App& program, std::ostream& out);

}  // namespace hexant::app
