// Footprints of secondary rays (Igehy 1999, "Tracing ray differentials"): a reflected or
// refracted ray starts where the footprint landed (the interaction's dP/dx, dP/dy) and its
// direction changes across the footprint as the incoming direction and the normal do; a shadow
// ray keeps the footprint's size on its way to the light.
#pragma once

#include "core/scene/interaction.h"
#include "core/footprint/ray_footprint.h"

namespace darc {

// The perfect mirror direction of unit d about unit n.
inline Vec3f reflect(const Vec3f& d, const Vec3f& n) { return d - n * (2 * dot(d, n)); }

// The refraction of unit d through unit n (facing against d) with eta = n_from / n_to.
// Returns false on total internal reflection.
bool refract(const Vec3f& d, const Vec3f& n, float eta, Vec3f& out);

// The footprint of the ray reflected at `at` about n (unit, facing against d), where the
// incoming unit direction d had direction differentials ddx, ddy (the incoming footprint's).
// `dndx`, `dndy`: the change of n across the footprint (already facing-flipped as n was).
RayFootprint reflected_footprint(const Interaction& at, const Vec3f& d, const Vec3f& n, const Vec3f& dndx,
                                 const Vec3f& dndy, const RayFootprint& incoming);

// The footprint of the ray refracted at `at` (direction t, from refract(d, n, eta)).
RayFootprint refracted_footprint(const Interaction& at, const Vec3f& d, const Vec3f& n, const Vec3f& dndx,
                                 const Vec3f& dndy, float eta, const Vec3f& t, const RayFootprint& incoming);

// The footprint of a shadow ray from `at` along unit direction l: the footprint at the point,
// kept at that size toward the light (a point or distant light has no extent to grow toward).
RayFootprint shadow_footprint(const Interaction& at, const Vec3f& l, float min_radius);

}  // namespace darc
