// The last resort of fdhcert's main: an error nobody foresaw (an exception no command handles,
// in main or in another thread) is an internal error, never an abort, and the run's temporaries
// go first (docs/limits.md).
#pragma once

namespace fdh::verify {

// The exit status of an internal error.
constexpr int kInternalErrorStatus = 3;

// Removes this run's recorded temporaries (fdh/os/temporaries.hpp), prints
// "fdhcert: internal error: WHAT" on standard error and ends the process with status 3.
[[noreturn]] void end_with_internal_error(const char* what) noexcept;

// std::terminate (an exception that escaped a thread or a noexcept function) ends the process
// through end_with_internal_error, with the exception's words.
void end_with_internal_error_on_terminate();

}  // namespace fdh::verify
