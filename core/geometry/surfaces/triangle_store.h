// The scene's one store of triangles, world space: every surface that is lowered to triangles
// when the scene is built (patches, NURBS, subdivision surfaces) ends up here, so that the
// tracers see one kind for all of them (DESIGN.md, "one geometry dispatch point").
#pragma once

#include "core/math/bbox.h"
#include "core/math/ray.h"
#include "core/geometry/surfaces/surface_hit.h"
#include "core/geometry/surfaces/triangle_mesh_data.h"
#include "core/math/vec.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace darc {

class TriangleStore {
 public:
  // Adds a world-space mesh; returns how many of its triangles were kept (degenerate ones, of
  // zero area or with a non-finite vertex, are dropped). Its triangles are pieces of `layer`
  // (the scene builder gives their material, so that the patches of one surface, each its own
  // request, are one layer), or of a layer of their own.
  size_t add(const TriangleMeshData& world, std::optional<uint32_t> layer = std::nullopt);
  // Adds a moving mesh (motion blur): keys[k] is the mesh at shutter time times[k] (0 at open, 1
  // at close; times increase from 0 to 1), every key with keys[0]'s indices and parameters and as
  // many vertices; vertices move linearly between keys, and so do their normals (renormalised).
  // A triangle with a non-finite corner at any key is dropped, as add() drops it at one.
  size_t add_moving(std::span<const float> times, std::span<const TriangleMeshData> keys,
                    std::optional<uint32_t> layer = std::nullopt);

  size_t size() const { return corners_.size() / 3; }
  // The box of the triangle over the whole shutter (every key's corners when it moves).
  BBox bounds(uint32_t triangle) const;
  bool has_motion() const { return !motions_.empty(); }
  bool moving(uint32_t triangle) const;

  // Nearest hit with t in the open interval (ray.tmin, ray.tmax), with the triangle where it is at
  // ray.time: Moller-Trumbore in double
  // precision, so that the shared edges of a tessellated surface leave no visible pinholes.
  // hit.ng is the right-hand face normal; hit.u, hit.v the interpolated surface parameters
  // (the barycentrics when the mesh has none).
  bool intersect(uint32_t triangle, const Ray& ray, SurfaceHit& hit) const;

  // The triangle's corners a, b, c: the store's shared vertices, bitwise the same for every
  // triangle that uses them (what makes footprint coverage watertight along shared edges).
  // A moving triangle's corners at shutter time `time`: interpolated the same way for every
  // triangle that shares the vertex, so that they stay bitwise shared.
  Vec3f corner(uint32_t triangle, int k, float time = 0) const {
    return vertex_at(corners_[3 * size_t(triangle) + size_t(k)], time);
  }
  // The layer the triangle belongs to (SurfaceSet::layer): what add() was given, else which
  // add() it came from.
  uint32_t layer(uint32_t triangle) const { return layer_[triangle]; }

  // The unit face normal, (b - a) x (c - a) normalized (orientation not applied), at `time`.
  Vec3f face_normal(uint32_t triangle, float time = 0) const;

  // The shading normal at the point of the triangle's plane nearest p: the vertex normals
  // interpolated with p's barycentrics (clamped to the triangle), on the face normal's side;
  // the face normal when the mesh has no normals.
  Vec3f shading_normal(uint32_t triangle, const Vec3f& p, float time = 0) const;

  // The surface parameters (u, v) the mesh gave its vertices, at the point of the triangle's
  // plane nearest p (clamped to the triangle), and their changes along the footprint axes dx, dy.
  // False (nothing set) when the mesh gave none.
  bool parameters(uint32_t triangle, const Vec3f& p, const Vec3f& dx, const Vec3f& dy, Vec2f& uv, Vec2f& duv_dx,
                  Vec2f& duv_dy, float time = 0) const;

  size_t memory_bytes() const;

 private:
  // The barycentrics (of b and c) of the point of the triangle's plane nearest p.
  Vec2f barycentric(uint32_t triangle, const Vec3f& p, float time) const;
  // The plane coordinates (along b - a, c - a) of the offset w from corner a, clamped to the
  // triangle or not.
  Vec2f plane_coordinates(uint32_t triangle, const Vec3f& w_from_a, bool clamp, float time) const;
  // Vertex v (its normal) at shutter time `time`.
  Vec3f vertex_at(uint32_t v, float time) const;
  Vec3f normal_at(uint32_t v, float time) const;

  // How a moving mesh's vertices are stored: its key times start at motion_times_[times], and
  // the position of its vertex first_vertex + i at key k is motion_P_[positions + k * count + i]
  // (its normal at motion_N_[the same index], when the mesh has normals).
  struct MeshMotion {
    uint32_t times = 0, keys = 0, first_vertex = 0, count = 0;
    size_t positions = 0;
    bool normals = false;
  };
  static constexpr uint32_t kStaticVertex = 0xffffffffu;

  std::vector<Vec3f> P_, N_;    // vertices of all meshes; N_ parallel to P_ or empty per mesh
  std::vector<Vec2f> uv_;       // parallel to P_
  std::vector<uint32_t> corners_;  // 3 vertex indices per triangle
  std::vector<Vec3f> face_normal_;
  std::vector<uint8_t> smooth_;  // per triangle: kHasNormals | kHasParameters
  std::vector<uint32_t> layer_;  // per triangle
  uint32_t meshes_ = 0;          // add() calls so far
  // Motion blur: per vertex, an index into motions_ or kStaticVertex (empty while nothing moves).
  std::vector<uint32_t> vertex_motion_;
  std::vector<MeshMotion> motions_;
  std::vector<float> motion_times_;
  std::vector<Vec3f> motion_P_, motion_N_;
};

}  // namespace darc
