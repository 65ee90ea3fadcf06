// The animated PNG: a PNG that libpng reads (its first frame), with the APNG chunks in order,
// sequence numbers without gaps, every CRC right and every frame's data inflating to a whole
// image; and `simulate --movie` writing one, or refusing a bad path before the run.
#include "fdh/io/movie.hpp"

#include <gtest/gtest.h>
#include <png.h>
#include <zlib.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "cli_run.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

struct Chunk {
  std::string type, data;
  bool crc_ok;
};

std::uint32_t u32(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v = (v << 8) | std::uint8_t(s[at + std::size_t(i)]);
  return v;
}

std::vector<Chunk> chunks(const std::string& png) {
  std::vector<Chunk> out;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::uint32_t len = u32(png, at);
    const std::string body = png.substr(at + 4, 4 + len);
    const auto crc = crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()));
    out.push_back({body.substr(0, 4), body.substr(4), crc == u32(png, at + 8 + len)});
    at += 12 + len;
  }
  return out;
}

// The size of the zlib stream's inflated bytes.
std::size_t inflated_size(const std::string& z) {
  std::string out(1 << 22, '\0');
  uLongf n = uLongf(out.size());
  EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(out.data()), &n,
                       reinterpret_cast<const Bytef*>(z.data()), uLong(z.size())),
            Z_OK);
  return n;
}

Movie three_frames() {
  Movie m(64, 48, 10);
  std::vector<Vec3> x = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<Tri> tris = {{0, 1, 2}};
  for (int f = 0; f < 3; ++f) {
    x[2].z = 0.25 * f;  // the triangle tilts
    m.add_frame({{"t", &x, &tris, {0.8, 0.2, 0.2}}});
  }
  return m;
}

TEST(Movie, IsAPngThatLibpngReads) {
  const std::string bytes = three_frames().bytes();
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()))
      << image.message;
  EXPECT_EQ(image.width, 64u);
  EXPECT_EQ(image.height, 48u);
  png_image_free(&image);
}

TEST(Movie, HoldsEveryFrameAsApngChunksInSequence) {
  const std::vector<Chunk> c = chunks(three_frames().bytes());
  std::vector<std::string> types;
  for (const Chunk& k : c) {
    types.push_back(k.type);
    EXPECT_TRUE(k.crc_ok) << k.type;
  }
  EXPECT_EQ(types, (std::vector<std::string>{"IHDR", "acTL", "fcTL", "IDAT", "fcTL", "fdAT", "fcTL",
                                             "fdAT", "IEND"}));
  EXPECT_EQ(u32(c[1].data, 0), 3u);  // frames
  EXPECT_EQ(u32(c[1].data, 4), 0u);  // loops forever
  std::uint32_t sequence = 0;
  for (const Chunk& k : c) {
    if (k.type != "fcTL" && k.type != "fdAT") continue;
    EXPECT_EQ(u32(k.data, 0), sequence++) << k.type;
    if (k.type == "fcTL") {
      EXPECT_EQ(u32(k.data, 4), 64u);
    } else {  // a frame's filtered rows: a filter byte and 3 bytes a pixel each
      EXPECT_EQ(inflated_size(k.data.substr(4)), 48u * (1 + 3 * 64));
    }
  }
  EXPECT_EQ(inflated_size(c[3].data), 48u * (1 + 3 * 64));
}

TEST(Movie, SimulateWritesOneAndRefusesABadPathBeforeTheRun) {
  const std::filesystem::path dir = fresh_temp_dir("movie");
  const std::string movie = (dir / "run.png").string();
  const CliRun r =
      fdhcert({"simulate", FDH_SOURCE_DIR "/corpus/scenes/table.scene", "--grid", "6", "--frames",
               "40", "--no-check", "--movie", movie, "--movie-frames", "8"});
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(movie, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(u32(chunks(bytes)[1].data, 0), 9u);  // frame 1, then every 5th of 40
  const CliRun bad = fdhcert({"simulate", FDH_SOURCE_DIR "/corpus/scenes/table.scene", "--grid",
                              "6", "--frames", "4", "--movie", dir.string()});
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find(dir.string()), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace fdh::verify
