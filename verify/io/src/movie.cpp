#include "fdh/io/movie.hpp"

#include <zlib.h>

#include <cstdint>
#include <stdexcept>

#include "fdh/os/atomic_file.hpp"

namespace fdh::verify {
namespace {

void put_u32(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(char((v >> shift) & 0xff));
}

void put_u16(std::string& out, std::uint16_t v) {
  out.push_back(char(v >> 8)), out.push_back(char(v & 0xff));
}

std::uint32_t get_u32(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v = (v << 8) | std::uint8_t(s[at + std::size_t(i)]);
  return v;
}

// A PNG chunk: length, type, data, and the CRC of type and data (PNG spec, §5.3).
void put_chunk(std::string& out, const char* type, const std::string& data) {
  put_u32(out, std::uint32_t(data.size()));
  const std::string body = type + data;
  out += body;
  put_u32(out,
          std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()))));
}

// The IHDR data and the joined IDAT data of one PNG file from libpng.
std::pair<std::string, std::string> header_and_image(const std::string& png) {
  std::string ihdr, idat;
  for (std::size_t at = 8; at + 12 <= png.size();) {  // after the 8-byte signature
    const std::uint32_t len = get_u32(png, at);
    const std::string type = png.substr(at + 4, 4);
    if (type == "IHDR") ihdr = png.substr(at + 8, len);
    if (type == "IDAT") idat += png.substr(at + 8, len);
    at += 12 + std::size_t(len);
  }
  if (ihdr.empty() || idat.empty()) throw std::runtime_error("libpng wrote no image");
  return {ihdr, idat};
}

// fcTL: the frame's place and time: the whole canvas for 1/fps s, nothing disposed or blended.
std::string frame_control(std::uint32_t sequence, int width, int height, int fps) {
  std::string d;
  put_u32(d, sequence), put_u32(d, std::uint32_t(width)), put_u32(d, std::uint32_t(height));
  put_u32(d, 0), put_u32(d, 0);                   // x and y offsets
  put_u16(d, 1), put_u16(d, std::uint16_t(fps));  // delay 1/fps s
  d.push_back(0), d.push_back(0);                 // dispose: none; blend: source
  return d;
}

}  // namespace

Movie::Movie(int width, int height, int fps, double margin)
    : width_(width), height_(height), fps_(fps), margin_(margin) {
  if (width < 1 || height < 1 || fps < 1 || fps > 65535)
    throw std::invalid_argument("a movie needs a positive size and 1 to 65535 frames per second");
}

void Movie::add_frame(const std::vector<SceneMesh>& meshes) {
  if (frames_.empty()) {
    view_ = frame_view(meshes);
    view_.radius *= margin_;
  }
  auto [ihdr, image] = header_and_image(encode_png(render(meshes, width_, height_, view_)));
  if (frames_.empty()) ihdr_ = std::move(ihdr);
  frames_.push_back(std::move(image));
}

std::string Movie::bytes() const {
  if (frames_.empty()) throw std::logic_error("a movie without frames");
  std::string out = "\x89PNG\r\n\x1a\n";
  put_chunk(out, "IHDR", ihdr_);  // every frame's: one size, 8-bit RGB
  std::string actl;
  put_u32(actl, std::uint32_t(frames_.size())), put_u32(actl, 0);  // frames; loop forever
  put_chunk(out, "acTL", actl);
  std::uint32_t sequence = 0;  // fcTL and fdAT chunks share one sequence
  for (std::size_t f = 0; f < frames_.size(); ++f) {
    put_chunk(out, "fcTL", frame_control(sequence++, width_, height_, fps_));
    if (f == 0) {
      put_chunk(out, "IDAT", frames_[f]);  // the default image is the first frame
    } else {
      std::string fdat;
      put_u32(fdat, sequence++);
      put_chunk(out, "fdAT", fdat + frames_[f]);
    }
  }
  put_chunk(out, "IEND", "");
  return out;
}

void Movie::write(const std::string& path) const {
  write_file_atomically(path, bytes());
}

}  // namespace fdh::verify
