// One small z-up sequence with a crossing, written in every format `fdhcert audit` reads (OBJ
// frames, ascii and binary PLY frames of either byte order, a PC2 and an MDD cache with their
// OBJ mesh, a bake folder), must give the same verdict and first violation; its picture, with a
// 10 m ground under it, must show the violation (more than 1 % of its pixels in the mark colour).
#include <gtest/gtest.h>
#include <png.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_run.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// A 5x5 vertex cloth (1 m, z up) over a 10 m ground at z = 0: three frames, falling; in the last
// the middle vertex (12) is pushed through the ground. Every coordinate is a multiple of 1/64, so
// float32 (PC2, MDD, binary PLY) and decimal text hold the same numbers.
struct ZUpScene {
  std::vector<std::array<double, 3>> cloth(int frame) const {
    std::vector<std::array<double, 3>> x;
    const double z = frame == 0 ? 0.0625 : 0.046875;
    for (int r = 0; r < 5; ++r)
      for (int c = 0; c < 5; ++c) x.push_back({-0.5 + 0.25 * c, -0.5 + 0.25 * r, z});
    if (frame == 2) x[12][2] = -0.0625;
    return x;
  }
  std::vector<std::array<int, 3>> tris() const {
    std::vector<std::array<int, 3>> t;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) {
        const int a = r * 5 + c;
        t.push_back({a, a + 1, a + 6}), t.push_back({a, a + 6, a + 5});
      }
    return t;
  }
  std::vector<std::array<double, 3>> ground() const {
    return {{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}};
  }
};

std::string obj_of(const std::vector<std::array<double, 3>>& x,
                   const std::vector<std::array<int, 3>>& t) {
  std::ostringstream os;
  for (const auto& p : x) os << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
  for (const auto& f : t) os << "f " << f[0] + 1 << " " << f[1] + 1 << " " << f[2] + 1 << "\n";
  return os.str();
}

void put_bytes(std::string& s, const void* p, int n, bool big) {
  const auto* b = static_cast<const unsigned char*>(p);  // the host is little-endian here
  for (int i = 0; i < n; ++i) s += char(b[big ? n - 1 - i : i]);
}

std::string ply_of(const std::vector<std::array<double, 3>>& x,
                   const std::vector<std::array<int, 3>>& t, const std::string& format) {
  const bool ascii = format == "ascii", big = format == "binary_big_endian";
  std::ostringstream os;
  os << "ply\nformat " << format << " 1.0\ncomment fdhcert test\nelement vertex " << x.size()
     << "\nproperty " << (ascii ? "double" : "float")
     << " x\nproperty float y\nproperty float z\nproperty uchar red\nelement face " << t.size()
     << "\nproperty list uchar int vertex_indices\nend_header\n";
  std::string s = os.str();
  for (const auto& p : x) {
    if (ascii) {
      std::ostringstream v;
      v << p[0] << " " << p[1] << " " << p[2] << " 7\n";
      s += v.str();
      continue;
    }
    for (const double c : p) {
      const auto f = float(c);
      put_bytes(s, &f, 4, big);
    }
    s += char(7);
  }
  for (const auto& f : t) {
    if (ascii) {
      s += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) +
           "\n";
      continue;
    }
    s += char(3);
    for (const int i : f) put_bytes(s, &i, 4, big);
  }
  return s;
}

// PC2 (Blender's io_export_pc2) or MDD (io_shape_mdd) of the three cloth frames.
std::string cache_of(const ZUpScene& sc, bool pc2) {
  std::string s;
  const std::int32_t frames = 3, points = 25, one = 1;
  const float start = 1, rate = 1;
  if (pc2) {
    s.append("POINTCACHE2\0", 12);
    put_bytes(s, &one, 4, false), put_bytes(s, &points, 4, false), put_bytes(s, &start, 4, false);
    put_bytes(s, &rate, 4, false), put_bytes(s, &frames, 4, false);
  } else {
    put_bytes(s, &frames, 4, true), put_bytes(s, &points, 4, true);
    for (int f = 0; f < 3; ++f) {
      const float time = float(f) / 25;
      put_bytes(s, &time, 4, true);
    }
  }
  for (int f = 0; f < 3; ++f)
    for (const auto& p : sc.cloth(f))
      for (const double c : p) {
        const auto v = float(c);
        put_bytes(s, &v, 4, !pc2);
      }
  return s;
}

