// The scene schema (fdh/io/scene_schema.hpp): one table for the reader, the check, simulate's
// overrides and docs/limits.md.
#include "fdh/io/scene_schema.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "fdh/io/input_error.hpp"
#include "fdh/io/scene_file.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

std::string text_of_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// docs/limits.md holds the table as scene_limits_markdown() prints it, after its marker.
TEST(SceneSchema, TheDocsShowTheTable) {
  const std::string doc = text_of_file(FDH_SOURCE_DIR "/docs/limits.md");
  const std::string marker = "<!-- scene values: scene_limits_markdown(), checked by a test -->\n";
  const std::size_t at = doc.find(marker);
  ASSERT_NE(at, std::string::npos) << "no marker in docs/limits.md";
  const std::string table = scene_limits_markdown();
  EXPECT_EQ(doc.substr(at + marker.size(), table.size()), table) << "docs/limits.md should read\n"
                                                                 << table;
}

TEST(SceneSchema, EveryFieldHasANameAndARange) {
  std::set<std::string> fields;
  for (const SceneValue& f : scene_values()) {
    EXPECT_TRUE(fields.insert(f.field).second) << f.field << " twice";
    EXPECT_LT(f.lo, f.hi) << f.field;
    EXPECT_TRUE(f.admits(f.hi)) << f.field;
    EXPECT_EQ(f.admits(f.lo), !f.open_lo) << f.field;
    EXPECT_EQ(&scene_value(f.field), &f);
    if (f.get) {
      EXPECT_NE(f.set, nullptr) << f.field;
      // The default scene is within every range.
      for (int c = 0; c < f.components; ++c) EXPECT_TRUE(f.admits(f.get(cloth::Scene{}, c)));
    }
  }
  EXPECT_THROW(scene_value("nope"), std::logic_error);
}

TEST(SceneSchema, ARangeSaysItsUnitAndAWholeNumberItsBound) {
  EXPECT_EQ(scene_value("size").range_text(), "[0.001, 1000] m");
  EXPECT_EQ(scene_value("stiffness structural").range_text(), "(0, 1e+09] N/m");
  EXPECT_EQ(scene_value("frames").range_text(), "[0, 100000000]");
  EXPECT_FALSE(scene_value("grid").admits(2.5));
  EXPECT_EQ(scene_value("grid").refusal("grid", "'4000'", 4000),
            "grid must be a whole number in [2, 2000], not '4000'; the bound is 2000 particles "
            "per side; set FDH_MAX_GRID to raise it (docs/limits.md)");
  EXPECT_EQ(scene_value("frames").refusal("frames", "-1", -1),
            "frames must be a whole number in [0, 100000000], not -1");
}

// The check takes its ranges from the table: a value set past a field's range is refused with
// the field's name, for every field the table reads alone.
TEST(SceneSchema, TheCheckRefusesEveryFieldPastItsRange) {
  for (const SceneValue& f : scene_values()) {
    if (!f.set) continue;
    cloth::Scene s;
    f.set(s, f.components - 1, f.hi * 2 + 1);
    try {
      check_scene(s, "s.scene");
      ADD_FAILURE() << f.field << " accepted past its range";
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find("s.scene: " + std::string(f.field)), std::string::npos)
          << e.what();
    }
  }
}

// self_distance: a length in the table's range, or auto (the skin); out of range, the file and
// line.
TEST(SceneSchema, SelfDistanceIsALengthOrAuto) {
  const std::string path = (fresh_temp_dir("self_distance") / "s.scene").string();
  const auto read = [&](const std::string& text) {
    std::ofstream(path) << text;
    return read_scene(path);
  };
  EXPECT_EQ(read("grid 11\nsize 1\n").self_gap(), read("grid 11\nsize 1\n").skin());
  EXPECT_EQ(read("grid 11\nsize 1\nself_distance auto\n").self_gap(), 0.6 * 1 / 10);
  EXPECT_EQ(read("grid 11\nself_distance 0.01\n").self_gap(), 0.01);
  EXPECT_EQ(read("self_distance 0\n").self_gap(), 0);
  try {
    read("grid 11\nself_distance -1\n");
    ADD_FAILURE() << "a negative self_distance accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.scene:2: self_distance must be in [0, 1000] m"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fdh::verify
