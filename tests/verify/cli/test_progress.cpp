// --quiet and --progress: every long command takes --quiet and prints no progress when its
// standard error is not a terminal (here: a string); --progress takes auto, always or never.
#include <gtest/gtest.h>

#include <sstream>

#include "cli_run.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

TEST(Progress, LongCommandsTakeQuietAndPrintNoProgressOffATerminal) {
  const std::string dir = fresh_temp_dir("progress").string();
  const std::string scene = FDH_SOURCE_DIR "/corpus/scenes/table.scene";
  const std::vector<std::vector<std::string>> runs = {
      {"simulate", scene, "--grid", "5", "--frames", "30", "--quiet"},
      {"simulate", scene, "--grid", "5", "--frames", "30"},
      {"fuzz", "--method", "linear-system", "--family", "sliver", "--count", "20", "--out",
       dir + "/fuzz", "--quiet"}};
  for (const auto& args : runs) {
    const CliRun r = fdhcert(args);
    EXPECT_EQ(r.status, 0) << args[0] << ": " << r.err;
    EXPECT_EQ(r.err.find('\r'), std::string::npos) << args[0];
  }
  for (const char* cmd : {"certify", "report", "table1", "scenes", "simulate", "fuzz"}) {
    const CliRun help = fdhcert({cmd, "--help"});
    EXPECT_NE(help.out.find("--quiet"), std::string::npos) << cmd;
  }
  EXPECT_EQ(fdhcert({"simulate", "--progress", "sometimes"}).status, 2);
}

}  // namespace
}  // namespace fdh::verify
