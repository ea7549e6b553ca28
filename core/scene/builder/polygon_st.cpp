#include "core/scene/builder/polygon_st.h"

#include <fmt/format.h>

namespace darc {

namespace {

// One texture coordinate's values and how many numbers each element has ("st": 2, "s": 1).
struct Coordinate {
  const Param* param = nullptr;
  int stride = 1, offset = 0;
};

// The element of a primvar of `storage` class for corner j (its place in `indices`) of face f.
size_t element_of(StorageClass storage, size_t face, size_t j, int vertex) {
  switch (storage) {
    case StorageClass::Constant: return 0;
    case StorageClass::Uniform: return face;
    case StorageClass::FaceVarying:
    case StorageClass::FaceVertex: return j;
    case StorageClass::Varying:
    case StorageClass::Vertex: break;
  }
  return size_t(vertex);
}

// How many elements a primvar of `storage` needs.
size_t elements_needed(StorageClass storage, size_t faces, size_t corners, size_t points) {
  switch (storage) {
    case StorageClass::Constant: return 1;
    case StorageClass::Uniform: return faces;
    case StorageClass::FaceVarying:
    case StorageClass::FaceVertex: return corners;
    case StorageClass::Varying:
    case StorageClass::Vertex: break;
  }
  return points;
}

}  // namespace

std::string fit_polygon_st(const ParamList& params, const std::vector<int>& nloops_per_face,
                           const std::vector<int>& nverts_per_loop, const std::vector<int>& indices,
                           const std::vector<Vec3f>& world, std::vector<PolygonShape>& shapes) {
  Coordinate s, t;
  if (const Param* st = params.find("st")) {
    s = {st, 2, 0};
    t = {st, 2, 1};
  } else {
    s.param = params.find("s");
    t.param = params.find("t");
  }
  if (!s.param && !t.param) return "";
  for (const Coordinate* c : {&s, &t}) {
    if (!c->param) continue;
    const Param& p = *c->param;
    if (p.decl.is_string() || p.decl.components() != c->stride)
      return fmt::format("\"{}\" must have {} number{} per value, declared as {}: ignored", p.name, c->stride,
                         c->stride == 1 ? "" : "s", to_string(p.decl));
    const size_t needed = elements_needed(p.decl.storage, nloops_per_face.size(), indices.size(), world.size());
    if (p.floats.size() / size_t(c->stride) < needed)
      return fmt::format("\"{}\" ({}) has {} values, needs {}: ignored", p.name, to_string(p.decl.storage),
                         p.floats.size() / size_t(c->stride), needed);
  }
  auto value = [&](const Coordinate& c, size_t face, size_t j) -> float {
    if (!c.param) return 0.0f;  // "s" without "t" (or the reverse): the other is 0
    const size_t e = element_of(c.param->decl.storage, face, j, indices[j]);
    return c.param->floats[e * size_t(c.stride) + size_t(c.offset)];
  };
  // The first index of each face's outer loop and its length.
  std::vector<size_t> first(nloops_per_face.size()), count(nloops_per_face.size());
  size_t loop = 0, j = 0;
  for (size_t f = 0; f < nloops_per_face.size(); ++f) {
    first[f] = j;
    count[f] = size_t(nverts_per_loop[loop]);
    for (int k = 0; k < nloops_per_face[f]; ++k) j += size_t(nverts_per_loop[loop++]);
  }
  std::vector<Vec3f> corners;
  std::vector<float> ss, ts;
  for (PolygonShape& shape : shapes) {
    const size_t f = size_t(shape.source_face);
    corners.clear();
    ss.clear();
    ts.clear();
    for (size_t k = 0; k < count[f]; ++k) {
      const size_t at = first[f] + k;
      corners.push_back(world[size_t(indices[at])]);
      ss.push_back(value(s, f, at));
      ts.push_back(value(t, f, at));
    }
    shape.fit_st(corners, ss, ts);
  }
  return "";
}

}  // namespace darc
