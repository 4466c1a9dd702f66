#include "app/man_page.hpp"

#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

#include "app/version.hpp"

namespace hexant::app {

namespace {

// Text as roff reads it: a backslash is \e, every '-' a minus sign (\-)
// as help2man writes them, so that flags copied from the page work, and a
// line that starts with '.' or '\'' is no request.
std::string roff(const std::string& text) {
    std::string out;
    bool line_start = true;
    for (const char c : text) {
        if (line_start && (c == '.' || c == '\'')) out += "\\&";
        line_start = c == '\n';
        if (c == '\\')
            out += "\\e";
        else if (c == '-')
            out += "\\-";
        else
            out += c;
    }
    return out;
}

// One paragraph of prose: CLI11's descriptions may break lines where
// --help wraps; roff fills them again.
void paragraph(std::ostream& out, const std::string& text) {
    if (text.empty()) return;
    out << ".PP\n" << roff(text) << "\n";
}

// "-W, --width" (bold) and its value's label (italic), as --help shows them.
std::string option_heading(const CLI::Option& option) {
    std::string heading;
    auto add = [&](const std::string& name) {
        heading += (heading.empty() ? "" : ", ") + ("\\fB" + roff(name) + "\\fR");
    };
    if (option.get_positional() && option.get_snames().empty() && option.get_lnames().empty()) {
        heading = "\\fI" + roff(option.get_name(true, false)) + "\\fR";
    } else {
        for (const auto& name : option.get_snames()) add("-" + name);
        for (const auto& name : option.get_lnames()) add("--" + name);
    }
    if (!option.get_option_text().empty()) {
        heading += " " + roff(option.get_option_text());
    } else if (option.get_type_size() != 0 && !option.get_positional()) {
        if (!option.get_type_name().empty())
            heading += " \\fI" + roff(option.get_type_name()) + "\\fR";
        if (!option.get_default_str().empty())
            heading += " (default " + roff(option.get_default_str()) + ")";
    }
    if (option.get_positional() && option.get_expected_max() > 1) heading += " ...";
    if (option.get_required()) heading += " (required)";
    return heading;
}

void options(std::ostream& out, const CLI::App& command, bool with_help) {
    const CLI::Option* help = command.get_help_ptr();
    std::vector<std::string> groups;
    for (const CLI::Option* option : command.get_options())
        if (!option->get_group().empty() &&
            std::find(groups.begin(), groups.end(), option->get_group()) == groups.end())
            groups.push_back(option->get_group());
    // Positionals first, then each group of flags in order, as --help.
    for (const bool positional : {true, false}) {
        for (const std::string& group : groups) {
            bool titled = positional || group == "Options";
            for (const CLI::Option* option : command.get_options()) {
                if (option->get_group() != group || option->get_positional() != positional)
                    continue;
                if (option == help && !with_help) continue;
                if (!titled) {
                    out << ".PP\n\\fB" << roff(group) << "\\fR\n";
                    titled = true;
                }
                out << ".TP\n" << option_heading(*option) << "\n";
                out << roff(option->get_description().empty() ? "(no description)"
                                                              : option->get_description())
                    << "\n";
            }
        }
    }
}

std::vector<const CLI::App*> visible_subcommands(const CLI::App& command) {
    return command.get_subcommands([](const CLI::App* sub) { return !sub->get_group().empty(); });
}

// A subcommand's section, then its own subcommands' (bench error-time).
void subcommand(std::ostream& out, const CLI::App& command, const std::string& path) {
    const std::vector<const CLI::App*> subs = visible_subcommands(command);
    out << ".SS \"" << roff(path) << "\"\n";
    paragraph(out, command.get_description());
    std::string usage = "\\fB" + roff(path) + "\\fR";
    for (const CLI::Option* option : command.get_options())
        if (option->get_positional() && !option->get_group().empty())
            usage += " \\fI" + roff(option->get_name(true, false)) + "\\fR" +
                     (option->get_expected_max() > 1 ? " ..." : "");
    if (!subs.empty()) usage += " \\fISUBCOMMAND\\fR";
    usage += " [\\fIflags\\fR]";
    out << ".PP\n" << usage << "\n";
    options(out, command, false);
    if (!command.get_footer().empty()) {
        out << ".PP\n.nf\n" << roff(command.get_footer()) << "\n.fi\n";
    }
    for (const CLI::App* sub : subs) subcommand(out, *sub, path + " " + sub->get_name());
}

}  // namespace

void write_man_page(const CLI::App& program, std::ostream& out) {
    const std::vector<const CLI::App*> subs = visible_subcommands(program);
    // No date: the page is the same at every build of one version.
    out << ".\\\" Made by `hexant man-page` from the program's own help (app/man_page.cpp).\n"
        << ".TH HEXANT 1 \"\" \"" << roff(version_text())
        << "\" \"User Commands\"\n"
        // Flags are not hyphenated at line ends, nor lines stretched.
        << ".nh\n.ad l\n"
        << ".SH NAME\n"
        << "hexant \\- spacetime ray tracing of POV\\-Ray\\-style animated scenes\n"
        << ".SH SYNOPSIS\n";
    std::string names;
    for (const CLI::App* sub : subs) names += (names.empty() ? "" : "|") + roff(sub->get_name());
    out << "\\fBhexant\\fR " << names
        << " \\fISCENE.pov\\fR [\\fIFILE.ini\\fR ...] [\\fIPOV\\-Ray switches\\fR] "
           "[\\fIflags\\fR]\n.br\n"
        << "\\fBhexant\\fR \\fISCENE.pov\\fR|\\fISCENE.ini\\fR [...]\n.br\n"
        << "\\fBhexant \\-\\-version\\fR | \\fB\\-\\-help\\fR\n"
        << ".SH DESCRIPTION\n";
    paragraph(out, program.get_description());
    paragraph(out,
              "hexant renders animations written in a subset of POV-Ray 3.7's scene language "
              "with Andrew Glassner's spacetime ray tracing: the whole animation is one static "
              "object in 4D spacetime, and every ray carries its own time, so motion blur, "
              "moving shadows and a moving camera come out of the same tracer.");
    paragraph(out,
              "POV-Ray .ini files, POV-Ray 3.7's switches (+W640 +KFF60 -D) and its Key=Value "
              "options apply in the order written, as in POV-Ray; then hexant's flags override "
              "them. A first word that is a scene, an .ini file or a POV-Ray switch means "
              "render, as povray is called. Each subcommand's --help lists its flags, as below.");
    out << ".SH OPTIONS\n";
    options(out, program, true);
    out << ".SH SUBCOMMANDS\n";
    for (const CLI::App* sub : subs) subcommand(out, *sub, "hexant " + sub->get_name());
    out << ".SH FILES\n"
        << ".TP\n\\fI../share/hexant/include/\\fR (beside the executable's folder)\n"
        << "The include files that ship with hexant (colors.inc), searched after the scene's "
           "folder and each \\fB\\-L\\fR folder.\n"
        << ".TP\n\\fI/usr/share/povray\\-3.7/include/\\fR\n"
        << "POV\\-Ray's own include files (Debian's povray\\-includes), searched last, as "
           "povray's Library_Path.\n"
        << ".TP\n\\fI/usr/share/fonts/truetype/povray/\\fR\n"
        << "POV\\-Ray's fonts for text objects (Debian's fonts\\-povray).\n"
        << ".SH EXIT STATUS\n"
        << "0 on success; non\-zero when a scene, a file or a flag is wrong, with a message "
           "naming the place on standard error.\n"
        << ".SH SEE ALSO\n"
        << ".BR povray (1).\n"
        << "The manual: README.md in hexant's documentation folder (/usr/share/doc/hexant "
           "from the Debian package).\n";
}

}  // namespace hexant::app
