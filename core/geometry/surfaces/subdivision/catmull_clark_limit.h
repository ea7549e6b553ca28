// The limit surface of a refined Catmull-Clark mesh, as triangles: every vertex moves to its
// limit position and gets its limit normal, then each drawn quad becomes two triangles.
//
// Limit masks (Halstead, Kass and DeRose 1993; the tangent masks as in Loop and Schaefer 2008):
// a smooth vertex of valence n with edge neighbours e_i and face-diagonal neighbours f_i goes to
// (n^2 v + 4 sum e_i + sum f_i) / (n (n + 5)); its two limit tangents weigh e_i by
// A cos(2 pi i / n) (sin) and f_i by cos(2 pi i / n) + cos(2 pi (i + 1) / n) (sin), with
// A = 1 + cos(2 pi / n) + cos(pi / n) sqrt(2 (9 + cos(2 pi / n))). A crease vertex goes to the
// cubic B-spline limit (a + 4 v + b) / 6 of its crease curve, a corner stays. Sharp edges that
// still have sharpness at the last level are treated as infinitely sharp.
//
// Along creases, boundaries and at corners the surface has one normal per side: a vertex there
// is emitted once per sector (the faces between two sharp edges), and a sector's normal is the
// area-weighted normal of the limit-position faces at the vertex (not an exact limit normal,
// which would need the one-sided tangent masks; at the final level's facet size the difference
// does not show).
#pragma once

#include <cstdint>
#include <vector>

#include "core/geometry/surfaces/subdivision/catmull_clark_refinement.h"
#include "core/geometry/surfaces/triangle_mesh_data.h"

namespace darc {

// level: a mesh of quads only (refined at least once). Appends to mesh (P, N, and uv when the
// level has texture coordinates: a vertex on a seam of a per-corner st map is emitted once per
// value) two triangles per
// face that is not hidden, quad (a, b, c, d) as (a, b, c) and (a, c, d) so that they wind as the
// face does, and the control face of each triangle to triangle_control_face.
void append_limit_triangles(const SubdivisionLevel& level, TriangleMeshData& mesh,
                            std::vector<uint32_t>& triangle_control_face);

}  // namespace darc
