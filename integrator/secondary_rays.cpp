#include "integrator/secondary_rays.h"

#include "core/scene/ray_differentials.h"

namespace darc {

namespace {

bool worth_tracing(float weight, const SecondaryRaySettings& s) {
  return s.contribution_threshold <= 0 || weight >= s.contribution_threshold;
}

}  // namespace

ShadedPoint shade_with_secondary_rays(const SceneShading& shading, const SecondaryRaySettings& settings,
                                      const Interaction& at, const Vec3f& incoming, const RayFootprint* footprint,
                                      int depth, const LazyWeight& weight, SecondaryRayTracer& tracer,
                                      RayCounters& counters) {
  ShadingPoint sp;
  sp.P = at.P;
  sp.N = at.N;
  sp.I = incoming;
  sp.Cs = at.Cs;
  sp.Os = at.Os;
  sp.dPdv = at.dPdv;
  const SurfaceShader& shader = shading.surface(at.material);
  const SurfaceLobes lobes = shader.lobes(sp);
  const bool pruning = settings.contribution_threshold > 0;
  auto path = [&] { return PathState{depth, pruning ? weight.get() : 1.0f}; };
  Vec3f c = lobes.emission;
  LightContribution lc;
  // Half the footprint's width at P: light edges are filtered over it (exact rays: none).
  const float footprint_radius =
      footprint ? 0.5f * std::sqrt(std::max(length_squared(at.dPdx), length_squared(at.dPdy))) : 0.0f;
  for (const Light* light : shading.lights(at.material)) {
    if (!light->illuminate(sp.P, lc, footprint_radius)) continue;
    if (lc.ambient) {
      c += mul(lobes.ambient, lc.Cl);
      continue;
    }
    if (!lobes.lit) continue;
    Vec3f unoccluded = shader.response(sp, lobes, lc);
    if (!light->casts_shadows() || max_component(unoccluded) <= 0) {
      c += unoccluded;
      continue;
    }
    const float shadow_weight = pruning ? weight.get() * max_component(mul(lobes.Oi, unoccluded)) : 1.0f;
    if (pruning && !worth_tracing(shadow_weight, settings)) {
      counters.count_pruned(SecondaryKind::Shadow);
      c += unoccluded;  // pruned: the light taken as unoccluded
      continue;
    }
    counters.count_traced(SecondaryKind::Shadow);
    c += mul(unoccluded, tracer.shadow_transmittance(at, lc.L, lc.distance, footprint, PathState{depth, shadow_weight}));
  }

  const bool may_bounce = depth < settings.max_depth;
  auto bounce = [&](const Vec3f& factor, SecondaryKind kind, const Vec3f& dir, const RayFootprint* fp) {
    const float ray_weight = path().weight * max_component(mul(lobes.Oi, factor));
    if (!worth_tracing(ray_weight, settings)) {
      counters.count_pruned(kind);  // pruned: black, what a ray leaving the scene sees
      return;
    }
    counters.count_traced(kind);
    Ray r{at.P, dir, settings.ray_offset};
    c += mul(factor, tracer.radiance(at, r, fp, PathState{depth + 1, ray_weight}));
  };
  if (may_bounce && max_component(lobes.reflection) > 0) {
    const Vec3f r = reflect(incoming, lobes.Nf);
    if (footprint) {
      const float flip = dot(lobes.Nf, at.N) < 0 ? -1.0f : 1.0f;
      RayFootprint fp = reflected_footprint(at, incoming, lobes.Nf, at.dNdx * flip, at.dNdy * flip, *footprint);
      bounce(lobes.reflection, SecondaryKind::Reflection, r, &fp);
    } else {
      bounce(lobes.reflection, SecondaryKind::Reflection, r, nullptr);
    }
  }
  Vec3f t;
  if (may_bounce && max_component(lobes.transmission) > 0 && refract(incoming, lobes.Nf, lobes.eta, t)) {
    if (footprint) {
      const float flip = dot(lobes.Nf, at.N) < 0 ? -1.0f : 1.0f;
      RayFootprint fp =
          refracted_footprint(at, incoming, lobes.Nf, at.dNdx * flip, at.dNdy * flip, lobes.eta, t, *footprint);
      bounce(lobes.transmission, SecondaryKind::Refraction, t, &fp);
    } else {
      bounce(lobes.transmission, SecondaryKind::Refraction, t, nullptr);
    }
  }
  return {mul(lobes.Oi, c), lobes.Oi};
}

}  // namespace darc
