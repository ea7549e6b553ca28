// RI SubdivisionMesh lowered to triangles: the control mesh and its tags are checked, refined a
// fixed number of Catmull-Clark levels chosen from the mesh size, and the limit surface of the
// last level is emitted with limit normals (catmull_clark_refinement.h, catmull_clark_limit.h).
//
// Schemes: "catmull-clark"; "bilinear", the control mesh itself (faces fan-triangulated around
// their first vertex, flat shaded); "loop" (for triangle meshes) is not implemented and is
// refined with the Catmull-Clark rules instead, with a warning: the same control mesh gives a
// smooth surface of nearly the same shape (Catmull-Clark splits each triangle into three quads).
//
// Tags (RI 3.4 / PRMan):
//   "interpolateboundary" [mode] []: 0 none, 1 edges and corners (also when mode is omitted),
//       2 edges only. Edges and corners: boundary edges are infinitely sharp creases and a
//       boundary vertex with a single face is a corner; edges only: the corners are rounded.
//       Without the tag (PRMan's default) or with 0 the boundary is not interpolated: the faces
//       touching a boundary vertex, whose limit surface needs a ring of faces that is not there,
//       are not drawn (OpenSubdiv's VTX_BOUNDARY_NONE).
//   "crease" [v0 v1 ... vk] [s] (or k sharpnesses, one per edge): semi-sharp crease along the
//       chain of edges; the sharpness decreases by 1 per level, s >= 10 is infinitely sharp.
//   "corner" [v ...] [s] (or one per vertex): semi-sharp or (s >= 10) infinitely sharp vertices.
//   "hole" [f ...] []: faces that shape their neighbours but are not drawn.
// Other tags are ignored with a warning.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry/surfaces/dicing_view.h"
#include "core/geometry/surfaces/triangle_mesh_data.h"
#include "core/math/vec.h"

namespace darc {

// The arguments of a SubdivisionMesh request, P being its "P" (one point per vertex). nargs
// holds 3 counts per tag (integers, floats, strings; RI 3.4) or 2 (integers, floats; RI 3.2).
struct SubdivisionMeshRequest {
  std::string scheme;
  std::vector<int> nvertices;
  std::vector<int> vertices;
  std::vector<std::string> tags;
  std::vector<int> nargs;
  std::vector<int> intargs;
  std::vector<float> floatargs;
  std::vector<std::string> stringargs;
  std::vector<Vec3f> P;
  // Texture coordinates (s, t), at most one of the two: per vertex (RI "vertex" class,
  // subdivided like P) or per face corner in face order (every other class, written per corner
  // by the caller: subdivided linearly inside each face). The tessellation's uv are then (s, t).
  std::vector<Vec2f> vertex_st;
  std::vector<Vec2f> corner_st;
};

// The limit surface emits at most this many triangles per mesh: levels are dropped (down to one)
// until it fits. A million triangles keep a mesh's share of memory near 100 MB.
inline constexpr size_t kSubdivisionTriangleBudget = size_t(1) << 20;
// Four levels split each control quad into 16 x 16 facets: a silhouette chord then departs from
// the limit surface by about 0.2% of the face's size, under a pixel for faces up to ~500 pixels.
inline constexpr int kMaxSubdivisionLevels = 4;

struct SubdivisionTessellation {
  TriangleMeshData mesh;                        // object space; N empty for "bilinear"
  std::vector<uint32_t> triangle_control_face;  // the control face each triangle comes from
  int levels = 0;                               // Catmull-Clark levels applied
  std::vector<std::string> warnings;            // for the caller to report (ignored tags, ...)
  std::string error;                            // not empty: the request is invalid, mesh is empty

  bool ok() const { return error.empty(); }
};

// The levels a Catmull-Clark mesh with this many face corners (= quads after one level) gets:
// the most, up to kMaxSubdivisionLevels, whose triangles fit kSubdivisionTriangleBudget; at least 1.
int subdivision_levels_for(size_t control_corner_count);

// With a view, no more levels than bring the longest control edge down to kSubdivisionFacetPixels
// on the screen (each level halves it): a far or small mesh is not refined into facets far
// below a pixel. Never more levels than subdivision_levels_for gives; at least 1.
inline constexpr double kSubdivisionFacetPixels = 1.0;
int subdivision_levels_on_screen(double longest_edge_pixels, int levels_for_size);

SubdivisionTessellation tessellate_subdivision_mesh(const SubdivisionMeshRequest& request,
                                                    const DicingView* view = nullptr);

}  // namespace darc
