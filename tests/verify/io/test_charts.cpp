// Charts: gnuplot string literals, and a chart drawn without a shell into an awkward folder.
#include "fdh/io/charts.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

TEST(Charts, AGnuplotLiteralDoublesItsQuotesAndKeepsTheRest) {
  EXPECT_EQ(gnuplot_quote("data/a.csv"), "'data/a.csv'");
  EXPECT_EQ(gnuplot_quote("it's"), "'it''s'");
  EXPECT_EQ(gnuplot_quote("a\\b \"$(x)\""), "'a\\b \"$(x)\"'");
  EXPECT_THROW(gnuplot_quote("a\nb"), std::invalid_argument);
}

bool have_gnuplot() {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  const std::string all = path;
  for (std::size_t b = 0, e; b <= all.size(); b = e + 1) {
    e = all.find(':', b);
    if (e == std::string::npos) e = all.size();
    if (fs::exists(fs::path(all.substr(b, e - b)) / "gnuplot")) return true;
  }
  return false;
}

TEST(Charts, DrawsPngAndSvgIntoAFolderWhoseNameAShellWouldMisread) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = fresh_temp_dir("charts") / "it's $(x) & y";
  fs::create_directories(dir);
  const fs::path data = dir / "d.csv";
  std::ofstream(data) << "x,y\n1,2\n2,3\n";
  draw_chart({(dir / "c").string(), 300, 200,
              "plot " + gnuplot_quote(data.string()) + " skip 1 using 1:2 with lines title 'y'"});
  EXPECT_GT(fs::file_size(dir / "c.png"), 100u);
  EXPECT_GT(fs::file_size(dir / "c.svg"), 100u);
}

TEST(Charts, AFailingScriptIsAnError) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = fresh_temp_dir("charts_fail");
  EXPECT_THROW(draw_chart({(dir / "c").string(), 300, 200, "plot 'no such file' using 1:2"}),
               std::runtime_error);
}

}  // namespace
}  // namespace fdh::verify
