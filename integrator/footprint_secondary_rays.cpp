#include "integrator/footprint_secondary_rays.h"

#include "core/scene/ray_differentials.h"
#include "integrator/hit_filter.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace darc {

namespace {

// How much longer than the incoming footprint is wide a shadow ray's receiving patch may be
// (the stretch of a surface seen about 83 degrees from its normal; footprint-everything.md §2.5).
constexpr float kShadowPatchElongation = 2;

}  // namespace

Vec3f FootprintSecondaryRays::shadow_transmittance(const Interaction& at, const Vec3f& l, float distance,
                                                   const RayFootprint* incoming, const PathState& path) {
  const SecondaryRaySettings& s = ctx_.base.secondary;
  Ray ray{at.P, l, s.ray_offset, distance};
  ray.time = at.time;
  ray.sweeps_shutter = at.sweeps_shutter;
  ray.sweep_from = at.sweep_from;
  ray.sweep_to = at.sweep_to;
  // The receiving patch at most kShadowPatchElongation times the incoming footprint's width
  // at P.
  const float max_extent =
      incoming ? kShadowPatchElongation * std::max(length(incoming->dox + incoming->ddx * at.t),
                                                   length(incoming->doy + incoming->ddy * at.t))
               : std::numeric_limits<float>::infinity();
  if (seen_ && !at.is_curve && length(seen_->dPdx) <= max_extent && length(seen_->dPdy) <= max_extent)
    return seen_surface_transmittance(at, l, distance, path);
  RayFootprint footprint = shadow_footprint(at, distance, ctx_.min_radius, max_extent);
  if (cone_ > 0) widen_by_cone(footprint, l, cone_);
  HitFilter filter = shadow_filter(at);
  uint32_t local;
  if (!at.is_curve && ctx_.base.scene.prim_kind(at.primitive, local) == Scene::PrimKind::Surface) {
    // The start point's own mesh, within a few footprint radii, is the start point itself.
    filter.origin_layer = ctx_.base.scene.surfaces.layer(local);
    filter.origin_layer_min_t = 4 * footprint.reach(0);
  }
  return trace_footprint_transmittance(ctx_, ray, footprint, counters_,
                                       scratch_.at(size_t(path.depth) + 1), filter,
                                       stopping_transmittance(s, path.weight, kDistanceMinTransmittance));
}

bool FootprintSecondaryRays::cone_shadow_transmittance(const Interaction& at, const Vec3f& l, float distance,
                                                       float half_angle, const RayFootprint* incoming,
                                                       const PathState& path, Vec3f& transmittance) {
  if (std::isfinite(distance) && !ctx_.settings.area_light_cones) return false;
  // Toward a light at a distance the shadow footprint is a pencil from the receiving patch to
  // the light's centre; widened by the cone, it reaches the square of the light's disc there.
  cone_ = half_angle;
  transmittance = shadow_transmittance(at, l, distance, incoming, path);
  cone_ = 0;
  return true;
}

Vec3f FootprintSecondaryRays::seen_surface_transmittance(const Interaction& at, const Vec3f& l, float distance,
                                                         const PathState& path) {
  const SecondaryRaySettings& s = ctx_.base.secondary;
  Interaction patch = at;
  patch.P = seen_->centre;
  patch.dPdx = seen_->dPdx;
  patch.dPdy = seen_->dPdy;
  Vec3f dir = l;
  float to_light = distance;
  if (std::isfinite(distance)) {
    dir = at.P + l * distance - patch.P;
    to_light = length(dir);
    dir = dir / to_light;
  }
  RayFootprint footprint = shadow_footprint(patch, to_light, ctx_.min_radius, std::numeric_limits<float>::infinity());
  if (cone_ > 0) widen_by_cone(footprint, dir, cone_);
  HitFilter filter = shadow_filter(at);
  uint32_t local;
  if (ctx_.base.scene.prim_kind(at.primitive, local) == Scene::PrimKind::Surface) {
    filter.origin_layer = ctx_.base.scene.surfaces.layer(local);
    filter.origin_layer_min_t = 4 * footprint.reach(0);
  }
  Ray ray{patch.P, dir, s.ray_offset, to_light};
  ray.time = at.time;
  ray.sweeps_shutter = at.sweeps_shutter;
  ray.sweep_from = at.sweep_from;
  ray.sweep_to = at.sweep_to;
  return trace_footprint_transmittance(ctx_, ray, footprint, counters_,
                                       scratch_.at(size_t(path.depth) + 1), filter,
                                       stopping_transmittance(s, path.weight, kDistanceMinTransmittance),
                                       &seen_->weights);
}

Vec3f FootprintSecondaryRays::radiance(const Interaction& at, const Ray& ray, const RayFootprint* footprint,
                                       const PathState& next, const Vec3f& beyond) {
  RayFootprint fp = footprint ? *footprint : RayFootprint{};
  fp.min_radius = ctx_.min_radius;
  const float self = std::max(ctx_.base.secondary.self_offset, 4 * fp.reach(0));
  const SampleValue v =
      trace_distance_ray(ctx_, ray, fp, counters_, scratch_, next, leaving_filter(at, ctx_.base.scene, self));
  return v.color + beyond * (1 - v.alpha);
}

}  // namespace darc
