// Reading OBJ frames (fdh/io/obj_file.hpp) and sequences of them (fdh/io/mesh_sequence.hpp).
#include "fdh/io/obj_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <clocale>
#include <filesystem>
#include <fstream>

#include "fdh/io/input_error.hpp"
#include "fdh/io/mesh_sequence.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

std::string write(const std::filesystem::path& dir, const std::string& name,
                  const std::string& text) {
  const std::string p = (dir / name).string();
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

// The error of reading `text` as an OBJ, "" if it reads.
std::string error_of(const std::string& text) {
  const auto dir = fresh_temp_dir("obj");
  const std::string p = write(dir, "a.obj", text);
  try {
    read_obj(p);
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(p + ":", 0), 0u) << what;
    return what.substr(p.size() + 1);
  }
  return "";
}

const char* const kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(ObjFile, ReadsVerticesFacesObjectsCommentsAndCrlf) {
  const auto dir = fresh_temp_dir("obj");
  const std::string p = write(dir, "a.obj",
                              "# a comment\r\nmtllib x.mtl\r\no cloth\r\nv 0 0 0\r\nv 1 0 0\r\n"
                              "v +1 1e0 -0.5\r\nvt 0 0\r\nvn 0 0 1\r\ns off\r\nf 1/1 2/1/1 3//1\r\n"
                              "o obstacles\r\nv 0 0 1\r\nf -4 -3 -1\r\n");
  const ObjFile f = read_obj(p);
  ASSERT_EQ(f.x.size(), 4u);
  EXPECT_EQ(f.x[2].z, -0.5);
  EXPECT_EQ(f.vertex_lines[3], 12);
  ASSERT_EQ(f.objects.size(), 2u);
  EXPECT_EQ(f.objects[0].name, "cloth");
  EXPECT_EQ(f.objects[0].tris[0], (Tri{0, 1, 2}));
  EXPECT_EQ(f.objects[0].lines[0], 10);
  EXPECT_EQ(f.objects[1].tris[0], (Tri{0, 1, 3}));
  EXPECT_EQ(f.polygons, 0);
}

TEST(ObjFile, QuadsAndPolygonsAreFanTriangulatedAndCounted) {
  const auto dir = fresh_temp_dir("obj");
  const ObjFile f = read_obj(
      write(dir, "q.obj", std::string(kSquare) + "v 0.5 2 0\nf 1 2 3 4\nf 1 2 3 5 4\nf 1 2 3\n"));
  ASSERT_EQ(f.objects.size(), 1u);
  EXPECT_EQ(f.objects[0].name, "");
  EXPECT_EQ(f.polygons, 2);
  ASSERT_EQ(f.objects[0].tris.size(), 2u + 3u + 1u);
  EXPECT_EQ(f.objects[0].tris[1], (Tri{0, 2, 3}));
  EXPECT_EQ(f.objects[0].tris[4], (Tri{0, 4, 3}));
}

TEST(ObjFile, NumbersAreReadTheSameInAnyLocale) {
  const char* old = std::setlocale(LC_NUMERIC, nullptr);
  const std::string saved = old ? old : "C";
  std::setlocale(LC_NUMERIC, "de_DE.UTF-8");  // a decimal comma where installed
  const auto dir = fresh_temp_dir("obj");
  const ObjFile f = read_obj(write(dir, "a.obj", "v 0.25 1.5e-1 -3\n"));
  std::setlocale(LC_NUMERIC, saved.c_str());
  EXPECT_EQ(f.x[0].x, 0.25);
  EXPECT_EQ(f.x[0].y, 0.15);
}

TEST(ObjFile, BadInputNamesFileAndLine) {
  const std::string sq = kSquare;
  EXPECT_EQ(error_of(sq + "v 0 nan 0\n"), "5: coordinate 2: 'nan' is not a finite number");
  EXPECT_EQ(error_of(sq + "v inf 0 0\n"), "5: coordinate 1: 'inf' is not a finite number");
  EXPECT_EQ(error_of(sq + "v 1e999 0 0\n"),
            "5: coordinate 1: '1e999' is outside the range of a double");
  EXPECT_EQ(error_of(sq + "v 1,5 0 0\n"), "5: coordinate 1: '1,5' is not a number");
  EXPECT_EQ(error_of(sq + "v 1 2\n"), "5: a vertex needs three coordinates, not 2");
  EXPECT_EQ(error_of(sq + "f 1 2 0\n"), "5: corner 3: vertex index 0 (OBJ counts from 1)");
  EXPECT_EQ(error_of(sq + "f 1 2 9\n"), "5: vertex index 9 with only 4 vertices in the file");
  EXPECT_EQ(error_of(sq + "f 1 2 -5\n"),
            "5: corner 3: vertex index -5 with only 4 vertices before it");
  EXPECT_EQ(error_of(sq + "f 1 2 x\n"), "5: corner 3: 'x' is not a vertex index");
  EXPECT_EQ(error_of(sq + "f 1 2\n"), "5: a face needs at least 3 vertices, not 2");
  EXPECT_EQ(error_of(sq + "f 1 2 1\n"), "5: a degenerate face: vertex 1 twice");
  EXPECT_EQ(error_of(sq + "f 1 2 3 -4\n"), "5: a degenerate face: vertex 1 twice");
  EXPECT_EQ(error_of(sq + "f 1 2 3\n"), "");
}

