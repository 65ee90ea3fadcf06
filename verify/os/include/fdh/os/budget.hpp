// A run's time budget (--budget SECONDS on certify and fuzz): a deadline on the steady clock,
// counted from the run's start, that a long job looks at between units of work (a query, a
// transformed query, a shrinking step, a fuzz case) so as to stop at a clean point and still
// write its outputs whole; and what it then cut short, for the job's outputs to say. A plug-in
// call in progress is not interrupted: one call (at most --plugin-timeout) may run past it.
// Copies and forked children share the deadline (the steady clock is the machine's).
#pragma once

#include <chrono>
#include <limits>
#include <string>

namespace fdh::verify {

class Budget {
 public:
  using Clock = std::chrono::steady_clock;

  Budget() = default;  // no limit
  Budget(double seconds, Clock::time_point start)
      : seconds_(seconds),
        deadline_(start + std::chrono::duration_cast<Clock::duration>(
                              std::chrono::duration<double>(seconds))) {}

  bool limited() const { return seconds_ > 0; }
  // The budget is used up; no clock is read without a limit.
  bool spent() const { return limited() && Clock::now() >= deadline_; }
  double seconds() const { return seconds_; }
  Clock::time_point deadline() const { return deadline_; }  // max() without a limit

 private:
  double seconds_ = 0;  // 0: no limit
  Clock::time_point deadline_ = Clock::time_point::max();
};

// The run starts now: fdhcert calls it first, so that a budget counts the whole run (loading
// and probing plug-ins included).
void mark_run_start();
// When the run started: the last mark_run_start, else the first call of either.
Budget::Clock::time_point run_start();

// The budget of this run (--budget, whichever command took it; none by default): what is done
// before a command's own work, the plug-ins' probe, looks at it. mark_run_start resets it.
void set_run_budget(const Budget& budget);
const Budget& run_budget();

// What a budget cut short: a stage and how far it got ("generator families", 12 of 5600
// "queries"); total 0 when it is not known.
struct BudgetCut {
  std::string stage;
  long done = 0, total = 0;
  std::string unit;
};

}  // namespace fdh::verify
