#include "fdh/cli/cli.hpp"

#include "commands.hpp"
#include "fdh/io/input_error.hpp"

namespace fdh::verify {
namespace {

const char* const kMainHelp =
    R"(fdhcert: exact verification of FDH (k-DOP) cloth collision detection

usage: fdhcert <command> [options]

commands:
  classify FILE...   run the point-triangle methods side by side on query files
  fuzz               search a generator family for cases where a method is wrong,
                     shrink them and store them
  replay PATH...     re-run stored cases: which methods still fail where
  generate FAMILY    write queries of a generator family to a file
  certify            certify the fast library against the exact reference
  report             certificate, measurements and charts in one folder
  simulate SCENE     run a cloth scene: time per frame, accuracy and exact audit
  table1             the paper's Table 1 on today's machine, accuracy beside speed

Run 'fdhcert <command> --help' for the options of a command.
Exit status: 0 success, 1 a check or certificate failed, 2 bad input or usage.
)";

}  // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  try {
    if (args.empty()) {
      err << kMainHelp;
      return 2;
    }
    const std::string& cmd = args[0];
    const Args rest(args.begin() + 1, args.end());
    if (cmd == "-h" || cmd == "--help" || cmd == "help") {
      out << kMainHelp;
      return 0;
    }
    if (cmd == "classify") return classify_command(rest, out, err);
    if (cmd == "fuzz") return fuzz_command(rest, out, err);
    if (cmd == "replay") return replay_command(rest, out, err);
    if (cmd == "generate") return generate_command(rest, out, err);
    if (cmd == "certify") return certify_command(rest, out, err);
    if (cmd == "report") return report_command(rest, out, err);
    if (cmd == "simulate") return simulate_command(rest, out, err);
    if (cmd == "table1") return table1_command(rest, out, err);
    throw UsageError("unknown command '" + cmd + "' (see fdhcert --help)");
  } catch (const UsageError& e) {
    err << "fdhcert: " << e.what() << "\n";
    return 2;
  } catch (const InputError& e) {
    err << "fdhcert: error: " << e.what() << "\n";
    return 2;
  } catch (const std::runtime_error& e) {  // I/O failures while writing output
    err << "fdhcert: error: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace fdh::verify
