// The readers of mesh frames beside OBJ: PLY (ascii, binary of either byte order), PC2 and MDD
// point caches, and bake folders (numbered frames beside un-numbered obstacles).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "fdh/io/bake_folder.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/ply_file.hpp"
#include "fdh/io/point_cache.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

std::string put_file(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
  return p.string();
}

std::string error_text(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PlyFile, AsciiQuadsDoublesAndOtherElementsSkipped) {
  const auto dir = fresh_temp_dir("ply");
  const std::string p = put_file(
      dir / "q.ply",
      "ply\r\nformat ascii 1.0\r\ncomment a quad\r\nelement material 1\r\nproperty list uchar "
      "float c\r\nelement vertex 4\r\nproperty double x\r\nproperty double y\r\nproperty double "
      "z\r\nproperty list uchar int junk\r\nelement face 1\r\nproperty uchar flags\r\nproperty "
      "list uchar uint vertex_index\r\nend_header\r\n2 0.5 0.25\r\n0 0 0.1 0\r\n1 0 0.1 2 7 7\r\n"
      "1 1 0.1 0\r\n0 1 0.1 0\r\n9 4 0 1 2 3\r\n");
  const ObjFile f = read_ply(p);
  ASSERT_EQ(f.x.size(), 4u);
  EXPECT_EQ(f.x[1].x, 1.0);
  EXPECT_EQ(f.x[1].z, 0.1);  // double: the decimal as read
  EXPECT_EQ(f.vertex_lines, (std::vector<int>{16, 17, 18, 19}));
  ASSERT_EQ(f.objects.size(), 1u);
  EXPECT_EQ(f.objects[0].tris, (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(f.polygons, 1);
  EXPECT_FALSE(f.byte_offsets);
}

TEST(PlyFile, BadBodiesNameTheLineOrTheByte) {
  const auto dir = fresh_temp_dir("ply");
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty "
      "float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string v = "0 0 0\n1 0 0\n0 1 0\n";
  const auto err = [&](const std::string& body) {
    const std::string p = put_file(dir / "b.ply", head + body);
    return error_text([&] { read_ply(p); });
  };
  EXPECT_EQ(err(v + "3 0 1 2\n"), "");
  EXPECT_NE(err(v + "3 0 1 3\n").find("b.ply:13: corner 3: vertex index 3 with 3 vertices"),
            std::string::npos);
  EXPECT_NE(err(v + "3 0 1 1\n").find("b.ply:13: a degenerate face: vertex 1 twice"),
            std::string::npos);
  EXPECT_NE(err("0 nan 0\n").find("b.ply:10: vertex 0's y: 'nan' is not a finite number"),
            std::string::npos);
  EXPECT_NE(err(v).find("b.ply:12: the file ends before face 0"), std::string::npos);
  EXPECT_NE(err(v + "3 0 1 2 5\n").find("b.ply:13: face 0 has 5 values"), std::string::npos);
  const std::string p = put_file(dir / "h.ply",
                                 "ply\nformat ascii 1.0\nelement vertex 1\n"
                                 "property int x\nend_header\n1\n");
  EXPECT_NE(error_text([&] {
              read_ply(p);
            }).find("h.ply:3: the vertex element needs a property x of type float or double"),
            std::string::npos);
}

TEST(PointCache, HeadersAndFrames) {
  const auto dir = fresh_temp_dir("cache");
  std::string pc2("POINTCACHE2\0", 12);
  const auto word = [](std::string& s, std::uint32_t w, bool big) {
    for (int i = 0; i < 4; ++i) s += char((w >> (8 * (big ? 3 - i : i))) & 0xff);
  };
  for (const std::uint32_t w : {1u, 1u, 0x3f800000u, 0x3f800000u, 2u}) word(pc2, w, false);
  for (const std::uint32_t w : {0x3f800000u, 0u, 0u, 0x40000000u, 0u, 0xbf800000u})
    word(pc2, w, false);  // (1, 0, 0), (2, 0, -1)
  const PointCache c = open_point_cache(put_file(dir / "a.PC2", pc2));
  EXPECT_EQ(c.points, 1);
  EXPECT_EQ(c.frames, 2);
  EXPECT_EQ(read_cache_frame(c, 1)[0].x, 2.0);
  EXPECT_EQ(read_cache_frame(c, 1)[0].z, -1.0);
  std::string mdd;
  for (const std::uint32_t w : {1u, 1u, 0u, 0x7fc00000u, 0u, 0u}) word(mdd, w, true);
  const PointCache m = open_point_cache(put_file(dir / "a.mdd", mdd));
  EXPECT_TRUE(m.big_endian);
  EXPECT_EQ(error_text([&] { read_cache_frame(m, 0); }),
            m.path + ": byte 12: frame 0, point 0, coordinate 1: not a finite number");
}

TEST(BakeFolder, NumberedFramesAndFixedObstacles) {
  const auto dir = fresh_temp_dir("bake");
  for (const char* n :
       {"cloth_10.obj", "cloth_9.obj", "obstacle_sphere.obj", "ground.PLY", "notes.txt"})
    put_file(dir / n, "");
  const BakeFolder b = read_bake_folder(dir.string());
  ASSERT_EQ(b.frames.size(), 2u);
  EXPECT_EQ(fs::path(b.frames[0]).filename(), "cloth_9.obj");
  ASSERT_EQ(b.obstacles.size(), 2u);
  EXPECT_EQ(fs::path(b.obstacles[0]).filename(), "ground.PLY");
  EXPECT_NE(b.roles("D").find("D: the frames are cloth_*.obj (2 files); fixed obstacles: "
                              "ground.PLY, obstacle_sphere.obj"),
            std::string::npos)
      << b.roles("D");
  put_file(dir / "obstacle_1.obj", "");
  EXPECT_NE(error_text([&] {
              read_bake_folder(dir.string());
            }).find("numbered files of more than one name: cloth_*.obj (2), obstacle_*.obj (1)"),
            std::string::npos);
}

}  // namespace
}  // namespace fdh::verify