void write_bytes(const fs::path& p, const std::string& bytes) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << bytes;
}

// The audit's JSON, run with `args`, less what depends on the files (places, names, costs).
Json audit_json(std::vector<std::string> args) {
  args.insert(args.begin(), "audit");
  args.push_back("--json");
  const CliRun r = fdhcert(args);
  EXPECT_EQ(r.status, 1) << r.err;
  Json j = Json::parse(r.out.empty() ? "{}" : r.out);
  j.erase("cost"), j.erase("summary"), j.erase("kept");
  if (j.contains("first_violation")) j["first_violation"].erase("places");
  return j;
}

class AuditFormats : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fresh_temp_dir("audit_formats");
    const std::vector<std::array<double, 3>> none;
    write_bytes(dir / "objs/ground.obj", obj_of(sc.ground(), {{0, 1, 2}, {0, 2, 3}}));
    for (const char* f : {"ascii", "binary_little_endian", "binary_big_endian"})
      write_bytes(dir / f / "ground.ply", ply_of(sc.ground(), {{0, 1, 2}, {0, 2, 3}}, f));
    for (int i = 0; i < 3; ++i) {
      const std::string n = "cloth_" + std::to_string(i + 1);
      write_bytes(dir / "objs" / (n + ".obj"), obj_of(sc.cloth(i), sc.tris()));
      for (const char* f : {"ascii", "binary_little_endian", "binary_big_endian"})
        write_bytes(dir / f / (n + ".ply"), ply_of(sc.cloth(i), sc.tris(), f));
    }
    write_bytes(dir / "cloth.obj", obj_of(sc.cloth(0), sc.tris()));
    write_bytes(dir / "cloth.pc2", cache_of(sc, true));
    write_bytes(dir / "cloth.mdd", cache_of(sc, false));
  }
  std::string at(const std::string& name) const { return (dir / name).string(); }

  ZUpScene sc;
  fs::path dir;
};

TEST_F(AuditFormats, EveryFormatGivesTheSameVerdictAndFirstViolation) {
  const std::string ground = at("objs/ground.obj");
  std::vector<std::string> objs;
  for (int i = 1; i <= 3; ++i) objs.push_back(at("objs/cloth_" + std::to_string(i) + ".obj"));
  objs.insert(objs.end(), {"--obstacle", ground});
  const Json want = audit_json(objs);
  ASSERT_FALSE(want["clean"].get<bool>());
  EXPECT_EQ(want["first_violation"]["kind"], "cloth-vertex-obstacle") << want.dump();
  EXPECT_EQ(want["first_violation"]["vertices"][0], 12);
  EXPECT_EQ(audit_json({at("objs")}), want) << "the bake folder";
  for (const char* f : {"ascii", "binary_little_endian", "binary_big_endian"})
    EXPECT_EQ(audit_json({at(f)}), want) << f;
  EXPECT_EQ(audit_json({at("cloth.obj"), at("cloth.pc2"), "--obstacle", ground}), want) << "PC2";
  EXPECT_EQ(audit_json({at("cloth.obj"), at("cloth.mdd"), "--obstacle", ground}), want) << "MDD";
}

