// Lights with extent: a shape of uniform radiance L, one-sided where it is flat. They are
// sampled (Light::samples, Light::sample): each sample is a point of the shape seen from the
// shading point, with Cl = L * (solid angle the sample stands for) / pi, so that RI's diffuse()
// (which carries no 1/pi: a matte of Kd 1 returns Cl) gives a Lambertian surface its physical
// radiance, rho * E / pi, and chianghair's pi * S * Cl gives S * E (lookdev.md §2.1, §2.4).
//
// Shapes (in the light's own space, placed by its transform; RenderMan's RIS lights, whose
// bridges show they emit along +z: lookdev.md §2.2):
// - "rectlight" (PxrRectLight): the unit square of the xy plane, centred, emitting toward +z;
// - "disklight" (PxrDiskLight): the disc of diameter 1 in the xy plane, emitting toward +z;
// - "spherelight" (PxrSphereLight): the sphere of diameter 1 (its radius is that of the sphere
//   of the same volume under a non-uniform scale), emitting everywhere.
// The dome, which has no shape, is shading/dome_light.h.
// Sampling: the rectangle by solid angle (spherical rectangles, Urena et al. 2013; by area when
// it is sheared into a parallelogram or subtends under 1e-3 sr), the disc by area (through the
// concentric map, so that strata stay compact), the sphere by the cone it subtends (uniform in
// solid angle).
#pragma once

#include "core/math/matrix.h"
#include "shading/lights.h"

#include <memory>
#include <string>

namespace darc {

// The default samples per shading point of an area light ("int nsamples").
inline constexpr int kDefaultAreaLightSamples = 16;

enum class AreaShape { Rect, Disk, Sphere };

// `radiance`: intensity * lightcolor (already divided by the area with areaNormalize).
std::unique_ptr<Light> make_area_light(AreaShape shape, const Matrix4& light_to_world, const Vec3f& radiance,
                                       int samples);

// The shape of a darc light shader name ("rectlight", "disklight", "spherelight"); false for others.
bool area_shape_of(const std::string& shader, AreaShape& shape);

}  // namespace darc
