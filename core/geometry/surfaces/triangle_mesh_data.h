// A tessellated surface as the geometry that is lowered to triangles produces it (bilinear and
// bicubic patches, NURBS, subdivision surfaces: DESIGN.md, "one geometry dispatch point"), in
// the object space of its request. SceneBuilder moves it to world space and adds it to the
// scene's one triangle store, so that the tracers see a single kind for all of them.
#pragma once

#include "core/math/vec.h"

#include <cstdint>
#include <vector>

namespace darc {

struct TriangleMeshData {
  std::vector<Vec3f> P;  // vertices
  // Per-vertex shading normals (the limit surface's), unit length; empty: flat shading.
  std::vector<Vec3f> N;
  // Per-vertex surface parameters (u, v) of the request (RI's parametric u and v); may be empty.
  std::vector<Vec2f> uv;
  // Three vertex indices per triangle, wound so that the right-hand normal (b - a) x (c - a)
  // points the way of the surface's numeric dP/du x dP/dv: the direction RI Orientation and
  // Sides then act on, as they do for the polygons' Newell normal and the sphere's.
  std::vector<uint32_t> indices;

  size_t triangle_count() const { return indices.size() / 3; }
};

}  // namespace darc
