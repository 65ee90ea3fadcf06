// fdhcert replay: re-run stored cases; exact must still give each stored truth.
#include <map>

#include "commands.hpp"
#include "fdh/io/case_files.hpp"
#include "fdh/check/classify.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/json.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/io/query_io.hpp"

namespace fdh::verify {
namespace {

const char* const kReplayHelp = R"(usage: fdhcert replay PATH... [--methods LIST] [--json]

Re-runs stored cases (native query files; a folder means every *.vf below it,
such as corpus/ or a fuzz --out folder). Every case must carry a truth.

  exact must still give each case's stored truth: if it does not, replay names
  the case and exits with status 1.
  For every other method it reports which cases it still gets wrong.

  --methods LIST   comma-separated methods (default: all)
  --json           {"cases": N, "exact_mismatches": [...],
                    "methods": {"<name>": {"failing": K, "cases": [...]}}}
  -h, --help       this text
)";

}  // namespace

int replay_command(const Args& args, std::ostream& out, std::ostream& err) {
  std::vector<std::string> paths, names;
  bool json = false;
  for (ArgReader a(args); a.next();) {
    if (a.is("-h") || a.is("--help")) {
      out << kReplayHelp;
      return 0;
    } else if (a.is("--methods")) {
      names = split_list(a.value());
    } else if (a.is("--json")) {
      json = true;
    } else if (a.is_option()) {
      a.unknown("replay");
    } else {
      paths.push_back(a.word());
    }
  }
  if (paths.empty()) throw UsageError("replay needs at least one file or folder");
  const std::vector<Method> methods = methods_named(names);

  std::vector<Query> cases;
  std::size_t skipped = 0;
  for (const std::string& p : paths)
    for (const std::string& f : list_query_files(p))
      for (Query& q : read_native(f)) {
        if (!q.has_truth()) throw InputError(q.file, q.line, "a stored case needs a truth");
        if (q.is_static_vf())
          cases.push_back(std::move(q));
        else
          ++skipped;
      }
  if (skipped) err << "fdhcert: note: skipped " << skipped << " moving or edge-edge cases\n";
  if (cases.empty()) throw InputError(paths.front(), 0, "no stored static vertex-face case");

  const Classification c = classify(cases, methods);
  const auto where = [&](std::size_t i) {
    return cases[i].file + ":" + std::to_string(cases[i].line);
  };
  std::map<std::string, std::vector<std::string>> failing;
  for (const MethodResult& m : c.methods) {
    std::vector<std::string>& list = failing[m.name];
    for (std::size_t i = 0; i < cases.size(); ++i)
      if (m.verdict[i] != kNotApplicable && m.verdict[i] != c.reference[i])
        list.push_back(where(i));
  }

  if (json) {
    out << "{\"cases\": " << cases.size() << ", \"exact_mismatches\": [";
    for (std::size_t k = 0; k < c.exact_vs_file.size(); ++k)
      out << (k ? ", " : "") << json_string(where(c.exact_vs_file[k]));
    out << "], \"methods\": {";
    bool first = true;
    for (const MethodResult& m : c.methods) {
      const auto& list = failing[m.name];
      out << (first ? "" : ", ") << '"' << m.name << "\": {\"failing\": " << list.size()
          << ", \"cases\": [";
      for (std::size_t k = 0; k < list.size(); ++k) out << (k ? ", " : "") << json_string(list[k]);
      out << "]}";
      first = false;
    }
    out << "}}\n";
  } else {
    out << "replayed " << cases.size() << " cases; exact "
        << (c.exact_vs_file.empty()
                ? "gives every stored truth"
                : "DISAGREES with " + std::to_string(c.exact_vs_file.size()) + " stored truths")
        << "\n";
    for (const MethodResult& m : c.methods) {
      const auto& list = failing[m.name];
      out << "  " << m.name << ": " << list.size() << " failing\n";
      for (const std::string& w : list) out << "    " << w << "\n";
    }
  }
  for (const std::size_t i : c.exact_vs_file)
    err << "fdhcert: exact no longer gives the stored truth at " << where(i) << "\n";
  return c.exact_vs_file.empty() ? 0 : 1;
}

}  // namespace fdh::verify
