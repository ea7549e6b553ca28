// What a hit is, built once from {primitive, t, u} and the ray that found it: the point, its
// normals, colour and opacity, the material, and the ray's footprint transferred to the point
// with the normal's change across it (Igehy 1999), which reflected and refracted rays need to
// carry their own differentials. The hiders keep only {primitive, t, u} per hit and build this
// in one place (DESIGN.md, "the interaction is built once from the hit").
#pragma once

#include "core/math/ray.h"
#include "core/math/texture_coordinates.h"
#include "core/footprint/ray_footprint.h"
#include "core/scene/scene.h"

#include <cstdint>

namespace darc {

struct Interaction {
  uint32_t primitive = 0;  // the accelerator's primitive index
  uint32_t material = 0;
  uint32_t strand = kNoStrand;  // the curve strand hit (kNoStrand on surfaces)
  bool is_curve = false;
  float t = 0;  // along the ray that found it
  // The ray's shutter time and whether it stands for the whole shutter (Ray): rays leaving the
  // point (shadows, reflections) see the scene as it did.
  float time = 0;
  bool sweeps_shutter = false;
  float sweep_from = 0, sweep_to = 1;
  float u = 0;  // along a curve segment; surface parameters where the surface has them
  float v = 0;
  Vec3f P;
  // Surfaces: the geometric normal, orientation applied (not face-forwarded). Curves: the ribbon
  // normal of an oriented ("N") curve, else facing the ray (a tube seen from the ray).
  Vec3f N;
  Vec3f Cs, Os;
  Vec3f dPdv;  // unit tangent along a curve; zero on surfaces
  // The footprint at P: the ray's differentials moved to the hit (on the surface's tangent plane;
  // for curves on the plane through P perpendicular to the ray), and how N changes across them.
  // All zero when the ray had no footprint.
  Vec3f dPdx, dPdy;
  Vec3f dNdx, dNdy;
  // Texture coordinates at P and their changes across the footprint (SurfaceSet::
  // texture_coordinates; on curves their "st" along the strand) when the material reads textures
  // (Material::reads_textures); zero otherwise, and on points, which have none yet.
  TextureCoordinates st;
};

// Where a strand seen through a footprint is shaded across its width: on the band centred on its
// axis (where the whole strand is), or where `ray` crosses it (the part of it the footprint sees
// past what is in front, see ABuffer::at_visible_part), kept inside its width. `seen_share`: the
// part of the strand's coverage the footprint sees; the band rays leave is that much narrower.
enum class StrandShadingPoint { BandCentre, WhereTheRayCrosses };

// Builds the interaction of `ray` with primitive `primitive` at `t` (u: along a curve segment).
// `footprint` may be null (exact rays of the stochastic hider): no differentials then.
Interaction make_interaction(const Scene& scene, uint32_t primitive, const Ray& ray, float t, float u,
                             const RayFootprint* footprint,
                             StrandShadingPoint strand_point = StrandShadingPoint::BandCentre, float seen_share = 1.0f);

}  // namespace darc
