// The dome: light from every direction, infinitely far ("domelight", which PxrDomeLight maps to,
// and "envlight": shading/lights.h). Its radiance is L = intensity * lightcolor, times the
// lat-long "mapname" image when it has one (shading/latlong_map.h), oriented by the light's
// transform (rotation: +z of its own space is the map's top row). Not seen by camera rays; seen by
// reflected and refracted rays that leave the scene (Light::environment).
//
// Sampling, each sample's Cl being L / (pi pdf) (as for the area lights, so that RI's diffuse() of a matte of Kd 1 returns the
// radiance under a uniform dome: the furnace): a constant dome by the cosine about a surface's
// normal and uniformly over the sphere for a strand; a mapped dome by the map's importance
// (texels of luminance * sin theta), for surfaces and strands alike.
#pragma once

#include "core/math/matrix.h"
#include "shading/latlong_map.h"
#include "shading/lights.h"

#include <memory>

namespace darc {

std::unique_ptr<Light> make_dome_light(const Vec3f& radiance, int samples,
                                       const Matrix4& light_to_world = Matrix4::identity(),
                                       std::shared_ptr<const LatLongMap> map = nullptr);

}  // namespace darc
