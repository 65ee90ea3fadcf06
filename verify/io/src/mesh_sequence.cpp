#include "fdh/io/mesh_sequence.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <optional>

#include "fdh/io/input_error.hpp"
#include "fdh/io/point_cache.hpp"

namespace fdh::verify {
namespace fs = std::filesystem;

namespace {

using Lines = std::shared_ptr<const std::vector<int>>;

Lines gather(const std::vector<int>& lines, const std::vector<int>& at) {
  auto out = std::make_shared<std::vector<int>>();
  out->reserve(at.size());
  for (const int i : at) out->push_back(lines[std::size_t(i)]);
  return out;
}

std::vector<Vec3> gather(const std::vector<Vec3>& x, const std::vector<int>& at) {
  std::vector<Vec3> out;
  out.reserve(at.size());
  for (const int i : at) out.push_back(x[std::size_t(i)]);
  return out;
}

std::string object_list(const ObjFile& f) {
  std::string s;
  for (const ObjObject& o : f.objects)
    s += (s.empty() ? "" : ", ") +
         (o.name.empty() ? std::string("faces before any o or g") : "'" + printable(o.name) + "'");
  return s.empty() ? "none" : s;
}

// Two triangles with the same corners in the same cyclic order: the same face, the same way
// round, whichever corner an exporter lists first.
bool same_face(const Tri& a, const Tri& b) {
  for (int r = 0; r < 3; ++r)
    if (a[0] == b[std::size_t(r)] && a[1] == b[std::size_t((r + 1) % 3)] &&
        a[2] == b[std::size_t((r + 2) % 3)])
      return true;
  return false;
}

// A frame file's faces as the first frame has them: what every later frame must repeat.
class Shape {
 public:
  explicit Shape(const ObjFile& first)
      : file_(first.path), vertices_(first.x.size()), objects_(first.objects) {
    for (ObjObject& o : objects_) o.lines.clear();
  }
  const std::string& file() const { return file_; }

  void check(const ObjFile& f) const {
    if (f.x.size() != vertices_) {
      // The line of the first vertex too many, or of the last one there is.
      const bool more = f.x.size() > vertices_;
      const std::size_t at = more ? vertices_ : f.x.size() - 1;
      throw InputError(f.path, f.x.empty() ? 0 : f.vertex_lines[at],
                       std::to_string(f.x.size()) + " vertices, and " + printable(file_) + " has " +
                           std::to_string(vertices_) + "; every frame needs the same (" +
                           (more ? "the first vertex too many" : "the last vertex") + " is here)");
    }
    if (f.objects.size() != objects_.size())
      throw InputError(f.path, 0,
                       "objects " + object_list(f) + ", and " + printable(file_) + " has " +
                           std::to_string(objects_.size()) + "; every frame needs the same");
    long face = 0;
    for (std::size_t k = 0; k < objects_.size(); ++k) check_object(f, k, face);
  }

 private:
  void check_object(const ObjFile& f, std::size_t k, long& face) const {
    const ObjObject &want = objects_[k], &have = f.objects[k];
    if (want.name != have.name)
      throw InputError(f.path, have.lines.front(),
                       "object '" + printable(have.name) + "' where " + printable(file_) +
                           " has '" + printable(want.name) + "'");
    if (want.tris.size() != have.tris.size())
      throw InputError(f.path, 0,
                       std::to_string(have.tris.size()) + " triangles in object '" +
                           printable(have.name) + "', and " + printable(file_) + " has " +
                           std::to_string(want.tris.size()));
    for (std::size_t t = 0; t < want.tris.size(); ++t, ++face)
      if (!same_face(want.tris[t], have.tris[t]))
        throw InputError(
            f.path, have.lines[t],
            "face " + std::to_string(face + 1) + " differs from " + printable(file_) + "'s");
  }

