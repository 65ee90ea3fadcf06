#include "fdh/io/charts.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "chart_files.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/os/child_process.hpp"
#include "fdh/os/temporaries.hpp"

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

// What gnuplot said (its standard output and error, in order) and how it ended.
struct GnuplotRun {
  ChildStatus status;
  std::string messages;
};

// Everything that comes through `fd` until it closes (the last 64 KiB of it).
std::string read_all(int fd) {
  std::string text;
  char buf[4096];
  for (ssize_t got; (got = ::read(fd, buf, sizeof buf)) != 0;) {
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) break;
    text.append(buf, std::size_t(got));
    if (text.size() > (1u << 17)) text.erase(0, text.size() - (1u << 16));
  }
  return text;
}

// Runs gnuplot SCRIPT in folder DIR (so that the folder's name never enters a script), its
// standard output and error captured. The child is an argument list (fork and execvp, no
// shell) and is killed when fdhcert dies (fdh/os/child_process.hpp). Throws when it cannot start.
GnuplotRun run_gnuplot(const std::string& script, const std::string& dir) {
  const ScriptFile file(script);
  std::string prog = "gnuplot", arg = file.path();
  char* argv[] = {prog.data(), arg.data(), nullptr};
  int report[2], said[2];  // the child's errno if it cannot start gnuplot; gnuplot's messages
  if (::pipe2(report, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("cannot run gnuplot: ") + std::strerror(errno));
  if (::pipe2(said, O_CLOEXEC) != 0) {
    ::close(report[0]), ::close(report[1]);
    throw std::runtime_error(std::string("cannot run gnuplot: ") + std::strerror(errno));
  }
  std::optional<ChildProcess> child;
  try {
    // The child: async-signal-safe calls only.
    child.emplace([&] {
      int why = 0;
      if (::dup2(said[1], STDOUT_FILENO) < 0 || ::dup2(said[1], STDERR_FILENO) < 0 ||
          ::chdir(dir.c_str()) != 0)
        why = errno;
      else
        ::execvp(argv[0], argv), why = errno;
      write_all(report[1], std::string_view(reinterpret_cast<const char*>(&why), sizeof why));
      return 127;
    });
  } catch (const std::exception& e) {
    for (const int fd : {report[0], report[1], said[0], said[1]}) ::close(fd);
    throw std::runtime_error(std::string("cannot run gnuplot: ") + e.what());
  }
  ::close(report[1]), ::close(said[1]);
  const std::string why = read_all(report[0]);
  ::close(report[0]);
  GnuplotRun run;
  run.messages = read_all(said[0]);
  ::close(said[0]);
  run.status = child->wait();
  if (why.size() == sizeof(int)) {
    int e = 0;
    std::memcpy(&e, why.data(), sizeof e);
    throw std::runtime_error(fmt::format(
        "cannot run gnuplot in {} ({}; Debian package gnuplot-nox)", dir, std::strerror(e)));
  }
  return run;
}

// The last line gnuplot printed, if any: at most 200 bytes, control bytes escaped.
std::string last_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  const std::size_t from = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
  return printable(std::string_view(text).substr(from, 200));
}

// Why a chart came out wrong: the disk's own reason when a write fails now (gnuplot ignores its
// write errors), else gnuplot's last words or status, else what is wrong with the file.
std::string failure_reason(const GnuplotRun& run, PrivateFolder& folder,
                           const std::string& problem) {
  const std::string disk = folder.write_probe();
  if (!disk.empty()) return disk;
  const std::string said = last_line(run.messages);
  if (!run.status.ok())
    return "gnuplot ended with " + run.status.words() + (said.empty() ? "" : ": " + said);
  return problem + (said.empty() ? "" : " (gnuplot: " + said + ")");
}

// A drawing of the chart: the terminal, the extension and its check.
struct Drawing {
  const char* terminal;
  const char* extension;
  std::string (*problem)(std::string_view);
};

const Drawing kDrawings[] = {{"pngcairo", "png", png_problem}, {"svg dynamic", "svg", svg_problem}};

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
  const auto final_path = [&, &dir = dir, &name = name](const Drawing& d) {
    return (fs::path(dir) / (name + "." + d.extension)).string();
  };
  for (const Drawing& d : kDrawings) check_output_path(final_path(d));
  remove_dead_runs_temporaries((fs::path(dir) / name).string());
  PrivateFolder folder(dir, name);
  std::string script;
  for (const Drawing& d : kDrawings) {
    const std::string file = name + "." + d.extension;
    folder.expect(file);
    script += fmt::format(
        "reset\nset datafile separator ','\nset grid\nset terminal {} size {},{}\n"
        "set output {}\n{}\nunset output\n",
        d.terminal, chart.width, chart.height, gnuplot_quote(folder.name() + "/" + file),
        chart.commands);
  }
  const GnuplotRun run = run_gnuplot(script, dir);
  write_all(STDERR_FILENO, run.messages);  // its warnings, as if it had written them itself
  // Both drawings whole before either is published: the old charts stay as a pair.
  for (const Drawing& d : kDrawings) {
    const std::optional<std::string> bytes = folder.read(name + "." + d.extension);
    const std::string problem = !bytes ? "gnuplot wrote no chart" : d.problem(*bytes);
    if (!problem.empty() || !run.status.ok())
      throw std::runtime_error(fmt::format("gnuplot failed drawing {}: {}",
                                           printable(final_path(d)),
                                           failure_reason(run, folder, problem)));
  }
  for (const Drawing& d : kDrawings) {
    check_output_path(final_path(d));
    folder.publish(name + "." + d.extension, final_path(d));
  }
}

}  // namespace fdh::verify
