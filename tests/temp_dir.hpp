// A test's own folder for files: unique (mkdtemp) under GoogleTest's temporary directory
// ($TEST_TMPDIR, else $TMPDIR, else /tmp), named fdh_<name>.XXXXXX, and removed when the test
// that made it ends, passed or failed (or at exit, for one made outside a test). With
// FDH_KEEP_TEST_FILES=1 in the environment it is kept, and its path printed.
#pragma once

#include <filesystem>
#include <string>

namespace fdh {

std::filesystem::path fresh_temp_dir(const std::string& name);

}  // namespace fdh
