// The RI quadrics as triangle meshes, for motion blur: a sphere or other quadric that moves (a
// motion block of the same request with other numbers, a moving transform, a moving camera)
// becomes a moving triangle mesh, as patches and subdivision surfaces are (TriangleStore keys),
// since its analytic intersection has one placement. A still quadric stays analytic.
//
// The mesh is the spec's parametrization (quadric.h, sphere.h) on an nu x nv grid of (u, v),
// wound so that the right-hand normal is dP/du x dP/dv (what Orientation and Sides act on), with
// the parametric normal at each vertex for shading and (u, v) as its surface parameters.
#pragma once

#include "core/geometry/surfaces/dicing_view.h"
#include "core/geometry/surfaces/quadric.h"
#include "core/geometry/surfaces/sphere.h"
#include "core/geometry/surfaces/triangle_mesh_data.h"

namespace darc {

struct QuadricGrid {
  int nu = 16, nv = 1;  // grid intervals along u (theta) and v
};

// Intervals enough that a chord departs from the curved directions by at most a fiftieth of a
// pixel where `view` sees the surface, 32 to 1024 per full turn (64 without a view). A chord
// that cut a tenth of a pixel in took about 0.07 of the alpha of the pixels its silhouette
// crosses, and 3 % of the area of a disk 8 pixels wide.
QuadricGrid sphere_grid(const Sphere& sphere, const DicingView* view);
QuadricGrid quadric_grid(const Quadric& quadric, const DicingView* view);

// The object-space mesh (object_to_world is not applied: the caller moves it).
TriangleMeshData tessellate_sphere(const Sphere& sphere, QuadricGrid grid);
TriangleMeshData tessellate_quadric(const Quadric& quadric, QuadricGrid grid);

}  // namespace darc
