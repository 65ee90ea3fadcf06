#include "fdh/io/scene_output.hpp"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "fdh/io/atomic_file.hpp"

namespace fdh::verify {

void write_obj(const std::string& path, const std::vector<SceneMesh>& meshes) {
  std::ostringstream os;
  os.precision(17);
  int base = 1;  // OBJ vertex indices count from 1 across the file
  for (const SceneMesh& m : meshes) {
    os << "o " << m.name << "\n";
    for (const Vec3& p : *m.x) os << "v " << p.x << " " << p.y << " " << p.z << "\n";
    for (const Tri& t : *m.tris)
      os << "f " << t[0] + base << " " << t[1] + base << " " << t[2] + base << "\n";
    base += int(m.x->size());
  }
  write_file_atomically(path, os.str());
}

namespace {

// A pinhole camera looking at `target` from direction `from`.
struct Camera {
  Vec3 eye, right, up, forward;
  double focal;  // pixels
  int width, height;

  // Pixel coordinates and depth; depth <= 0 behind the eye.
  Vec3 project(const Vec3& p) const {
    const Vec3 d = p - eye;
    const double z = dot(d, forward);
    return {width / 2.0 + focal * dot(d, right) / z, height / 2.0 - focal * dot(d, up) / z, z};
  }
};

Vec3 unit(const Vec3& v) {
  return (1 / norm(v)) * v;
}

Camera fit_camera(const std::vector<SceneMesh>& meshes, int width, int height) {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const SceneMesh& m : meshes)
    for (const Vec3& p : *m.x) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  const Vec3 centre = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * norm(hi - lo), 1e-9);
  Camera c;
  c.width = width, c.height = height;
  c.forward = unit(Vec3{-0.55, -0.45, -1.0});  // from front, right and above
  c.right = unit(cross(c.forward, Vec3{0, 1, 0}));
  c.up = cross(c.right, c.forward);
  const double half_fov = 0.45;  // radians, vertical
  c.focal = (height / 2.0) / std::tan(half_fov);
  c.eye = centre - (1.05 * radius / std::sin(half_fov)) * c.forward;
  return c;
}

}  // namespace

void write_png(const std::string& path, const std::vector<SceneMesh>& meshes, int width,
               int height) {
  const Camera cam = fit_camera(meshes, width, height);
  std::vector<unsigned char> rgb(std::size_t(width) * height * 3);
  std::vector<double> depth(std::size_t(width) * height, std::numeric_limits<double>::infinity());
  for (int y = 0; y < height; ++y)  // a soft vertical gradient behind everything
    for (int x = 0; x < width; ++x) {
      const double s = 0.75 + 0.2 * y / height;
      for (int k = 0; k < 3; ++k)
        rgb[(std::size_t(y) * width + x) * 3 + k] = (unsigned char)(255 * s);
    }
  const Vec3 light = unit(Vec3{0.3, 1.0, 0.6});
  for (const SceneMesh& m : meshes)
    for (const Tri& t : *m.tris) {
      const Vec3 &a = (*m.x)[t[0]], &b = (*m.x)[t[1]], &c = (*m.x)[t[2]];
      const Vec3 n = cross(b - a, c - a);
      const double len = norm(n);
      if (len == 0) continue;
      // Two-sided Lambert: a cloth has no inside.
      const double shade = 0.25 + 0.75 * std::fabs(dot(n, light)) / len;
      const Vec3 p[3] = {cam.project(a), cam.project(b), cam.project(c)};
      if (p[0].z <= 0 || p[1].z <= 0 || p[2].z <= 0) continue;
      const int x0 = std::max(0, int(std::floor(std::min({p[0].x, p[1].x, p[2].x}))));
      const int x1 = std::min(width - 1, int(std::ceil(std::max({p[0].x, p[1].x, p[2].x}))));
      const int y0 = std::max(0, int(std::floor(std::min({p[0].y, p[1].y, p[2].y}))));
      const int y1 = std::min(height - 1, int(std::ceil(std::max({p[0].y, p[1].y, p[2].y}))));
      const double area =
          (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
      if (area == 0) continue;
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const double px = x + 0.5, py = y + 0.5;
          // Barycentric weights from edge functions, either winding.
          const double w0 = ((p[1].x - px) * (p[2].y - py) - (p[2].x - px) * (p[1].y - py)) / area;
          const double w1 = ((p[2].x - px) * (p[0].y - py) - (p[0].x - px) * (p[2].y - py)) / area;
          const double w2 = 1 - w0 - w1;
          if (w0 < 0 || w1 < 0 || w2 < 0) continue;
          const double z = w0 * p[0].z + w1 * p[1].z + w2 * p[2].z;
          const std::size_t i = std::size_t(y) * width + x;
          if (z >= depth[i]) continue;
          depth[i] = z;
          for (int k = 0; k < 3; ++k)
            rgb[i * 3 + k] =
                (unsigned char)std::lround(255 * std::clamp(shade * m.colour[k], 0.0, 1.0));
        }
    }
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = png_uint_32(width);
  image.height = png_uint_32(height);
  image.format = PNG_FORMAT_RGB;
  png_alloc_size_t size = 0;
  // Into memory first, then written whole.
  if (!png_image_write_to_memory(&image, nullptr, &size, 0, rgb.data(), 0, nullptr))
    throw std::runtime_error(path + ": cannot encode PNG: " + image.message);
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&image, bytes.data(), &size, 0, rgb.data(), 0, nullptr))
    throw std::runtime_error(path + ": cannot encode PNG: " + image.message);
  bytes.resize(size);
  write_file_atomically(path, bytes);
}

}  // namespace fdh::verify