TEST(ObjFile, AFilePastTheSizeBoundIsRefused) {
  setenv("FDH_MAX_FILE_BYTES", "30", 1);
  const std::string e = error_of(std::string(kSquare) + "f 1 2 3\n");
  unsetenv("FDH_MAX_FILE_BYTES");
  EXPECT_NE(e.find("FDH_MAX_FILE_BYTES"), std::string::npos) << e;
}

TEST(MeshSequence, NaturalOrder) {
  std::vector<std::string> v = {"f_10.obj", "f_2.obj", "f_1.obj", "f_02.obj", "g.obj", "f_9a.obj"};
  std::sort(v.begin(), v.end(), natural_less);
  EXPECT_EQ(v, (std::vector<std::string>{"f_1.obj", "f_02.obj", "f_2.obj", "f_9a.obj", "f_10.obj",
                                         "g.obj"}));
  const auto dir = fresh_temp_dir("seq");
  for (const char* n : {"frame_10.obj", "frame_2.obj", "frame_1.OBJ", "notes.txt"})
    write(dir, n, "");
  const std::vector<std::string> files = frame_files({dir.string()});
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(std::filesystem::path(files[0]).filename(), "frame_1.OBJ");
  EXPECT_EQ(std::filesystem::path(files[2]).filename(), "frame_10.obj");
  EXPECT_THROW(frame_files({(dir / "none").string()}), InputError);
}

const char* const kTwoObjects =
    "o cloth\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\no obstacles\nv 0 0 -1\nv 1 0 -1\n"
    "v 0 1 -1\nf 5 6 7\n";

TEST(MeshSequence, SplitsClothAndObstaclesAndStreamsFrames) {
  const auto dir = fresh_temp_dir("seq");
  write(dir, "f1.obj", kTwoObjects);
  std::string moved = kTwoObjects;
  moved.replace(moved.find("v 0 0 -1"), 8, "v 0 0 -2");
  write(dir, "f2.obj", moved);
  const std::string fixed = write(dir, "fixed.mesh", "v 5 5 5\nv 6 5 5\nv 5 6 5\nf 1 2 3\n");
  const MeshSequence s({dir.string()}, "", {fixed});
  EXPECT_EQ(s.frames(), 2);
  EXPECT_EQ(s.cloth_name(), "cloth");
  EXPECT_EQ(s.polygons(), 1);
  EXPECT_EQ(s.topology().cloth_vertices, 4);
  EXPECT_EQ(s.topology().cloth.size(), 2u);
  EXPECT_EQ(s.topology().obstacle_vertices, 6);
  EXPECT_EQ(s.topology().obstacle, (std::vector<Tri>{{0, 1, 2}, {3, 4, 5}}));
  const MeshFrame m = s.read(1);
  EXPECT_EQ(m.obstacle[0].z, -2);
  EXPECT_EQ(m.obstacle[3].x, 5);
  EXPECT_EQ(m.cloth_vertices.at(3), s.files()[1] + ":5");
  EXPECT_EQ(m.obstacle_tris.at(1), fixed + ":4");
  // The whole file as the cloth when asked for an object that is the whole file.
  const MeshSequence whole({s.files()[0]}, "obstacles", {});
  EXPECT_EQ(whole.topology().cloth_vertices, 3);
  EXPECT_EQ(whole.topology().obstacle_vertices, 4);
}

std::string sequence_error(const std::vector<std::string>& texts, const std::string& cloth = "") {
  const auto dir = fresh_temp_dir("seq");
  for (std::size_t i = 0; i < texts.size(); ++i)
    write(dir, "f" + std::to_string(i) + ".obj", texts[i]);
  try {
    const MeshSequence s({dir.string()}, cloth, {});
    for (int i = 0; i < s.frames(); ++i) s.read(i);
  } catch (const InputError& e) {
    std::string what = e.what();
    const std::string prefix = dir.string() + "/";
    for (std::size_t at; (at = what.find(prefix)) != std::string::npos;)
      what.erase(at, prefix.size());
    return what;
  }
  return "";
}

TEST(MeshSequence, TopologyMismatchNamesTheFaceAndTheFirstFile) {
  const std::string a = std::string(kSquare) + "f 1 2 3\nf 1 3 4\n";
  EXPECT_EQ(sequence_error({a, a}), "");
  const std::string b = std::string(kSquare) + "f 1 2 3\nf 1 4 3\n";
  std::string e = sequence_error({a, b});
  EXPECT_NE(e.find("f1.obj:6: face 2 differs from "), std::string::npos) << e;
  e = sequence_error({a, std::string(kSquare) + "f 1 2 3\n"});
  EXPECT_NE(e.find("1 triangles in object ''"), std::string::npos) << e;
  e = sequence_error({a, a + "v 0 0 0\n"});
  EXPECT_NE(e.find("f1.obj:7: 5 vertices, and "), std::string::npos) << e;
  e = sequence_error({a}, "sheet");
  EXPECT_NE(e.find("no object named 'sheet'"), std::string::npos) << e;
}

TEST(MeshSequence, NonManifoldClothIsRefused) {
  const std::string fan = std::string(kSquare) + "v 1 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n";
  const std::string e = sequence_error({fan});
  EXPECT_NE(e.find("f0.obj:8: non-manifold cloth: the edge between vertices 1 and 2"),
            std::string::npos)
      << e;
  EXPECT_NE(sequence_error({kTwoObjects + std::string("o x\nf 1 5 6\n")})
                .find("belongs to the cloth and to an obstacle"),
            std::string::npos);
}

}  // namespace
}  // namespace fdh::verify
