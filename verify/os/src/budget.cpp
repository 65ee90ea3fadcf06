#include "fdh/os/budget.hpp"

namespace fdh::verify {
namespace {

Budget::Clock::time_point& start() {
  static Budget::Clock::time_point t = Budget::Clock::now();
  return t;
}

}  // namespace

void mark_run_start() {
  start() = Budget::Clock::now();
}

Budget::Clock::time_point run_start() {
  return start();
}

}  // namespace fdh::verify
