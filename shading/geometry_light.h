// An RI AreaLightSource: the geometry of its attribute block sends light (RI Spec 3.2,
// RiAreaLightSource). Its radiance is the light shader's intensity * lightcolor, the colour the
// geometry is drawn with (make_area_light_surface), sent from the side its normal N faces (the
// classic arealight shader's illuminate(P, N, PI/2); Orientation and ReverseOrientation turn it).
// Spheres (whole) and planar convex pieces (polygons, mesh faces, the triangles of patches and
// subdivision surfaces) emit; other quadrics and non-convex polygons are drawn emissive but send
// nothing (one warning). The pieces are sampled by area, a sample's Cl being radiance * (solid
// angle it stands for) / pi as for darc's other area lights (shading/area_lights.h).
#pragma once

#include "core/scene/scene.h"
#include "parser/diagnostics.h"
#include "shading/lights.h"

#include <memory>

namespace darc {

// The light of scene.lights[index] (a LightDesc with `geometry`), from the surfaces whose
// material names it.
std::unique_ptr<Light> make_geometry_light(const Scene& scene, uint32_t index, Diagnostics& diag);

}  // namespace darc
