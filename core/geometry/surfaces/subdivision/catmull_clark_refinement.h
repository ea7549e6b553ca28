// One step of Catmull-Clark subdivision with sharp and semi-sharp creases (DeRose, Kass and
// Truong 1998, "Subdivision Surfaces in Character Animation"; the rules PRMan and OpenSubdiv
// use, with sharpness decreasing by 1 per level). A face of n vertices becomes n quads, so after
// one step every face is a quad.
#pragma once

#include <cstdint>
#include <vector>

#include "core/geometry/surfaces/subdivision/subdivision_topology.h"
#include "core/math/vec.h"

namespace darc {

// Edges and vertices at least this sharp are infinitely sharp: their sharpness never decreases
// (PRMan's and OpenSubdiv's convention, Sdc::Crease::SHARPNESS_INFINITE).
inline constexpr float kInfiniteSharpness = 10.0f;

// A mesh at one level of refinement, with everything the next level needs.
struct SubdivisionLevel {
  SubdivisionTopology topology;
  std::vector<Vec3d> points;            // one per vertex
  std::vector<float> edge_sharpness;    // one per edge; 0: smooth
  std::vector<float> vertex_sharpness;  // one per vertex (RI "corner"); 0: not a corner
  // One per face: refined like the others (it shapes its neighbours) but not drawn ("hole"
  // faces, and faces on a boundary that is not interpolated). Children inherit it.
  std::vector<uint8_t> face_hidden;
  std::vector<uint32_t> face_control_face;  // the control face each face descends from
  // Texture coordinates (s, t, 0), when the mesh has them: either per vertex, subdivided by the
  // same rules as the points (RI "vertex" class), or per corner (face by face, as the topology
  // numbers corners), subdivided linearly inside each face (RI "varying", "facevarying",
  // "uniform" and "constant" classes, all written per corner). At most one is not empty.
  std::vector<Vec3d> vertex_st;
  std::vector<Vec3d> corner_st;
};

// The sharpness an edge or vertex of sharpness s has one level finer.
inline float refined_sharpness(float s) { return s >= kInfiniteSharpness ? s : (s > 1.0f ? s - 1.0f : 0.0f); }

// Which rule moves a vertex (and which limit mask applies): smooth with fewer than two sharp
// edges (a "dart" with one), crease along exactly two, corner with three or more or when the
// vertex itself is sharp.
enum class VertexRule { Smooth, Crease, Corner };
inline VertexRule vertex_rule(int sharp_edge_count, float vertex_sharpness) {
  if (vertex_sharpness > 0.0f || sharp_edge_count > 2) return VertexRule::Corner;
  return sharp_edge_count == 2 ? VertexRule::Crease : VertexRule::Smooth;
}

// Boundary edges are always infinitely sharp: the caller sets that on the control level, so the
// rules here never see an edge with one face that is smooth.
//
// Child vertex numbering: the vertex points of the parent vertices first (same indices), then
// one edge point per parent edge, then one face point per parent face. Child face k of parent
// face f (in corner order) is (vertex point of corner k, edge point of corner k's edge, face
// point, edge point of the previous corner's edge): it turns the same way as its parent, so
// orientation is kept.
SubdivisionLevel refine_catmull_clark(const SubdivisionLevel& parent);

}  // namespace darc
