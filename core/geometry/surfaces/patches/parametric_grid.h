// The triangulation shared by every parametric surface that is lowered to triangles (patch
// meshes, NURBS): the surface is a rectangle of spans (one patch of a mesh, one pair of knot
// intervals of a NURBS), each evaluated exactly with its first derivatives; a grid of vertices is
// laid over it whose density follows the surface and, given a DicingView, the screen (no finer
// than the frame can show: see the screen rules below), and the grid is cut into triangles.
//
// Every span column has one u segment count (the largest its spans need) and every span row one
// v count, so that two spans meeting at an edge sample it at the same parameters and share the
// vertices themselves: no cracks between patches, by construction.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/geometry/surfaces/dicing_view.h"
#include "core/geometry/surfaces/triangle_mesh_data.h"
#include "core/math/vec.h"

namespace darc {

// A control point as RI "Pw" gives it: (x, y, z, w) stands for the point (x/w, y/w, z/w).
// "P" is w = 1.
struct HomogeneousPoint {
  Vec3d xyz;
  double w = 1;
};

// Every point finite with a weight w > 0 (0 puts a point at infinity, a negative weight lets the
// surface pass through infinity); else false with error naming the first bad point.
bool valid_control_points(const std::vector<HomogeneousPoint>& points, std::string& error);

// One evaluation of a surface: the point and its exact first parametric derivatives.
struct SurfaceSample {
  Vec3d P, dPdu, dPdv;
};

// The point and derivatives of a rational surface from those of its homogeneous form
// (H, dH/du, dH/dv with weights w, dw/du, dw/dv): P = H / w, dP = (dH - P dw) / w. w > 0.
SurfaceSample rational_sample(const HomogeneousPoint& H, const HomogeneousPoint& dHdu, const HomogeneousPoint& dHdv);

// The spans of a surface: span (i, j) covers [u_edges[i], u_edges[i+1]] x [v_edges[j],
// v_edges[j+1]] of the request's own parameters (which become TriangleMeshData::uv).
// A closed direction (a periodic patch mesh) joins its last edge to its first: the vertices of
// that seam are shared as well, so the surface closes without a crack.
struct SpanLayout {
  std::vector<double> u_edges, v_edges;  // strictly increasing, at least 2 each
  bool u_closed = false, v_closed = false;
};

// Evaluates span (i, j) at the request's parameters (u, v), which lie within that span (its
// edges included: a span is evaluated at its own boundary, never its neighbour's formula).
using SpanEvaluator = std::function<SurfaceSample(int i, int j, double u, double v)>;

// ---- Density (the same constants for every surface kind) ----

// A flat triangle may deviate from the surface by this fraction of its span's size (the diagonal
// of the span's bounding box): 1e-3 of a ground patch 100 units wide is 0.1 units, of a sphere
// seen 500 pixels wide, half a pixel at most, and in practice the normal rule below is finer.
inline constexpr double kMaxDeviationFraction = 1e-3;
// The normals at the two ends of a triangle edge (a cell's side or its diagonal) may turn by at
// most this (radians; 4 degrees): interpolated normals then shade a sphere without visible facets,
// and its silhouette deviates from the circle by r (1 - cos 2 deg), 6e-4 r. A quarter of a sphere
// gets 32 segments each way, as does a quarter of a cylinder around it.
inline constexpr double kMaxNormalTurn = 4.0 * 3.14159265358979323846 / 180.0;
// Each span is probed on this many intervals per direction to estimate its curvature: a bicubic's
// second derivative is linear in each parameter, so its largest value is within 1/8 of a span of
// a probe, and the estimate is off by a few percent at most (NURBS of high order rarely bend more
// than that within one knot interval).
inline constexpr int kProbeIntervals = 8;
// At most this many segments per span and direction (8192 triangles per span): about 1.4 degrees
// per segment over a quarter circle, far finer than the rules above ask of any sane surface; it
// only bounds what a wild control net (points 1e6 apart in a unit patch) can allocate.
inline constexpr int kMaxSegmentsPerSpan = 64;
// The grid of one request is coarsened (every span's count scaled down together) above this many
// vertices (about 70 MB of vertex data): the per-column maximum of a mesh with thousands of
// columns and rows could otherwise multiply into billions. A mesh with more spans than this
// still gets one segment per span: its size is then that of the input.
inline constexpr size_t kMaxVerticesPerSurface = size_t(1) << 21;

// ---- Density on the screen (with a DicingView; each only ever lowers the counts above) ----

// A flat triangle may deviate from the surface by this many pixels where the span is nearest
// the eye: a silhouette's coverage is then off by at most this fraction of a pixel along it.
inline constexpr double kMaxDeviationPixels = 0.05;
// Where the deviation allows, a segment spans at least this many pixels: the normal rule above
// only refines segments longer than that (normals are interpolated across a triangle, and a
// facet of a pixel shows no facet; RenderMan's micropolygons are a pixel at ShadingRate 1).
// Measured on the Aqsis vase (frame 3, 256x192): 2 pixels rendered 20 % faster at the same
// error against a 16x16 reference, but a NURBS sphere 33 pixels wide then lost 0.25 % of its
// alpha to the chords (PatchSurface.NurbsSphereHasTheSpheresSilhouetteAndShading allows 0.2 %).
inline constexpr double kMinSegmentPixels = 1.0;

// The segment counts per span column and per span row that the rules above ask of the surface
// (the surface rules alone without a view).
struct GridDensity {
  std::vector<int> u_segments, v_segments;
};
GridDensity choose_grid_density(const SpanLayout& layout, const SpanEvaluator& evaluate,
                                const DicingView* view = nullptr);

// Triangulates the surface at that density: vertices P with unit normals N (dP/du x dP/dv,
// averaged over the spans that share a vertex; from a point just inside the span where the
// derivatives vanish, as at a sphere's pole) and the request's (u, v); two triangles per grid
// cell wound so that their normal is dP/du x dP/dv.
TriangleMeshData triangulate_grid(const SpanLayout& layout, const SpanEvaluator& evaluate, const GridDensity& density);

// choose_grid_density, then triangulate_grid.
TriangleMeshData tessellate_spans(const SpanLayout& layout, const SpanEvaluator& evaluate,
                                  const DicingView* view = nullptr);

}  // namespace darc
