#include "fdh/certify/corpus_folder.hpp"

#include <filesystem>
#include <system_error>

#include "fdh/io/usage_error.hpp"

// The installed corpus relative to the installed program (cmake/install.cmake sets it from
// GNUInstallDirs' BINDIR and DATADIR).
#ifndef FDH_CORPUS_FROM_BINDIR
#define FDH_CORPUS_FROM_BINDIR "../share/fdhcert/corpus"
#endif

namespace fdh::verify {
namespace fs = std::filesystem;

namespace {

bool is_corpus_folder(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

// The corpus beside the running program (Linux: /proc/self/exe, the program's real path).
fs::path installed_corpus() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  return fs::weakly_canonical(exe.parent_path() / FDH_CORPUS_FROM_BINDIR, ec);
}

}  // namespace

std::string corpus_or_default(const std::string& given) {
  if (!given.empty()) return given;
  if (is_corpus_folder("corpus")) return "corpus";
  const fs::path installed = installed_corpus();
  if (!installed.empty() && is_corpus_folder(installed)) return installed.string();
  throw UsageError("no corpus folder: looked for ./corpus (a source checkout) and " +
                   (installed.empty() ? std::string("the installed one (program path unknown)")
                                      : installed.string() + " (installed with fdhcert)") +
                   "; give --corpus DIR");
}

}  // namespace fdh::verify
