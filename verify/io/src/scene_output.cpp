#include "fdh/io/scene_output.hpp"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "fdh/os/atomic_file.hpp"

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
  double near;   // the near plane's depth: what is nearer is not drawn
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

Camera fit_camera(const Framing& view, int width, int height) {
  const Vec3 centre = view.centre;
  const double radius = view.radius;
  Camera c;
  c.width = width, c.height = height;
  c.forward = unit(-1.0 * view.towards_eye);
  c.right = unit(cross(c.forward, Vec3{0, 1, 0}));
  c.up = cross(c.right, c.forward);
  const double half_fov = 0.45;  // radians, vertical
  c.focal = (height / 2.0) / std::tan(half_fov);
  c.eye = centre - (1.05 * radius / std::sin(half_fov)) * c.forward;
  c.near = 1e-3 * radius;
  return c;
}

}  // namespace

namespace {

// The picture's background: a soft vertical gradient.
void fill_background(Picture& pic) {
  for (int y = 0; y < pic.height; ++y)
    for (int x = 0; x < pic.width; ++x) {
      const double s = 0.75 + 0.2 * y / pic.height;
      for (int k = 0; k < 3; ++k)
        pic.rgb[(std::size_t(y) * pic.width + x) * 3 + k] = (unsigned char)(255 * s);
    }
}

// A projected triangle (pixel x, y and depth) filled with `rgb` where it is nearest.
void fill(Picture& pic, std::vector<double>& depth, const Vec3 (&p)[3],
          const std::array<unsigned char, 3>& rgb) {
  const int x0 = std::max(0, int(std::floor(std::min({p[0].x, p[1].x, p[2].x}))));
  const int x1 = std::min(pic.width - 1, int(std::ceil(std::max({p[0].x, p[1].x, p[2].x}))));
  const int y0 = std::max(0, int(std::floor(std::min({p[0].y, p[1].y, p[2].y}))));
  const int y1 = std::min(pic.height - 1, int(std::ceil(std::max({p[0].y, p[1].y, p[2].y}))));
  const double area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
  if (area == 0) return;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      // Barycentric weights from edge functions, either winding.
      const double w0 = ((p[1].x - px) * (p[2].y - py) - (p[2].x - px) * (p[1].y - py)) / area;
      const double w1 = ((p[2].x - px) * (p[0].y - py) - (p[0].x - px) * (p[2].y - py)) / area;
      const double w2 = 1 - w0 - w1;
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      const double z = w0 * p[0].z + w1 * p[1].z + w2 * p[2].z;
      const std::size_t i = std::size_t(y) * pic.width + x;
      if (z >= depth[i]) continue;
      depth[i] = z;
      for (int k = 0; k < 3; ++k) pic.rgb[i * 3 + k] = rgb[std::size_t(k)];
    }
}

// One triangle, flat shaded (two-sided Lambert: a cloth has no inside), into the depth buffer;
// the part of it in front of the camera's near plane (a close-up's eye may stand above a
// ground triangle: clipped, Sutherland-Hodgman, not dropped).
void draw_triangle(Picture& pic, std::vector<double>& depth, const Camera& cam, const Vec3& a,
                   const Vec3& b, const Vec3& c, const std::array<double, 3>& colour) {
  const Vec3 light = unit(Vec3{0.3, 1.0, 0.6});
  const Vec3 n = cross(b - a, c - a);
  const double len = norm(n);
  if (len == 0) return;
  const double shade = 0.25 + 0.75 * std::fabs(dot(n, light)) / len;
  std::array<unsigned char, 3> rgb;
  for (std::size_t k = 0; k < 3; ++k)
    rgb[k] = (unsigned char)std::lround(255 * std::clamp(shade * colour[k], 0.0, 1.0));
  const Vec3 in[3] = {a, b, c};
  std::vector<Vec3> poly;  // the clipped polygon, in the world
  for (int i = 0; i < 3; ++i) {
    const Vec3 &p = in[i], &q = in[(i + 1) % 3];
    const double dp = dot(p - cam.eye, cam.forward) - cam.near,
                 dq = dot(q - cam.eye, cam.forward) - cam.near;
    if (dp >= 0) poly.push_back(p);
    if ((dp >= 0) != (dq >= 0)) poly.push_back(p + (dp / (dp - dq)) * (q - p));
  }
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
    const Vec3 p[3] = {cam.project(poly[0]), cam.project(poly[i]), cam.project(poly[i + 1])};
    fill(pic, depth, p, rgb);
  }
}

}  // namespace

Framing frame_view(const std::vector<SceneMesh>& meshes) {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const SceneMesh& m : meshes)
    for (const Vec3& p : *m.x) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  return {0.5 * (lo + hi), std::max(0.5 * norm(hi - lo), 1e-9)};
}

Picture render(const std::vector<SceneMesh>& meshes, int width, int height,
               std::optional<Framing> view) {
  const Camera cam = fit_camera(view ? *view : frame_view(meshes), width, height);
  Picture pic{width, height, std::vector<unsigned char>(std::size_t(width) * height * 3)};
  std::vector<double> depth(std::size_t(width) * height, std::numeric_limits<double>::infinity());
  fill_background(pic);
  for (const SceneMesh& m : meshes)
    for (const Tri& t : *m.tris)
      draw_triangle(pic, depth, cam, (*m.x)[t[0]], (*m.x)[t[1]], (*m.x)[t[2]], m.colour);
  return pic;
}

std::string encode_png(const Picture& pic) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = png_uint_32(pic.width);
  image.height = png_uint_32(pic.height);
  image.format = PNG_FORMAT_RGB;
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&image, nullptr, &size, 0, pic.rgb.data(), 0, nullptr))
    throw std::runtime_error(std::string("cannot encode PNG: ") + image.message);
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&image, bytes.data(), &size, 0, pic.rgb.data(), 0, nullptr))
    throw std::runtime_error(std::string("cannot encode PNG: ") + image.message);
  bytes.resize(size);
  return bytes;
}

void write_png(const std::string& path, const std::vector<SceneMesh>& meshes, int width,
               int height) {
  std::string bytes;
  try {
    bytes = encode_png(render(meshes, width, height));
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  write_file_atomically(path, bytes);  // into memory first, then written whole
}

}  // namespace fdh::verify
