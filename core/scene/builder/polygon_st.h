// Texture coordinates on polygons: RI polygons have no parametrization, so a texture needs the
// request's "st" (or "s" and "t") primvars, of any storage class. Each face gets the affine map
// of its plane that fits its outer loop's corners (PolygonShape::fit_st).
#pragma once

#include <string>
#include <vector>

#include "core/geometry/surfaces/polygon.h"
#include "parser/param_list.h"

namespace darc {

// Fits the (s, t) that `params` gives the corners of each face (faces, loops and vertex indices
// as PointsGeneralPolygons has them; `world` the points) onto `shapes`, which came from those
// faces (PolygonShape::source_face). Returns a warning when a primvar is present but unusable
// (its size does not match its storage class: then no face gets coordinates), else "".
std::string fit_polygon_st(const ParamList& params, const std::vector<int>& nloops_per_face,
                           const std::vector<int>& nverts_per_loop, const std::vector<int>& indices,
                           const std::vector<Vec3f>& world, std::vector<PolygonShape>& shapes);

}  // namespace darc
