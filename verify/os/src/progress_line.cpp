#include "fdh/os/progress_line.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <iostream>

namespace fdh::verify {

ProgressLine::ProgressLine(std::ostream& err, ProgressShow show) : err_(err), show_(show) {
  // Lines are repeated from a thread of their own only on the process's standard error, whose
  // writes are safe from any thread; another stream hears only draw(). The thread starts at the
  // first draw(): a job that forks its workers first (fuzz) forks a process of one thread, since
  // a child forked beside a running thread can inherit a lock held there (ASan's allocator's
  // did: the worker hung in its first allocation).
  beats_ = (show_ == ProgressShow::Lines || show_ == ProgressShow::LinesWhenSlow) &&
           &err == &std::cerr;
}

ProgressLine::~ProgressLine() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (beat_.joinable()) beat_.join();
  clear();
}

ProgressSink ProgressLine::sink(std::string prefix) {
  return [this, prefix = std::move(prefix)](const Progress& p) {
    draw({prefix + p.stage, p.done, p.total, p.unit, p.detail});
  };
}

std::string ProgressLine::text_of(const Progress& p, Clock::time_point now) const {
  const double seconds = std::chrono::duration<double>(now - stage_start_).count();
  std::string line = fmt::format("{}: {}", p.stage, p.done);
  if (p.total > 0) line += fmt::format(" of {}", p.total);
  line += fmt::format(" {}", p.unit);
  if (seconds > 0.2) line += fmt::format(" ({:.3g} {}/s)", double(p.done) / seconds, p.unit);
  if (!p.detail.empty()) line += fmt::format(", {}", p.detail);
  return line;
}

void ProgressLine::draw(const Progress& p) {
  if (show_ == ProgressShow::None) return;
  const std::lock_guard lock(mutex_);
  if (beats_ && !beat_.joinable()) beat_ = std::thread([this] { beat(); });
  const Clock::time_point now = Clock::now();
  const bool new_stage = p.stage != what_, new_detail = p.detail != detail_;
  if (new_stage) what_ = p.stage, stage_start_ = now;
  if (new_detail) detail_ = p.detail;
  last_ = p;
  if (show_ == ProgressShow::Terminal) {
    if (!new_stage && !new_detail && now - last_draw_ < std::chrono::milliseconds(100) &&
        p.done != p.total)
      return;
    draw_in_place(p, now);
  } else {
    draw_line(p, now, new_stage);
  }
}

void ProgressLine::draw_in_place(const Progress& p, Clock::time_point now) {
  last_draw_ = now;
  std::string line = text_of(p, now);
  const std::size_t width = line.size();
  if (width < drawn_) line.append(drawn_ - width, ' ');  // cover what was longer
  err_ << '\r' << line << std::flush;
  drawn_ = width;
}

// A whole line: at a new stage, or kLineSeconds after the last; none before kSlowRunSeconds
// with --progress auto. Called with mutex_ held.
void ProgressLine::draw_line(const Progress& p, Clock::time_point now, bool new_stage) {
  const auto since = [now](Clock::time_point t) {
    return std::chrono::duration<double>(now - t).count();
  };
  if (show_ == ProgressShow::LinesWhenSlow && since(start_) < kSlowRunSeconds) return;
  if (!new_stage && last_draw_ != Clock::time_point{} && since(last_draw_) < kLineSeconds) return;
  last_draw_ = now;
  err_ << text_of(p, now) << fmt::format(" [{:.0f} s]", since(start_)) << '\n' << std::flush;
}

void ProgressLine::beat() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    wake_.wait_for(lock, std::chrono::seconds(1));
    if (!stopping_ && last_) draw_line(*last_, Clock::now(), false);
  }
}

void ProgressLine::clear() {
  const std::lock_guard lock(mutex_);
  last_.reset();
  what_.clear(), detail_.clear();
  if (show_ != ProgressShow::Terminal || drawn_ == 0) return;
  err_ << '\r' << std::string(drawn_, ' ') << '\r' << std::flush;
  drawn_ = 0;
}

ProgressShow progress_wanted(const std::ostream& err, ProgressWhen when) {
  if (when == ProgressWhen::Never) return ProgressShow::None;
  if (&err != &std::cerr)
    return when == ProgressWhen::Always ? ProgressShow::Lines : ProgressShow::None;
  if (::isatty(STDERR_FILENO)) return ProgressShow::Terminal;
  return when == ProgressWhen::Always ? ProgressShow::Lines : ProgressShow::LinesWhenSlow;
}

}  // namespace fdh::verify
