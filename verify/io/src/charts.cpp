#include "fdh/io/charts.hpp"

#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

// A script file that removes itself: mkstemp in the temporary folder, written whole.
class ScriptFile {
 public:
  explicit ScriptFile(const std::string& text) {
    std::string pattern = (fs::temp_directory_path() / "fdhcert-chart-XXXXXX").string();
    const int fd = ::mkstemp(pattern.data());
    if (fd < 0) throw std::runtime_error("cannot create a gnuplot script: " + errno_text());
    path_ = pattern;
    std::size_t done = 0;
    while (done < text.size()) {
      const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        const std::string why = errno_text();
        ::close(fd);
        throw std::runtime_error("cannot write the gnuplot script " + path_ + ": " + why);
      }
      done += std::size_t(n);
    }
    ::close(fd);
  }
  ~ScriptFile() {
    std::error_code ec;
    fs::remove(path_, ec);
  }
  ScriptFile(const ScriptFile&) = delete;
  ScriptFile& operator=(const ScriptFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  static std::string errno_text() { return std::strerror(errno); }
  std::string path_;
};

// gnuplot SCRIPT, its standard output sent to standard error; throws unless it exits with 0.
void run_gnuplot(const std::string& script, const std::string& what) {
  const ScriptFile file(script);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, STDERR_FILENO, STDOUT_FILENO);
  std::string prog = "gnuplot", arg = file.path();
  char* argv[] = {prog.data(), arg.data(), nullptr};
  pid_t pid = 0;
  const int rc = ::posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0)
    throw std::runtime_error(
        fmt::format("cannot run gnuplot ({}; Debian package gnuplot-nox)", std::strerror(rc)));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error("lost the gnuplot process");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(
        fmt::format("gnuplot failed drawing {} (is Debian's gnuplot-nox installed?)", what));
}

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
  std::string script;
  for (const auto& [terminal, extension] :
       {std::pair<const char*, const char*>{"pngcairo", "png"}, {"svg dynamic", "svg"}})
    script += fmt::format(
        "reset\nset datafile separator ','\nset grid\nset terminal {} size {},{}\n"
        "set output {}\n{}\nunset output\n",
        terminal, chart.width, chart.height, gnuplot_quote(chart.stem + "." + extension),
        chart.commands);
  run_gnuplot(script, chart.stem);
}

}  // namespace fdh::verify
