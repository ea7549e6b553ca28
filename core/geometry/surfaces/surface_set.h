// Every surface of a frame behind one interface: the tracers ask it for bounds, hits, normals
// and materials by surface index and never switch over the kinds themselves (DESIGN.md, "one
// geometry dispatch point"). Analytic quadrics stay analytic here; patches, NURBS and
// subdivision surfaces arrive as triangles. Surface index order: all spheres, then all
// polygons, then all triangles, then the other quadrics (the order the acceleration structure
// is built in).
#pragma once

#include "core/footprint/polygon_coverage.h"
#include "core/math/bbox.h"
#include "core/math/texture_coordinates.h"
#include "core/geometry/surfaces/polygon.h"
#include "core/geometry/surfaces/quadric.h"
#include "core/math/ray.h"
#include "core/geometry/surfaces/sphere.h"
#include "core/geometry/surfaces/surface_hit.h"
#include "core/geometry/surfaces/triangle_store.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace darc {

// The layer of a surface that is not a piece of a larger one: never merged with another.
inline constexpr uint32_t kNoLayer = 0xffffffffu;

// A planar convex surface (a triangle, a polygon of one convex loop) as footprint coverage
// sees it: its corners in order, and the layer it belongs to (the mesh: pieces of one layer that
// meet in a footprint are one fragment there).
struct ConvexOutline {
  std::array<Vec3f, kMaxPolygonCorners> corners;
  int count = 0;
  uint32_t layer = kNoLayer;
  std::span<const Vec3f> span() const { return {corners.data(), size_t(count)}; }
};

struct SurfaceSet {
  enum class Kind { Sphere, Polygon, Triangle, Quadric };

  std::vector<Sphere> spheres;
  std::vector<PolygonShape> polygons;
  TriangleStore triangles;
  std::vector<Quadric> quadrics;  // Cone, Cylinder, Disk, Paraboloid, Hyperboloid, Torus
  // Per shape of each kind: an index into Scene::materials.
  std::vector<uint32_t> sphere_material, polygon_material, triangle_material, quadric_material;

  size_t size() const { return spheres.size() + polygons.size() + triangles.size() + quadrics.size(); }
  // Motion blur: whether any surface moves during the shutter (only triangles do: tessellated
  // surfaces and polygon meshes under a moving transform or with motion samples).
  bool has_motion() const { return triangles.has_motion(); }
  bool moving(uint32_t surface) const {
    uint32_t i;
    return triangles.has_motion() && locate(surface, i) == Kind::Triangle && triangles.moving(i);
  }
  bool empty() const { return size() == 0; }

  // The kind of surface `surface` and its index among that kind.
  Kind locate(uint32_t surface, uint32_t& local) const {
    const uint32_t ns = uint32_t(spheres.size()), np = uint32_t(polygons.size());
    if (surface < ns) { local = surface; return Kind::Sphere; }
    if (surface < ns + np) { local = surface - ns; return Kind::Polygon; }
    const uint32_t nt = uint32_t(triangles.size());
    if (surface < ns + np + nt) { local = surface - ns - np; return Kind::Triangle; }
    local = surface - ns - np - nt;
    return Kind::Quadric;
  }

  BBox bounds(uint32_t surface) const;
  uint32_t material(uint32_t surface) const;
  // Nearest hit with t in (ray.tmin, ray.tmax). hit.ng is the surface's own normal, orientation
  // not applied (the caller applies Material::flip_normals and Sides).
  bool intersect(uint32_t surface, const Ray& ray, SurfaceHit& hit) const;
  // The geometric normal (as intersect gives it) at p, a point on or next to the surface, where
  // the surface is at shutter time `time` (as are the outline, shading normal and texture
  // coordinates below: only moving triangles depend on it).
  Vec3f geometric_normal(uint32_t surface, const Vec3f& p, float time = 0) const;
  // True for planar surfaces (polygons, triangles, disks): a ray leaving one cannot hit it again.
  bool is_flat(uint32_t surface) const {
    uint32_t i;
    const Kind kind = locate(surface, i);
    return kind == Kind::Quadric ? quadrics[i].flat : kind != Kind::Sphere;
  }
  // True for the triangles of tessellated surfaces and the faces of polygon meshes: pieces of a
  // larger surface, often smaller than a ray's footprint, which together cover it without gaps.
  bool is_piece(uint32_t surface) const {
    uint32_t i;
    const Kind kind = locate(surface, i);
    return kind == Kind::Triangle || (kind == Kind::Polygon && polygons[i].piece);
  }
  // The outline of `surface` when it is planar and convex (every triangle; a polygon of one
  // convex loop with at most kMaxPolygonCorners corners); false for everything else.
  bool convex_outline(uint32_t surface, ConvexOutline& out, float time = 0) const;
  // The ball `surface` is, when it is a whole sphere placed by a similarity (Sphere::whole_ball);
  // false for everything else.
  bool whole_ball(uint32_t surface, Vec3d& centre, double& radius) const {
    uint32_t i;
    return locate(surface, i) == Kind::Sphere && spheres[i].whole_ball(centre, radius);
  }
  // The layer `surface` is a piece of (its material, as the scene builder gives it: the patches
  // of one surface, each its own request, meet without a seam); kNoLayer for a surface on its own.
  uint32_t layer(uint32_t surface) const;
  // The normal shading uses at p: the geometric one, except on triangles with vertex normals.
  Vec3f shading_normal(uint32_t surface, const Vec3f& p, float time = 0) const;
  // The texture coordinates at p (a point on the surface) and their changes along the
  // footprint axes dx, dy. Parametric surfaces (spheres, quadrics, and patches and NURBS through
  // their triangles) map their (u, v) through `uv_to_st` (RI TextureCoordinates: the (s, t) of
  // the corners (0,0), (1,0), (0,1), (1,1), bilinear between them); polygons give the st of their
  // corners (PolygonShape::has_st); everything else s = t = 0.
  TextureCoordinates texture_coordinates(uint32_t surface, const Vec3f& p, const Vec3f& dx, const Vec3f& dy,
                                         const std::array<float, 8>& uv_to_st, float time = 0) const;
};

}  // namespace darc
