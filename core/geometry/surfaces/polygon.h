// Planar polygons with holes (RI Polygon, GeneralPolygon, PointsPolygons,
// PointsGeneralPolygons), intersected directly without triangulation: the ray meets the plane,
// then an even-odd point-in-polygon test over all loops decides, in 2D.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/math/bbox.h"
#include "core/math/ray.h"
#include "core/geometry/surfaces/surface_hit.h"
#include "core/math/vec.h"

namespace darc {

// A face is non-planar when a point lies further than this fraction of the face's bounding-box
// diagonal from its Newell plane: well above float rounding of modelled coordinates (~1e-7),
// well below any bend a viewer could see.
inline constexpr double kNonPlanarTolerance = 1e-4;

struct PolygonShape {
  // Unit plane normal from Newell's method on the outer loop. It follows the vertex order by
  // the right-hand rule of the coordinate axes: seen from the side the normal points to, the
  // outer loop runs counter-clockwise (for a convex polygon it equals (p1-p0) x (p2-p0)). In
  // RenderMan's left-handed spaces the caller applies Orientation to decide which side is "outside".
  Vec3f normal;
  double plane_offset = 0;  // dot(normal, p) for points p on the plane
  int drop_axis = 2;        // axis with the largest |normal| component, dropped for the 2D test
  // Every loop (outer first, then holes) projected to the two kept axes ((drop_axis + 1) % 3,
  // (drop_axis + 2) % 3), concatenated; loop k is points_2d[loop_starts[k] .. loop_starts[k+1]).
  std::vector<Vec2f> points_2d;
  std::vector<uint32_t> loop_starts;
  BBox box;  // bounds of every loop's points
  // Index of the face this shape came from (PointsPolygons / PointsGeneralPolygons), so that the
  // caller can find uniform and vertex data; 0 for shapes built directly with make().
  int source_face = 0;
  // One of several faces of a mesh, which together make one surface (set by the scene builder).
  bool piece = false;
  // The layer a piece belongs to (SurfaceSet::layer: the scene builder gives its material).
  uint32_t layer = 0;
  // The outer loop's world-space corners when the polygon is one convex loop (footprint
  // coverage works on them, SurfaceSet::convex_outline); empty otherwise.
  std::vector<Vec3f> convex_corners;

  // The texture coordinates the request gave the face's corners (its "st", "s" and "t"), as
  // the affine map of the plane that fits them best: s(p) = dot(s_gradient, p) + s_offset, the
  // same for t (exact when the corners' coordinates are affine in their positions, as on a
  // triangle or a parallelogram; a polygon has no RI parametrization to interpolate otherwise).
  // Without them, s = t = 0.
  bool has_st = false;
  Vec3f s_gradient, t_gradient;
  float s_offset = 0, t_offset = 0;

  // Sets the map above from the face's corners and their (s, t); false (nothing set) when the
  // corners span no plane.
  bool fit_st(const std::vector<Vec3f>& corners, const std::vector<float>& s, const std::vector<float>& t);

  // loops_world[0] is the outer boundary, the others are holes (all in world space). Holes
  // with fewer than 3 points are ignored. Returns nullopt for a degenerate polygon: fewer than
  // 3 outer points, (near) zero area, or a non-finite coordinate. Points are assumed coplanar
  // (see make_face_shapes for non-planar input).
  static std::optional<PolygonShape> make(const std::vector<std::vector<Vec3f>>& loops_world);

  BBox bounds() const { return box; }

  // Nearest hit with t in the open interval (ray.tmin, ray.tmax). Points inside an odd number
  // of loops are inside (even-odd rule), so a point in a hole misses. u = v = 0.
  bool intersect(const Ray& ray, SurfaceHit& hit) const;

  // True when the 2D point (in the kept axes) is inside by the even-odd rule.
  bool contains_2d(float x, float y) const;
};

// The shapes for one face: a single PolygonShape, or, when a single-loop face is not planar
// (some point further than kNonPlanarTolerance * its extent from the Newell plane), a triangle
// fan around its first vertex so that every piece is planar. Faces with holes are never split
// (they are projected onto their Newell plane as they are). Degenerate faces (and degenerate
// fan triangles) give no shape. Each shape gets source_face.
std::vector<PolygonShape> make_face_shapes(const std::vector<std::vector<Vec3f>>& loops_world, int source_face);

// PointsGeneralPolygons: face f has nloops_per_face[f] loops, loop k has nverts_per_loop[k]
// vertices, taken in order from indices, which point into P_world. Every count and index is
// validated first; on a violation returns an empty vector and sets error (e.g.
// "vertex index 17 out of range (13 points)"). Degenerate faces are dropped without error.
std::vector<PolygonShape> make_points_general_polygons(const std::vector<int>& nloops_per_face,
                                                       const std::vector<int>& nverts_per_loop,
                                                       const std::vector<int>& indices,
                                                       const std::vector<Vec3f>& P_world, std::string& error);

// PointsPolygons: the same with one loop per face.
std::vector<PolygonShape> make_points_polygons(const std::vector<int>& nverts_per_face, const std::vector<int>& indices,
                                               const std::vector<Vec3f>& P_world, std::string& error);

}  // namespace darc
