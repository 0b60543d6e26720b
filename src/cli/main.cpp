// build/rollkin: the command-line tool (the reference of every command: docs/cli.md).
//
//   rollkin solve SCENE [--from V --to V --step V] [--csv FILE] [--plot FILE.svg] [--draw FILE.svg]
//                       [--animate FILE.html] [--rates] [--analysis] [--verbose] [--interference] [--max-steps N]
//   rollkin reference SCENE [--from V --to V --step V] [--digits 30|50|100] [--max-steps N] --csv FILE
//   rollkin centrodes SCENE --links A B [--from V --to V --step V] [--max-steps N] --out PREFIX
//   rollkin check SCENE [--from V --to V --step V] [--max-steps N]
//   rollkin contours FILE [--draw OUT.svg] [--json]          (FILE: a format of io/contour_formats.hpp)
//   rollkin synthesize cam SPEC.json --out PREFIX
//   rollkin --help | --version;  rollkin COMMAND --help
//
// Exit codes: 0 every requested input value solved; 1 some were not (a limit met, assembly failed, a singular
// pose): one line per limit or singular pose on stderr, the solved rows still written; 2 bad input (scene file, contour files, command line,
// an output that would overwrite an input, an output that cannot be written): the message on stderr and no
// output file written; 3 out of memory ("out of memory while ..."), no output file written; 4 internal error (a
// file rollkin wrote that its own reader refuses), no output file written. Outputs are all or nothing
// (rollkin/io/output_set.hpp), and no temporary outlives a SIGINT or SIGTERM (rollkin/io/temporary_file.hpp).
//
// --animate writes one self-contained HTML page (inline SVG and script, no external file) that plays the
// solved poses: a play/pause button, a slider over the poses, the input value and each pose's status
// (include/rollkin/output/animation.hpp).
//
// The command line is parsed by CLI11. Each command is one file src/cli/command_<name>.cpp: its options struct,
// the function that declares its options (descriptions are the --help text) and the function that runs it;
// what they share is in commands.hpp. main() lists the commands. A new command is one more such file, its
// declaration in commands.hpp and one line in main().
#include "commands.hpp"

#include "rollkin/io/temporary_file.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#ifndef ROLLKIN_VERSION
#define ROLLKIN_VERSION "0.1.0"
#endif

namespace rollkin::cli {
namespace {

// ---- main: the commands --------------------------------------------------------------------------------

/// CLI11's "The following argument was not expected: X" in rollkin's words: what X was taken for and what
/// was expected. The arguments are named in command-line order.
/// The deepest subcommand given ("cam" of "rollkin synthesize cam"), or `command` itself.
const CLI::App* innermost(const CLI::App* command) {
  while (command) {
    const std::vector<const CLI::App*> given = command->get_subcommands([](const CLI::App* sub) { return sub->parsed(); });
    if (given.empty()) break;
    command = given.front();
  }
  return command;
}

/// "synthesize cam": the names from the command below `rollkin` down to `command`.
std::string command_path(const CLI::App* command) {
  std::string path;
  for (const CLI::App* c = command; c && c->get_parent(); c = c->get_parent())
    path = c->get_name() + (path.empty() ? "" : " " + path);
  return path;
}

/// The names of a command's own subcommands ("cam, gears, envelope"), empty when it has none.
std::string subcommand_names(const CLI::App* command) {
  std::string names;
  for (const CLI::App* sub : command->get_subcommands([](const CLI::App*) { return true; }))
    names += (names.empty() ? "" : ", ") + sub->get_name();
  return names;
}

/// Ends the --help of every command below `command` with the section of docs/cli.md that is its reference,
/// "rollkin synthesize cam" for `rollkin synthesize cam` (tests/repo/doc_references.py checks they exist).
void add_reference_lines(CLI::App& command) {
  for (CLI::App* sub : command.get_subcommands([](CLI::App*) { return true; })) {
    sub->footer(sub->get_footer() + "\nReference: docs/cli.md, \"rollkin " + command_path(sub) + "\".");
    add_reference_lines(*sub);
  }
}

std::string unexpected_argument(const CLI::App& rollkin, const CLI::App* command, int argc, char** argv) {
  command = innermost(command);
  const std::vector<std::string> extras = rollkin.remaining(true);
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (std::find(extras.begin(), extras.end(), a) == extras.end()) continue;
    if (a.size() > 1 && a[0] == '-' && !finite_number(a)) {
      if (!command) return "unknown option \"" + a + "\"; expected a command first";
      std::string names;
      for (const CLI::Option* opt : command->get_options())
        if (!opt->get_positional() && opt != command->get_help_ptr()) names += (names.empty() ? "" : ", ") + opt->get_name();
      return "unknown option \"" + a + "\" for " + command_path(command) + "; expected one of " + names;
    }
    if (!command) return "unknown command \"" + a + "\"";
    const std::string subcommands = subcommand_names(command);
    if (!subcommands.empty())
      return "unknown " + command_path(command) + " command \"" + a + "\"; expected one of " + subcommands;
    return "unexpected argument \"" + a + "\": " + command->get_name() + " takes one SCENE file";
  }
  return {};
}

/// "rollkin: <what is wrong>" and where to read what is expected; exit status 2.
int usage_error(const std::string& what, const CLI::App* command, const std::vector<Command>& commands) {
  std::cerr << "rollkin: " << what << "\n";
  if (command) {
    std::cerr << "(rollkin " << command_path(innermost(command)) << " --help lists its options)\n";
  } else {
    std::string names;
    for (const Command& c : commands) names += (names.empty() ? "" : ", ") + c.app->get_name();
    std::cerr << "(expected a command: " << names << "; rollkin --help for usage)\n";
  }
  return 2;
}

}  // namespace
}  // namespace rollkin::cli

int main(int argc, char** argv) {
  using namespace rollkin::cli;
  // SIGINT, SIGTERM, SIGHUP, SIGQUIT: no temporary outlives the process (docs/reliability.md, "Outputs,
  // signals and messages (issue 37)").
  rollkin::io::install_signal_cleanup();
  CLI::App rollkin("rollkin: kinematic analysis of planar mechanisms with rolling pairs", "rollkin");
  rollkin.set_version_flag("--version", "rollkin " ROLLKIN_VERSION);
  rollkin.get_formatter()->column_width(24);
  rollkin.footer("Run 'rollkin COMMAND --help' for the options of a command, e.g. 'rollkin solve --help'; the\n"
                 "reference of every command: docs/cli.md.\n" + std::string(kExitStatus));
  const std::vector<Command> commands{solve_command(rollkin), reference_command(rollkin), centrodes_command(rollkin),
                                      check_command(rollkin), contours_command(rollkin),
                                      synthesize_command(rollkin)};
  add_reference_lines(rollkin);
  const CLI::App* chosen = nullptr;
  try {
    try {
      rollkin.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return rollkin.exit(e);  // --help, --version
      const std::vector<CLI::App*> given = rollkin.get_subcommands();
      const CLI::App* command = given.empty() ? nullptr : given.front();
      const std::string unexpected = dynamic_cast<const CLI::ExtrasError*>(&e) ? unexpected_argument(rollkin, command, argc, argv) : "";
      return usage_error(unexpected.empty() ? e.what() : unexpected, command, commands);
    }
    for (const Command& c : commands)
      if (c.app->parsed()) {
        chosen = c.app;
        return c.run();
      }
    return usage_error("missing command", nullptr, commands);
  } catch (const UsageError& e) {
    return usage_error(e.what(), chosen, commands);
  } catch (...) {
    return error_status(std::cerr);
  }
}
