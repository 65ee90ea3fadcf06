// run_cli: one CLI11 app with a subcommand per command (commands.hpp explains the pattern).
#include "fdh/cli/cli.hpp"

#include <new>
#include <optional>

#include "commands.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/help/help_layout.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/os/standard_output.hpp"
#include "fdh/plugin/loader.hpp"
#include "suite_commands.hpp"

namespace fdh::verify {
namespace {

const char* const kAbout = "fdhcert: exact verification of FDH (k-DOP) cloth collision detection";
const char* const kFooter =
    "Run 'fdhcert <command> --help' for the options of a command.\n"
    "Exit status: 0 success, 1 a check or certificate failed, 2 bad input or usage,\n"
    "a bound passed, or an output (standard output included) that could not be\n"
    "written; every output path is checked before a run starts (docs/limits.md);\n"
    "3 a --plugin crashed, called exit() or answered garbage, or hung past\n"
    "--plugin-timeout where no promise check counts it (certify does: a broken\n"
    "promise; docs/plugins.md), or an internal error; 128+N killed by signal N\n"
    "(this run's temporary files removed first).";

std::vector<Command> add_commands(CLI::App& app) {
  return {add_classify(app), add_fuzz(app),   add_replay(app),   add_generate(app),
          add_certify(app),  add_report(app), add_simulate(app), add_audit(app),
          add_table1(app),   add_scenes(app), add_peers(app)};
}

std::string main_help(const CLI::App& app) {
  return app.get_formatter()->make_help(&app, "fdhcert", CLI::AppFormatMode::Normal);
}

// "fdhcert help" prints the main help, "fdhcert help COMMAND" that command's.
std::string help_text(const CLI::App& app, const std::vector<std::string>& topic) {
  for (const CLI::App* sub : app.get_subcommands({}))
    if (!topic.empty() && sub->get_name() == topic.front() && sub->get_group() != "")
      return sub->get_formatter()->make_help(sub, "fdhcert " + sub->get_name(),
                                             CLI::AppFormatMode::Normal);
  return main_help(app);
}

// A parse error in words: CLI11's, and where to read more.
std::string usage_message(const CLI::App& app, const CLI::ParseError& e,
                          const std::vector<std::string>& args) {
  const std::vector<CLI::App*> chosen = app.get_subcommands();
  if (chosen.empty() && !args.front().empty() && args.front()[0] != '-')
    return "unknown command " + quoted_input(args.front()) + " (see fdhcert --help)";
  const std::string see = chosen.empty() ? "fdhcert" : "fdhcert " + chosen.front()->get_name();
  // CLI11's words may hold the value whole: control bytes escaped, at most about 240 bytes.
  std::string what = quoted_input(e.what(), 240);
  what = what.substr(1, what.rfind('\'') - 1) + what.substr(what.rfind('\'') + 1);
  return what + " (see " + see + " --help)";
}

// Parses; the help and parse errors print here. Returns the exit status if that ended the run.
std::optional<int> parse(CLI::App& app, const std::vector<std::string>& args, const Io& io) {
  try {
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 pops from the back
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    io.out << app.help();  // the help of the command named, if any
    return 0;
  } catch (const CLI::CallForVersion& e) {
    io.out << e.what() << "\n";
    return 0;
  } catch (const CLI::ParseError& e) {
    io.err << "fdhcert: " << usage_message(app, e, args) << "\n";
    return 2;
  }
  if (app.got_subcommand("help")) {
    io.out << help_text(app, app.get_subcommand("help")->remaining());
    return 0;
  }
  return std::nullopt;
}

int run_command(const std::vector<Command>& commands, const Io& io) {
  for (const Command& c : commands)
    if (c.app->parsed()) return c.run(io);
  return 2;  // unreachable: CLI11 requires one command
}

}  // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  mark_run_start();  // --budget counts from here
  CLI::App app(kAbout, "fdhcert");
  app.formatter(help_layout());
  app.get_formatter()->column_width(24);
  app.require_subcommand(1);
  app.set_version_flag("--version", "fdhcert " FDH_VERSION, "print the version and exit");
  app.footer(kFooter);
  app.add_subcommand("help", "this text")->group("")->allow_extras();  // hidden
  const PluginScope plugins;  // --plugin's methods, for this run only
  const std::vector<Command> commands = add_commands(app);
  const Io io{out, err};
  if (args.empty()) {
    err << main_help(app);
    return 2;
  }
  try {
    if (const std::optional<int> status = parse(app, args, io))
      return checked_output(*status, out, err);
    probe_plugins(run_budget());  // --plugin's, within --budget wherever it was given
    return checked_output(run_command(commands, io), out, err);
  } catch (const UsageError& e) {
    err << "fdhcert: " << e.what() << "\n";
  } catch (const InputError& e) {
    err << "fdhcert: error: " << e.what() << "\n";
  } catch (const PluginFailure& e) {  // a plug-in crashed when probed, or answered garbage
    err << "fdhcert: " << e.what() << "\n";
    return kPluginFailureStatus;
  } catch (const NoAnswer& e) {  // a hang where no promise check counts it (classify, fuzz)
    err << "fdhcert: " << e.what() << "\n";
    return kPluginFailureStatus;
  } catch (const std::runtime_error& e) {  // I/O failures while writing output
    err << "fdhcert: error: " << e.what() << "\n";
  } catch (const std::bad_alloc&) {  // an error, not an abort (docs/limits.md)
    err << "fdhcert: error: out of memory (docs/limits.md)\n";
  } catch (const std::length_error& e) {
    err << "fdhcert: error: out of memory: " << e.what() << "\n";
  }
  return 2;
}

}  // namespace fdh::verify
