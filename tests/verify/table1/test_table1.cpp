// The Table 1 job (verify/table1/): its JSON and CSV, one row per method, k and grid, beside
// the paper's numbers.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <sstream>

#include "fdh/cli/cli.hpp"
#include "fdh/table1/table1.hpp"

namespace fdh::verify {
namespace {

const std::string kTable1Scenes = FDH_SOURCE_DIR "/corpus/scenes/";

std::size_t line_count(const std::string& s) {
  return std::size_t(std::count(s.begin(), s.end(), '\n'));
}

Table1 one_cell() {
  Table1 t;
  t.scene = "table.scene";
  t.frames = 10;
  Table1Cell c{"linear-system", 18, 15, {}};
  c.run.frames = 10;
  c.run.time.springs = 0.002;
  c.run.time.narrow = 0.001;
  c.run.fp = 3;
  t.cells.push_back(c);
  return t;
}

TEST(Table1, JsonHoldsEveryRowAndThePaper) {
  const nlohmann::ordered_json j = table1_json(one_cell());
  EXPECT_EQ(j["frames"], 10);
  ASSERT_EQ(j["rows"].size(), 1u);
  EXPECT_EQ(j["rows"][0]["method"], "linear-system");
  EXPECT_EQ(j["rows"][0]["fp"], 3);
  EXPECT_DOUBLE_EQ(j["rows"][0]["ms_per_frame"].get<double>(), 0.3);
  EXPECT_EQ(j["paper"]["grids"].get<std::vector<int>>(), (std::vector<int>{15, 25, 30, 50}));
  EXPECT_DOUBLE_EQ(j["paper"]["paper-intended"][3].get<double>(), 15.27);
  EXPECT_DOUBLE_EQ(one_cell().cells[0].paper_ms(), 12.17);
}

TEST(Table1, CsvHasOurRowsThenThePapers) {
  const std::string csv = table1_csv(one_cell());
  EXPECT_EQ(line_count(csv), 1u + 1u + 8u);
  EXPECT_NE(csv.find("linear-system k=18,18,15,225,0.3,3,0,0\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("paper: this paper,0,50,2500,15.27,,,\n"), std::string::npos);
}

TEST(Table1, JsonHasOneRowPerMethodKAndGrid) {
  std::ostringstream out, err;
  ASSERT_EQ(run_cli({"table1", "--scene", kTable1Scenes + "table.scene", "--frames", "3", "--json"},
                    out, err),
            0)
      << err.str();
  const nlohmann::json j = nlohmann::json::parse(out.str());
  EXPECT_EQ(j["rows"].size(), 24u);  // 6 rows × 4 grids
  EXPECT_EQ(j["paper"]["grids"], nlohmann::json({15, 25, 30, 50}));
  EXPECT_NE(out.str().find("15.27"), std::string::npos);
}

}  // namespace
}  // namespace fdh::verify
