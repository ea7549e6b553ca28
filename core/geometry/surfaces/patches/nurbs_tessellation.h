// RI NuPatch (RI Spec 3.2, section 5.4): a non-uniform rational B-spline surface of any order in
// each direction, lowered to triangles over its [umin, umax] x [vmin, vmax] part (as pbrt does for
// NURBS). Points and derivatives come from the Cox-de Boor recurrence on the homogeneous points.
#pragma once

#include <string>
#include <vector>

#include "core/geometry/surfaces/patches/parametric_grid.h"
#include "core/geometry/surfaces/triangle_mesh_data.h"

namespace darc {

// The largest order accepted: one evaluation costs order^2 per direction, so an order of 10^6 in
// a small file would hang the build; RenderMan exporters write orders 2 to 4, and modellers' caps
// are far below this (Maya's and Rhino's degree limits: 7 and 11).
inline constexpr int kMaxNurbsOrder = 32;

struct NurbsDirection {
  int n = 0;                  // control points
  int order = 0;              // degree + 1
  std::vector<double> knots;  // n + order values, non-decreasing
  double min = 0, max = 1;    // the part of the parameter range to draw
};

struct NurbsSurfaceDescription {
  NurbsDirection u, v;
  // u.n * v.n control points, u varying fastest, in object space, homogeneous as RI "Pw" ("P":
  // w = 1).
  std::vector<HomogeneousPoint> points;
};

// Checks the description: order 1 .. kMaxNurbsOrder, n >= order, n + order knots, non-decreasing,
// min < max within [knot[order - 1], knot[n]] (where the basis functions sum to 1), u.n * v.n
// finite points with positive weights. Returns false with error set to the first violation.
bool validate_nurbs(const NurbsSurfaceDescription& surface, std::string& error);

// The surface at (u, v) of its parameter domain, with exact first derivatives.
SurfaceSample evaluate_nurbs(const NurbsSurfaceDescription& surface, double u, double v);

// The triangles of the [min, max] part (parametric_grid.h: spans are the knot intervals, so a
// vertex lies on every knot line; uv are the request's own parameters). On invalid input returns
// an empty mesh and sets error.
TriangleMeshData tessellate_nurbs(const NurbsSurfaceDescription& surface, std::string& error, const DicingView* view = nullptr);

}  // namespace darc
