// The progress line: drawn and erased on a terminal, whole lines off one with --progress always,
// nothing when not shown or on a stream that is not the process's standard error.
#include "fdh/os/progress_line.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "text_file.hpp"

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
  EXPECT_EQ(progress_wanted(err, ProgressWhen::Auto),
            ProgressShow::None);  // not the process's own stderr
}

TEST(Progress, LinesOffATerminalWithProgressAlways) {
  std::ostringstream err;
  {
    ProgressLine line(err, ProgressShow::Lines);
    line.draw({"certify: corpus", 1, 12, "files"});
    line.draw({"certify: corpus", 2, 12, "files"});  // within kLineSeconds: not repeated
    line.draw({"certify: generator families", 0, 4800, "queries"});  // a new stage: a line
  }
  const std::string all = err.str();
  EXPECT_EQ(all.find('\r'), std::string::npos);
  EXPECT_TRUE(has(all, "certify: corpus: 1 of 12 files [0 s]\n")) << all;
  EXPECT_FALSE(has(all, "2 of 12")) << all;
  EXPECT_TRUE(has(all, "certify: generator families: 0 of 4800 queries [0 s]\n")) << all;
  std::ostringstream quiet;
  {
    ProgressLine line(quiet, ProgressShow::LinesWhenSlow);  // nothing in a run's first 10 s
    line.draw({"certify: corpus", 1, 12, "files"});
  }
  EXPECT_EQ(quiet.str(), "");
  EXPECT_EQ(progress_wanted(err, ProgressWhen::Always), ProgressShow::Lines);
  EXPECT_EQ(progress_wanted(err, ProgressWhen::Auto), ProgressShow::None);
}

}  // namespace
}  // namespace fdh::verify
