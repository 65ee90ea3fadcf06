#include "fdh/io/charts.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "fdh/os/atomic_file.hpp"
#include "fdh/os/child_process.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

// A script file with no name: mkstemp in the temporary folder, unlinked at once (so that a
// killed fdhcert leaves nothing there), written whole, and read by gnuplot, which inherits the
// descriptor, as /dev/fd/N.
class ScriptFile {
 public:
  explicit ScriptFile(const std::string& text) {
    std::string pattern = (fs::temp_directory_path() / "fdhcert-chart-XXXXXX").string();
    fd_ = ::mkstemp(pattern.data());
    if (fd_ < 0) throw std::runtime_error("cannot create a gnuplot script: " + errno_text());
    ::unlink(pattern.c_str());
    path_ = "/dev/fd/" + std::to_string(fd_);
    if (!write_all(fd_, text)) {
      const std::string why = errno_text();
      ::close(fd_);
      throw std::runtime_error("cannot write the gnuplot script " + pattern + ": " + why);
    }
  }
  ~ScriptFile() { ::close(fd_); }
  ScriptFile(const ScriptFile&) = delete;
  ScriptFile& operator=(const ScriptFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  static std::string errno_text() { return std::strerror(errno); }
  int fd_;
  std::string path_;
};

// The folder of a chart and its file name.
std::pair<std::string, std::string> split_stem(const std::string& stem) {
  const fs::path p(stem);
  const std::string dir = p.parent_path().empty() ? "." : p.parent_path().string();
  return {dir, p.filename().string()};
}

// Runs gnuplot SCRIPT in folder DIR (so that the folder's name never enters a script), its
// standard output sent to standard error. The child is an argument list (fork and execvp, no
// shell) and is killed when fdhcert dies (fdh/os/child_process.hpp). Throws unless it exits with 0.
void run_gnuplot(const std::string& script, const std::string& dir, const std::string& what) {
  const ScriptFile file(script);
  std::string prog = "gnuplot", arg = file.path();
  char* argv[] = {prog.data(), arg.data(), nullptr};
  int report[2];  // the child's errno if it cannot start gnuplot; closed by a successful exec
  if (::pipe2(report, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("cannot run gnuplot: ") + std::strerror(errno));
  std::optional<ChildProcess> child;
  try {
    // The child: async-signal-safe calls only.
    child.emplace([&] {
      ::close(report[0]);
      int why = 0;
      if (::dup2(STDERR_FILENO, STDOUT_FILENO) < 0 || ::chdir(dir.c_str()) != 0)
        why = errno;
      else
        ::execvp(argv[0], argv), why = errno;
      write_all(report[1], std::string_view(reinterpret_cast<const char*>(&why), sizeof why));
      return 127;
    });
  } catch (const std::exception& e) {
    ::close(report[0]), ::close(report[1]);
    throw std::runtime_error(std::string("cannot run gnuplot: ") + e.what());
  }
  ::close(report[1]);
  int why = 0;
  ssize_t got;
  while ((got = ::read(report[0], &why, sizeof why)) < 0 && errno == EINTR) {
  }
  ::close(report[0]);
  const ChildStatus status = child->wait();
  if (got == sizeof why)
    throw std::runtime_error(fmt::format(
        "cannot run gnuplot in {} ({}; Debian package gnuplot-nox)", dir, std::strerror(why)));
  if (!status.ok())
    throw std::runtime_error(
        fmt::format("gnuplot failed drawing {} (is Debian's gnuplot-nox installed?)", what));
}

// The temporary files gnuplot draws into, beside the chart; removed unless renamed into place.
struct ChartTemps {
  std::vector<std::pair<std::string, std::string>> files;  // (temporary, final), in the folder
  ~ChartTemps() {
    for (const auto& f : files) {
      std::error_code ec;
      fs::remove(f.first, ec);
    }
  }
};

}  // namespace

std::string gnuplot_quote(std::string_view s) {
  std::string out = "'";
  for (const char ch : s) {
    if (ch == '\n' || ch == '\r')
      throw std::invalid_argument("a gnuplot string cannot hold a line break: " + std::string(s));
    out += ch;
    if (ch == '\'') out += '\'';
  }
  return out + "'";
}

void draw_chart(const Chart& chart) {
  const auto [dir, name] = split_stem(chart.stem);
  static std::atomic<unsigned long> serial{0};
  const std::string tag = fmt::format(".tmp.{}.{}", ::getpid(), serial++);
  ChartTemps temps;
  std::string script;
  for (const auto& [terminal, extension] :
       {std::pair<const char*, const char*>{"pngcairo", "png"}, {"svg dynamic", "svg"}}) {
    const std::string final_name = name + "." + extension, temp_name = final_name + tag;
    check_output_path((fs::path(dir) / final_name).string());
    temps.files.emplace_back((fs::path(dir) / temp_name).string(),
                             (fs::path(dir) / final_name).string());
    script += fmt::format(
        "reset\nset datafile separator ','\nset grid\nset terminal {} size {},{}\n"
        "set output {}\n{}\nunset output\n",
        terminal, chart.width, chart.height, gnuplot_quote(temp_name), chart.commands);
  }
  run_gnuplot(script, dir, name);
  for (auto& [temp, final_path] : temps.files) {
    check_output_path(final_path);
    std::error_code ec;
    if (!fs::is_regular_file(temp, ec) || fs::file_size(temp, ec) == 0)
      throw std::runtime_error(final_path + ": gnuplot wrote no chart");
    if (std::rename(temp.c_str(), final_path.c_str()) != 0)
      throw std::runtime_error(final_path + ": cannot write file: " + std::strerror(errno));
    temp.clear();
  }
}

}  // namespace fdh::verify