  std::string file_;
  std::size_t vertices_;
  std::vector<ObjObject> objects_;
};

// Which of a frame file's vertices and triangles are the cloth's and which the obstacles'.
struct Split {
  std::vector<int> cloth_v, obstacle_v;  // file indices, in file order
  std::vector<Tri> cloth, obstacle;      // re-indexed
  std::vector<std::size_t> cloth_objects, obstacle_objects;
};

// The vertices the objects' faces use, in file order, and the faces re-indexed to them.
void take_objects(const ObjFile& f, const std::vector<std::size_t>& objects,
                  std::vector<int>& owner, int mark, std::vector<int>& used,
                  std::vector<Tri>& tris) {
  for (const std::size_t k : objects)
    for (std::size_t t = 0; t < f.objects[k].tris.size(); ++t)
      for (const int i : f.objects[k].tris[t]) {
        int& o = owner[std::size_t(i)];
        if (o != 0 && o != mark)
          throw InputError(
              f.path, f.objects[k].lines[t],
              "vertex " + std::to_string(i + 1) + " belongs to the cloth and to an obstacle");
        o = mark;
      }
  std::vector<int> index(f.x.size(), -1);
  for (std::size_t i = 0; i < f.x.size(); ++i)
    if (owner[i] == mark) index[i] = int(used.size()), used.push_back(int(i));
  for (const std::size_t k : objects)
    for (const Tri& t : f.objects[k].tris)
      tris.push_back(
          {index[std::size_t(t[0])], index[std::size_t(t[1])], index[std::size_t(t[2])]});
}

Split split(const ObjFile& f, const std::string& cloth) {
  Split s;
  if (cloth.empty()) {  // the whole file, every vertex included
    for (std::size_t k = 0; k < f.objects.size(); ++k) s.cloth_objects.push_back(k);
    for (std::size_t i = 0; i < f.x.size(); ++i) s.cloth_v.push_back(int(i));
    for (const ObjObject& o : f.objects)
      s.cloth.insert(s.cloth.end(), o.tris.begin(), o.tris.end());
    return s;
  }
  for (std::size_t k = 0; k < f.objects.size(); ++k)
    (f.objects[k].name == cloth ? s.cloth_objects : s.obstacle_objects).push_back(k);
  std::vector<int> owner(f.x.size(), 0);
  take_objects(f, s.cloth_objects, owner, 1, s.cloth_v, s.cloth);
  take_objects(f, s.obstacle_objects, owner, 2, s.obstacle_v, s.obstacle);
  return s;
}

// The lines of the faces of `objects`, in order.
Lines face_lines(const ObjFile& f, const std::vector<std::size_t>& objects) {
  auto out = std::make_shared<std::vector<int>>();
  for (const std::size_t k : objects)
    out->insert(out->end(), f.objects[k].lines.begin(), f.objects[k].lines.end());
  return out;
}

// No edge of the cloth in more than two triangles.
void check_manifold(const ObjFile& f, const Split& s) {
  std::vector<std::pair<std::uint64_t, int>> edges;  // (edge, triangle)
  edges.reserve(s.cloth.size() * 3);
  for (std::size_t t = 0; t < s.cloth.size(); ++t)
    for (int e = 0; e < 3; ++e) {
      const auto a = std::uint32_t(s.cloth[t][std::size_t(e)]);
      const auto b = std::uint32_t(s.cloth[t][std::size_t((e + 1) % 3)]);
      edges.push_back({(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b), int(t)});
    }
  std::sort(edges.begin(), edges.end());
  const Lines lines = face_lines(f, s.cloth_objects);
  for (std::size_t i = 2; i < edges.size(); ++i) {
    if (edges[i].first != edges[i - 2].first) continue;
    const auto a = int(edges[i].first >> 32), b = int(edges[i].first & 0xffffffffu);
    const int va = s.cloth_v[std::size_t(a)] + 1, vb = s.cloth_v[std::size_t(b)] + 1;
    throw InputError(f.path, (*lines)[std::size_t(edges[i].second)],
                     "non-manifold cloth: the edge between vertices " + std::to_string(va) +
                         " and " + std::to_string(vb) + " is in more than two triangles");
  }
}

// An obstacle file of its own: fixed (one file), or one file per frame (a folder).
struct ObstacleSource {
  std::vector<std::string> files;
  std::unique_ptr<Shape> shape;
  std::vector<Vec3> x;  // a fixed one's
  std::vector<Tri> tris;
  Lines vertex_lines, tri_lines;
  bool bytes = false;  // the places are byte offsets

