// The progress line of long commands (certify, report, table1, simulate, scenes, fuzz, peers,
// audit): it draws the jobs' one progress type (fdh/os/progress.hpp), what is being done, how far
// it has got and its rate, on standard error. On a terminal, one line redrawn in place ('\r'). Off
// a terminal (a log, a pipe), whole lines every few seconds once a run is slower than expected
// (kSlowRunSeconds), or from the start with --progress always, so that a slow run can be told
// from a hung one. --quiet or --progress never: nothing.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <thread>

#include "fdh/os/progress.hpp"

namespace fdh::verify {

// How progress shows: not at all, redrawn in place on a terminal, or as lines (from the start,
// or once the run has taken kSlowRunSeconds).
enum class ProgressShow { None, Terminal, Lines, LinesWhenSlow };

// --progress auto|always|never.
enum class ProgressWhen { Auto, Always, Never };

// Off a terminal, the first line comes after this many seconds (--progress auto), and a line at
// most every kLineSeconds, and at least that often while a run goes on.
inline constexpr double kSlowRunSeconds = 10;
inline constexpr double kLineSeconds = 3;

class ProgressLine {
 public:
  ProgressLine(std::ostream& err, ProgressShow show);
  // show: as on a terminal; else nothing.
  ProgressLine(std::ostream& err, bool show)
      : ProgressLine(err, show ? ProgressShow::Terminal : ProgressShow::None) {}
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  ~ProgressLine();

  // "<stage>: <done> of <total> <unit> (<rate> <unit>/s), <detail>"; total <= 0: no "of".
  // On a terminal, redrawn at most ten times a second, and whenever the stage changes (its rate
  // then starts again) or the detail does. As lines: a line when the stage changes, and the
  // last progress again every kLineSeconds while nothing new comes (with the time taken).
  void draw(const Progress& p);
  // A sink that draws what a job reports, its stage after `prefix`.
  ProgressSink sink(std::string prefix = {});
  // Erases the line (before the command prints its results); as lines, says nothing more
  // until the next draw.
  void clear();

 private:
  using Clock = std::chrono::steady_clock;
  std::string text_of(const Progress& p, Clock::time_point now) const;
  void draw_in_place(const Progress& p, Clock::time_point now);
  void draw_line(const Progress& p, Clock::time_point now, bool new_stage);
  void beat();  // the thread that repeats the last line off a terminal

  std::ostream& err_;
  ProgressShow show_;
  std::string what_, detail_;
  Clock::time_point start_ = Clock::now(), stage_start_, last_draw_;
  std::size_t drawn_ = 0;  // characters on the line now (on a terminal)
  std::mutex mutex_;       // draw() and the beat: the state above and the writes to err_
  std::condition_variable wake_;
  bool stopping_ = false;
  std::optional<Progress> last_;  // what the beat repeats; none after clear()
  bool beats_ = false;            // lines repeated by the beat (off a terminal, on std::cerr)
  std::thread beat_;              // started by the first draw(), not before: see the constructor
};

// How progress should show for `when` on `err`: on the process's own standard error, on a
// terminal in place, else as lines (auto: once the run is slow); on another stream (an in-process
// run), lines with --progress always, else none.
ProgressShow progress_wanted(const std::ostream& err, ProgressWhen when);

}  // namespace fdh::verify
