#include "fdh/os/budget.hpp"

namespace fdh::verify {
namespace {

Budget::Clock::time_point& start() {
  static Budget::Clock::time_point t = Budget::Clock::now();
  return t;
}

Budget& the_run_budget() {
  static Budget b;
  return b;
}

}  // namespace

void mark_run_start() {
  start() = Budget::Clock::now();
  the_run_budget() = Budget();
}

void set_run_budget(const Budget& budget) {
  the_run_budget() = budget;
}

const Budget& run_budget() {
  return the_run_budget();
}

Budget::Clock::time_point run_start() {
  return start();
}

}  // namespace fdh::verify
