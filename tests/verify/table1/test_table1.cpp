// The Table 1 job (verify/table1/): its JSON, one row per method, k and grid, beside the
// paper's numbers.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sstream>

#include "fdh/cli/cli.hpp"

namespace fdh::verify {
namespace {

const std::string kTable1Scenes = FDH_SOURCE_DIR "/corpus/scenes/";

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