  void take(const ObjFile& f) {
    x = f.x;
    vertex_lines = std::make_shared<std::vector<int>>(f.vertex_lines);
    std::vector<std::size_t> all;
    for (std::size_t k = 0; k < f.objects.size(); ++k) all.push_back(k);
    tri_lines = face_lines(f, all);
    bytes = f.byte_offsets;
  }
};

// "cache.pc2, frame 3": a cached frame's name, for messages and case files.
std::string cached_frame_name(const std::string& cache, int i) {
  return cache + ", frame " + std::to_string(i);
}

}  // namespace

struct MeshSequence::Impl {
  std::vector<std::string> files;  // a frame's name each (a cache's: cached_frame_name)
  std::string cloth_name;
  std::unique_ptr<Shape> shape;
  Split split;
  SequenceTopology topology;
  std::vector<ObstacleSource> obstacles;
  // Faces of more than three corners: the most in any one frame read so far (its frame file and
  // obstacle files), so that a later frame's quads are said too.
  mutable long polygons = 0;
  long fixed_polygons = 0;  // those of the obstacles that stand still
  std::vector<std::string> notes;
  std::optional<ObjFile> first;     // frame 0 as read for the checks, until read(0) takes it
  std::optional<PointCache> cache;  // the frames' positions, the faces those of `first`

