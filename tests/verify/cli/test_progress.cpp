// The progress line: drawn and erased on a terminal, absent otherwise; every long command takes
// --quiet and prints no progress when its standard error is not a terminal (here: a string).
#include "../../../verify/cli/src/progress.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "cli_run.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

TEST(Progress, ALineShowsStageCountTotalAndIsErased) {
  std::ostringstream err;
  {
    ProgressLine line(err, true);
    line.draw({"certify: generator families", 100, 4800, "queries"});
    line.draw({"certify: scene table", 10, 600, "frames", "now frame 10"});
    EXPECT_NE(err.str().find("\rcertify: generator families: 100 of 4800 queries"),
              std::string::npos);
    EXPECT_NE(err.str().find("certify: scene table: 10 of 600 frames, now frame 10"),
              std::string::npos);
  }
  const std::string all = err.str();
  EXPECT_EQ(all.back(), '\r');  // erased when it goes, the cursor back at the line's start
  EXPECT_EQ(all.find('\n'), std::string::npos);  // never a line of its own
}

TEST(Progress, NothingWhenNotShown) {
  std::ostringstream err;
  {
    ProgressLine line(err, false);
    line.draw({"simulate", 1, 2, "frames"});
    line.clear();
  }
  EXPECT_EQ(err.str(), "");
  std::ostringstream out;
  EXPECT_EQ(progress_wanted({out, err}, false),
            ProgressShow::None);  // not the process's own stderr
}

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
}

}  // namespace
}  // namespace fdh::verify