// Two --parts of the bake folder, merged: the whole run's verdict and first violation (issue 32,
// "Done when"; tests/audit/test_audit_parts.cpp checks merges at length on another sequence).
TEST_F(AuditFormats, TwoPartsMergedGiveTheSameVerdictAndFirstViolation) {
  const Json want = audit_json({at("objs")});
  for (const char* part : {"1/2", "2/2"}) {
    const std::string out = at(std::string("part") + part[0]);
    const CliRun r = fdhcert({"audit", at("objs"), "--part", part, "--out", out});
    EXPECT_TRUE(r.status == 0 || r.status == 1) << part << ": " << r.err;
  }
  const CliRun m =
      fdhcert({"audit", "--merge", at("part1"), at("part2"), "--out", at("merged"), "--json"});
  ASSERT_EQ(m.status, 1) << m.err;
  Json j = Json::parse(m.out);
  j.erase("cost"), j.erase("summary"), j.erase("kept");
  if (j.contains("first_violation")) j["first_violation"].erase("places");
  j["first_violation"].erase("case_file");  // the parts were written with --out; `want` was not
  EXPECT_EQ(j, want);
}

TEST_F(AuditFormats, TheOutputSaysWhatIsClothAndWhatObstacle) {
  const CliRun r = fdhcert({"audit", at("objs")});
  EXPECT_NE(r.err.find("the frames are cloth_*.obj (3 files); fixed obstacles: ground.obj"),
            std::string::npos)
      << r.err;
  const CliRun c = fdhcert(
      {"audit", at("cloth.obj"), at("cloth.pc2"), "--obstacle", at("objs/ground.obj"), "--json"});
  EXPECT_NE(c.err.find("a PC2 point cache of 3 frames, 25 points"), std::string::npos) << c.err;
  EXPECT_NE(c.out.find("cloth.obj:"), std::string::npos) << c.out;  // places name the mesh
  const std::string out = at("pc2-out");
  EXPECT_EQ(fdhcert({"audit", at("cloth.obj"), at("cloth.pc2"), "--obstacle", at("objs/ground.obj"),
                     "--out", out})
                .status,
            1);
  std::string first_line;
  for (const auto& e : fs::directory_iterator(out + "/cases")) {
    std::ifstream in(e.path());
    std::getline(in, first_line);
    break;
  }
  EXPECT_NE(first_line.find("from " + at("cloth.pc2") + ", frame 1 to"), std::string::npos)
      << first_line;  // a cached frame's name
  const CliRun b = fdhcert({"audit", at("binary_big_endian"), "--json"});
  EXPECT_NE(b.out.find("cloth_2.ply:byte "), std::string::npos) << b.out.substr(0, 2000);
}

// Pixels of the picture that are the mark's blue (shaded): blue well above red and green.
long mark_pixels(const std::string& png, long& total) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, png.data(), png.size())) return -1;
  image.format = PNG_FORMAT_RGB;
  std::vector<unsigned char> rgb(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, rgb.data(), 0, nullptr)) return -1;
  total = long(image.width) * long(image.height);
  long n = 0;
  for (std::size_t i = 0; i < rgb.size(); i += 3)
    n += rgb[i + 2] > rgb[i] + 30 && rgb[i + 2] > rgb[i + 1] + 20;
  return n;
}

TEST_F(AuditFormats, ThePictureShowsTheViolation) {
  const std::string out = at("out");
  for (const std::vector<std::string>& up :
       {std::vector<std::string>{}, std::vector<std::string>{"--up", "z"}}) {
    std::vector<std::string> args = {"audit", at("objs"), "--out", out};
    args.insert(args.end(), up.begin(), up.end());
    ASSERT_EQ(fdhcert(args).status, 1);
    std::ifstream in(out + "/first-violation.png", std::ios::binary);
    const std::string png((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    long total = 0;
    const long marks = mark_pixels(png, total);
    EXPECT_EQ(total, 800 * 600);
    EXPECT_GT(marks, total / 100) << marks << " of " << total << " pixels";
    std::cout << "first-violation.png" << (up.empty() ? "" : " --up z") << ": " << marks << " of "
              << total << " pixels in the mark's blue\n";
  }
  EXPECT_EQ(fdhcert({"audit", at("objs"), "--up", "w"}).status, 2);
}

}  // namespace
}  // namespace fdh::verify