  void read_first(const std::string& cloth);
  void open_cache();
  void add_obstacle(const std::string& arg);
  long add_obstacles(MeshFrame& m, int i) const;  // their polygons
  MeshFrame assemble(const ObjFile& f, std::vector<Vec3> x, int i) const;
};

void MeshSequence::Impl::read_first(const std::string& cloth) {
  first = read_mesh(files.front());
  const ObjFile& f = *first;
  if (f.objects.empty()) throw InputError(f.path, 0, "no faces");
  cloth_name = cloth;
  if (cloth.empty() && f.object("cloth")) cloth_name = "cloth";
  if (!cloth_name.empty() && !f.object(cloth_name))
    throw InputError(f.path, 0,
                     "no object named '" + printable(cloth_name) + "' (" +
                         (f.objects.size() == 1 && f.objects[0].name.empty()
                              ? std::string("the file has no o or g line; without --cloth the "
                                            "whole file is the cloth")
                              : "objects: " + object_list(f)) +
                         ")");
  split = verify::split(f, cloth_name);
  check_manifold(f, split);
  shape = std::make_unique<Shape>(f);
  polygons += f.polygons;
  topology.cloth_vertices = int(split.cloth_v.size());
  topology.cloth = split.cloth;
  topology.obstacle_vertices = int(split.obstacle_v.size());
  topology.obstacle = split.obstacle;
}

// MESH CACHE: frame 0 (`first`) is the mesh, kept for its faces; the cache gives the frames.
void MeshSequence::Impl::open_cache() {
  cache = open_point_cache(files[1]);
  const std::size_t n = first->x.size();
  if (std::size_t(cache->points) != n)
    throw InputError(cache->path, 0,
                     "byte " + std::string(cache->format == std::string("PC2") ? "16" : "4") +
                         ": " + std::to_string(cache->points) + " points, and " +
                         printable(first->path) + " has " + std::to_string(n) +
                         " vertices; a cache needs one point per vertex");
  const bool vowel = cache->format == std::string("MDD");  // "an MDD", "a PC2"
  notes.push_back(printable(cache->path) + (vowel ? ": an " : ": a ") + cache->format +
                  " point cache of " + std::to_string(cache->frames) + " frames, " +
                  std::to_string(cache->points) + " points; the faces are " +
                  printable(first->path) + "'s");
  files.clear();
  for (int i = 0; i < cache->frames; ++i) files.push_back(cached_frame_name(cache->path, i));
}

void MeshSequence::Impl::add_obstacle(const std::string& arg) {
  ObstacleSource o;
  o.files = frame_files({arg});
  const bool per_frame = o.files.size() > 1 || fs::is_directory(arg);
  if (per_frame && o.files.size() != files.size())
    throw InputError(arg, 0,
                     std::to_string(o.files.size()) + " obstacle frames for " +
                         std::to_string(files.size()) + " cloth frames");
  const ObjFile f = read_mesh(o.files.front());
  if (f.objects.empty()) throw InputError(f.path, 0, "no faces");
  polygons += f.polygons;
  const int base = topology.obstacle_vertices;
  for (const ObjObject& ob : f.objects)
    for (const Tri& t : ob.tris)
      topology.obstacle.push_back({t[0] + base, t[1] + base, t[2] + base});
  topology.obstacle_vertices += int(f.x.size());
  if (per_frame)
    o.shape = std::make_unique<Shape>(f);
  else
    o.take(f), fixed_polygons += f.polygons;
  obstacles.push_back(std::move(o));
}

long MeshSequence::Impl::add_obstacles(MeshFrame& m, int i) const {
  long polygons = fixed_polygons;
  for (const ObstacleSource& o : obstacles) {
    if (!o.shape) {
      m.obstacle.insert(m.obstacle.end(), o.x.begin(), o.x.end());
      m.obstacle_vertices.add(o.files.front(), o.vertex_lines, o.bytes);
      m.obstacle_tris.add(o.files.front(), o.tri_lines, o.bytes);
      continue;
    }
    ObstacleSource now;
    const ObjFile f = read_mesh(o.files[std::size_t(i)]);
    o.shape->check(f);
    now.take(f);
    polygons += f.polygons;
    m.obstacle.insert(m.obstacle.end(), now.x.begin(), now.x.end());
    m.obstacle_vertices.add(f.path, now.vertex_lines, now.bytes);
    m.obstacle_tris.add(f.path, now.tri_lines, now.bytes);
  }
  return polygons;
}

// Frame i from the faces and places of `f` and the positions `x` (f's own, or a cache's).
MeshFrame MeshSequence::Impl::assemble(const ObjFile& f, std::vector<Vec3> x, int i) const {
  const Split& s = split;
  const bool b = f.byte_offsets;
  MeshFrame m;
  m.index = i, m.file = files[std::size_t(i)];
  m.cloth = gather(x, s.cloth_v);
  m.obstacle = gather(x, s.obstacle_v);
  m.cloth_vertices.add(f.path, gather(f.vertex_lines, s.cloth_v), b);
  m.cloth_tris.add(f.path, face_lines(f, s.cloth_objects), b);
  m.obstacle_vertices.add(f.path, gather(f.vertex_lines, s.obstacle_v), b);
  m.obstacle_tris.add(f.path, face_lines(f, s.obstacle_objects), b);
  polygons = std::max(polygons, f.polygons + add_obstacles(m, i));
  return m;
}

MeshSequence::MeshSequence(const std::vector<std::string>& frames, const std::string& cloth,
                           const std::vector<std::string>& obstacles)
    : impl_(std::make_unique<Impl>()) {
  std::vector<std::string> fixed;
  impl_->files = frame_files(frames, &fixed, &impl_->notes);
  const bool cached = impl_->files.size() == 2 && is_point_cache(impl_->files[1]);
  for (std::size_t k = 0; k < impl_->files.size(); ++k)
    if (is_point_cache(impl_->files[k]) && !(cached && k == 1))
      throw InputError(impl_->files[k], 0,
                       "a point cache is audited with the mesh that gives its faces: fdhcert "
                       "audit MESH CACHE (one of each)");
  impl_->read_first(cloth);
  if (cached) impl_->open_cache();
  for (const std::string& o : fixed) impl_->add_obstacle(o);
  for (const std::string& o : obstacles) impl_->add_obstacle(o);
}

MeshSequence::~MeshSequence() = default;

int MeshSequence::frames() const {
  return int(impl_->files.size());
}
const std::vector<std::string>& MeshSequence::files() const {
  return impl_->files;
}
const SequenceTopology& MeshSequence::topology() const {
  return impl_->topology;
}
const std::string& MeshSequence::cloth_name() const {
  return impl_->cloth_name;
}
long MeshSequence::polygons() const {
  return impl_->polygons;
}
const std::vector<std::string>& MeshSequence::notes() const {
  return impl_->notes;
}

MeshFrame MeshSequence::read(int i) const {
  if (impl_->cache) return impl_->assemble(*impl_->first, read_cache_frame(*impl_->cache, i), i);
  std::optional<ObjFile> taken;
  if (i == 0 && impl_->first) taken.swap(impl_->first);  // read once, not twice
  ObjFile f = taken ? std::move(*taken) : read_mesh(impl_->files[std::size_t(i)]);
  impl_->shape->check(f);
  std::vector<Vec3> x = std::move(f.x);
  return impl_->assemble(f, std::move(x), i);
}

}  // namespace fdh::verify
