#include "fdh/os/last_resort.hpp"

#include <unistd.h>

#include <cstdio>
#include <exception>

#include "fdh/os/temporaries.hpp"

namespace fdh::verify {
namespace {

void on_terminate() {
  try {
    if (const std::exception_ptr e = std::current_exception()) std::rethrow_exception(e);
  } catch (const std::exception& e) {
    end_with_internal_error(e.what());
  } catch (...) {
    end_with_internal_error("an exception of unknown type");
  }
  end_with_internal_error("the program ended without an exception (std::terminate)");
}

}  // namespace

void end_with_internal_error(const char* what) noexcept {
  remove_recorded_temporaries();
  std::fprintf(stderr, "fdhcert: internal error: %s\n", what);
  std::fflush(stderr);
  ::_exit(kInternalErrorStatus);
}

void end_with_internal_error_on_terminate() {
  std::set_terminate(on_terminate);
}

}  // namespace fdh::verify
