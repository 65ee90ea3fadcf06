// How far a long job has got: the one shape every job (certify, fuzz, report, peers, table1,
// scenes, simulate) reports in, and the one the CLI draws (fdh/os/progress_line.hpp).
#pragma once

#include <functional>
#include <string>
#include <utility>

namespace fdh::verify {

struct Progress {
  Progress() = default;
  Progress(std::string stage_, long done_, long total_, std::string unit_ = {},
           std::string detail_ = {})
      : stage(std::move(stage_)),
        done(done_),
        total(total_),
        unit(std::move(unit_)),
        detail(std::move(detail_)) {}

  std::string stage;   // what is being done ("certify: scenes", "fuzz robust on angled")
  long done = 0;       // how much of it
  long total = 0;      // of how much; 0: unknown
  std::string unit;    // what is counted ("cases", "frames"); may be empty
  std::string detail;  // optional words after the count ("3 found", a run's name)
};

// Hears a job's progress; an empty sink hears nothing.
using ProgressSink = std::function<void(const Progress&)>;

inline void report(const ProgressSink& sink, const Progress& p) {
  if (sink) sink(p);
}

}  // namespace fdh::verify
