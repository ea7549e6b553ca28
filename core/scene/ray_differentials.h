// Footprints of secondary rays (Igehy 1999, "Tracing ray differentials"): a reflected or
// refracted ray starts where the footprint landed (the interaction's dP/dx, dP/dy) and its
// direction changes across the footprint as the incoming direction and the normal do; a shadow
// ray's footprint is what the light sees of the receiving footprint.
#pragma once

#include <limits>

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

// The footprint of a shadow ray from `at` toward a light `distance` away along its direction
// (infinity: a distant light): what the light sees of the receiving footprint. Its sub-rays
// start on the receiving patch (at.P + u dPdx + v dPdy, in the receiver's tangent plane, so that
// the receiver's own flat neighbourhood is never in the way). Toward a point or spot light they
// meet at the light: a pencil whose footprint shrinks to nothing there, so occluders near the
// light are tested against a small footprint and an occluder's shadow on the patch is the
// patch's exact box-filtered hard shadow. Toward a distant light they stay parallel: a prism of
// the patch, thinner where the light grazes it.
//
// `max_extent` bounds the patch's sides (dPdx, dPdy), keeping their direction. Where the camera
// grazes a surface (a silhouette) its footprint on the tangent plane grows without bound (a
// pixel at a teapot's rim spans 10x the pixel's width), while the piece the pixel shades covers
// only a sliver of it; the shadow ray of such a sliver would otherwise test every piece along the
// whole strip (measured on the vase: 3 % of the shadow rays made 60 % of the shadow work).
RayFootprint shadow_footprint(const Interaction& at, float distance, float min_radius,
                              float max_extent = std::numeric_limits<float>::infinity());

// Widens a shadow footprint toward a light at infinity by the cone of half-angle `half` around
// its unit direction l: sub-ray (u, v) leaves its patch point along l + u ddx + v ddy, a square of
// directions of side sqrt(pi) tan(half) per unit distance (the area of the cone's disc), so that
// the footprint's mean transmittance is the shadow averaged over the light's disc and the patch.
// Each sub-ray pairs one patch point with one direction, where the average wants every pair: the
// region the pairs sweep at distance t is the patch plus the cone's disc there, whose spread (a
// sum of independent offsets) is sqrt(patch^2 + (t side)^2) across. The cone's axes are the
// patch's turned by 90 degrees about l, so that |dox + t ddx| is exactly that and the footprint's
// area patch^2 + (t side)^2 (paired along the patch's own axes it would be (patch + t side)^2 and
// the occluders' share too small: a sphere inside the cone blocked 28 of 64 points for 33).
void widen_by_cone(RayFootprint& f, const Vec3f& l, float half);

}  // namespace darc
