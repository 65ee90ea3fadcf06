#include "progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <iostream>

namespace fdh::verify {

ProgressSink ProgressLine::sink(std::string prefix) {
  return [this, prefix = std::move(prefix)](const Progress& p) {
    draw({prefix + p.stage, p.done, p.total, p.unit, p.detail});
  };
}

void ProgressLine::draw(const Progress& p) {
  if (!show_) return;
  const std::string_view what = p.stage, unit = p.unit, detail = p.detail;
  const long done = p.done, total = p.total;
  const Clock::time_point now = Clock::now();
  const bool new_stage = what != what_, new_detail = detail != detail_;
  if (new_stage) what_ = what, stage_start_ = now;
  if (new_detail) detail_ = detail;
  if (!new_stage && !new_detail && now - last_draw_ < std::chrono::milliseconds(100) &&
      done != total)
    return;
  last_draw_ = now;
  const double seconds = std::chrono::duration<double>(now - stage_start_).count();
  std::string line = fmt::format("{}: {}", what, done);
  if (total > 0) line += fmt::format(" of {}", total);
  line += fmt::format(" {}", unit);
  if (seconds > 0.2) line += fmt::format(" ({:.3g} {}/s)", double(done) / seconds, unit);
  if (!detail.empty()) line += fmt::format(", {}", detail);
  const std::size_t width = line.size();
  if (width < drawn_) line.append(drawn_ - width, ' ');  // cover what was longer
  err_ << '\r' << line << std::flush;
  drawn_ = width;
}

void ProgressLine::clear() {
  if (!show_ || drawn_ == 0) return;
  err_ << '\r' << std::string(drawn_, ' ') << '\r' << std::flush;
  drawn_ = 0;
  what_.clear(), detail_.clear();
}

bool progress_wanted(const Io& io, bool quiet) {
  return !quiet && &io.err == &std::cerr && ::isatty(STDERR_FILENO);
}

CLI::Option* add_quiet_flag(CLI::App& cmd, bool& quiet) {
  return cmd.add_flag("--quiet", quiet,
                      "no progress line (it shows only on a terminal in any case)");
}

}  // namespace fdh::verify
