#include "integrator/secondary_rays.h"

#include "core/scene/ray_differentials.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace darc {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// The strata of an area light's samples: nx x ny cells (nx the rounded square root of the count
// asked for), each sampled at its centre moved by the rotation, wrapped into [0, 1).
class LightSampleGrid {
 public:
  explicit LightSampleGrid(int n) : nx_(std::max(1, int(std::lround(std::sqrt(double(n)))))), ny_((n + nx_ - 1) / nx_) {}
  int count() const { return nx_ * ny_; }
  template <class Rotation>
  void point(int k, const Rotation& r, float& u0, float& u1) const {
    u0 = wrap((float(k % nx_) + 0.5f) / float(nx_) + r.u0);
    u1 = wrap((float(k / nx_) + 0.5f) / float(ny_) + r.u1);
  }

 private:
  static float wrap(float u) {
    u -= std::floor(u);
    return u < 1.0f ? u : 0.0f;
  }
  int nx_, ny_;
};

// Two numbers in [0, 1) from a point's coordinates and a light's index (splitmix64 finaliser).
struct LightSampleRotation {
  float u0 = 0, u1 = 0;
  LightSampleRotation(const Vec3f& P, uint32_t light) {
    uint64_t h = mix((uint64_t(std::bit_cast<uint32_t>(P.x)) << 32) ^ std::bit_cast<uint32_t>(P.y));
    h = mix(h ^ (uint64_t(std::bit_cast<uint32_t>(P.z)) << 32) ^ light);
    u0 = float(h >> 40) * 0x1.0p-24f;
    u1 = float((h >> 16) & 0xFFFFFF) * 0x1.0p-24f;
  }
  static uint64_t mix(uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
};

// Four numbers for a shader's draw of sample k (SurfaceShader::sample_response): the stratum's
// two (u0, u1) where a fibre's lobe is steered (its longitudinal and azimuthal angles), and two
// drawn from the stratum's rotation and k (which lobe and entry point, the cone's turn).
std::array<float, 4> lobe_numbers(const LightSampleRotation& r, int k, float u0, float u1) {
  const uint64_t h = LightSampleRotation::mix((uint64_t(std::bit_cast<uint32_t>(r.u0)) << 32) ^
                                              std::bit_cast<uint32_t>(r.u1) ^ (uint64_t(uint32_t(k)) << 16));
  return {float(h >> 40) * 0x1.0p-24f, u0, float((h >> 16) & 0xFFFFFF) * 0x1.0p-24f, u1};
}

// Above this ratio of an area light's stratum (its angular size over sqrt(samples)) to the
// response's lobe width, the light and the shader's draws are combined by MIS.
constexpr float kMisStratumPerLobeWidth = 1.4f;

// Veach's power heuristic: the weight of a sample drawn with density `own` where another
// technique, drawing as many samples, has density `other`.
float power_weight(float own, float other) {
  const float a = own * own, b = other * other;
  return a + b > 0 && std::isfinite(a + b) ? a / (a + b) : (std::isfinite(a) && a > 0 ? 1.0f : 0.0f);
}

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
  sp.st = at.st;
  const SurfaceShader& shader = shading.surface(at.material);
  shader.apply_patterns(sp);
  const SurfaceLobes lobes = shader.lobes(sp);
  const bool pruning = settings.contribution_threshold > 0;
  auto path = [&] { return PathState{depth, pruning ? weight.get() : 1.0f}; };
  Vec3f c = lobes.emission;
  LightContribution lc;
  // Half the footprint's width at P: light edges are filtered over it (exact rays: none).
  const float footprint_radius =
      footprint ? 0.5f * std::sqrt(std::max(length_squared(at.dPdx), length_squared(at.dPdy))) : 0.0f;
  // The light of one direction toward `light`, whose whole contribution that direction
  // estimates, times `share` (an area light's sample: 1 / samples), through its shadow ray when
  // it casts shadows. An area light's samples are pruned (and stop) by the light's whole
  // contribution as each estimates it, not by their share of it: many samples of a light that
  // matters are each small, and pruning them one by one took the whole light as unoccluded.
  // `cone` > 0: the light is a small disc at infinity seen along lc.L, and its shadow is the mean
  // over that cone, in one ray when the tracer can (else the light is sampled: false).
  // `whole`: the light's whole contribution as estimated (what prunes its shadow rays);
  // `unoccluded`: the part this shadow ray stands for, toward unit direction L, `distance` away.
  auto add_shadowed = [&](const Light& light, const Vec3f& whole, const Vec3f& unoccluded, const Vec3f& L,
                          float distance, float cone) {
    if (!light.casts_shadows() || max_component(unoccluded) <= 0) {
      c += unoccluded;
      return true;
    }
    const float shadow_weight = pruning ? weight.get() * max_component(mul(lobes.Oi, whole)) : 1.0f;
    if (pruning && !worth_tracing(shadow_weight, settings)) {
      counters.count_pruned(SecondaryKind::Shadow);
      c += unoccluded;  // pruned: the light taken as unoccluded
      return true;
    }
    if (cone > 0) {
      Vec3f transmittance;
      if (!tracer.cone_shadow_transmittance(at, L, distance, cone, footprint, PathState{depth, shadow_weight},
                                            transmittance))
        return false;
      counters.count_traced(SecondaryKind::Shadow);
      c += mul(unoccluded, transmittance);
      return true;
    }
    counters.count_traced(SecondaryKind::Shadow);
    c += mul(unoccluded, tracer.shadow_transmittance(at, L, distance, footprint, PathState{depth, shadow_weight}));
    return true;
  };
  auto add_light = [&](const Light& light, const LightContribution& lc, float share, float cone = 0.0f) {
    const Vec3f whole = shader.response(sp, lobes, lc);
    return add_shadowed(light, whole, whole * share, lc.L, lc.distance, cone);
  };
  uint32_t light_index = 0;
  for (const Light* light : shading.lights(at.material)) {
    ++light_index;
    if (const int n = light->samples(); n > 0) {
      if (!lobes.lit) continue;
      // A small sun with a footprint: its direction alone (within kMaxConeShadowHalfAngle the
      // response barely changes over the cone) and one shadow ray widened by the cone.
      if (const float cone = light->cone_half_angle();
          cone > 0 && cone <= kMaxConeShadowHalfAngle && footprint && light->illuminate(sp.P, lc, footprint_radius) &&
          add_light(*light, lc, 1.0f, cone))
        continue;
      // A grid of strata over the light's parameters, rotated by an amount drawn from the point
      // and the light (Cranley-Patterson): neighbouring points see different points of the light,
      // so the light's shape does not print as a pattern of copies, and the result depends on
      // nothing but the point (the same for any thread count or tile order).
      const LightSampleRotation rotation(sp.P, light_index);
      // Surfaces respond in the hemisphere their faced-forward normal points to; strands all around.
      const Vec3f around = at.is_curve ? Vec3f{} : lobes.Nf;
      // Multiple importance sampling (Veach 1997, the power heuristic) where the shader can draw
      // directions by its response (a fibre's lobes, 2-17 degrees wide) and a ray can meet the
      // light (an area light's shape, the dome): half the samples from the light, half from the
      // shader, each weighed by its density against the other technique's, so that neither a
      // narrow lobe nor a small bright part of the light is left to chance. Under a constant dome
      // the light's own draw is uniform and adds only noise: the shader draws every sample (for a
      // fibre without absorption each then weighs exactly the dome's radiance).
      bool mis = light->can_be_hit() && shader.can_sample_response(sp);
      // An area light's own samples are strata of its solid angle: while a stratum is not much
      // wider than the response's lobe they integrate it better than the lobe's draws do (which
      // miss the light where the lobe is wider than it). Measured on a strand behind a 2x2 rect
      // light (docs/lookdev.md): the crossover is a stratum of about 1.4 lobe widths.
      if (LightExtent seen; mis && light->extent_toward(sp.P, seen))
        mis = seen.half_angle * std::sqrt(kPi / float(n)) > kMisStratumPerLobeWidth * shader.response_lobe_width(sp);
      const bool light_draws = !(mis && light->has_constant_radiance());
      const LightSampleGrid grid(mis && light_draws ? (n + 1) / 2 : n);
      const float share = 1.0f / float(grid.count());
      const LightSampleRotation lobe_rotation(sp.P, light_index | 0x80000000u);
      // take(whole, part, L, distance) for each sample: its estimate of the light's whole
      // contribution (what prunes its shadow ray), the part it adds, toward L, `distance` away.
      auto for_each_sample = [&](auto&& take) {
        for (int k = 0; k < grid.count(); ++k) {
          float u0, u1;
          if (light_draws) {
            grid.point(k, rotation, u0, u1);
            if (light->sample(sp.P, around, u0, u1, lc)) {
              if (!mis) {
                const Vec3f whole = shader.response(sp, lobes, lc);
                take(whole, whole * share, lc.L, lc.distance);
              } else {
                float shader_pdf = 0;
                const Vec3f whole = shader.response_and_pdf(sp, lobes, lc, shader_pdf);
                const float w = power_weight(lc.pdf, shader_pdf);
                if (w > 0) take(whole, whole * (w * share), lc.L, lc.distance);
              }
            }
          }
          if (!mis) continue;
          grid.point(k, lobe_rotation, u0, u1);
          SurfaceShader::ResponseSample drawn;
          LightHit met;
          if (!shader.sample_response(sp, lobes, lobe_numbers(lobe_rotation, k, u0, u1), drawn) ||
              !light->hit(sp.P, around, drawn.L, met))
            continue;
          // Cl = L / (pi pdf), as the light's own samples carry it (shading/area_lights.h).
          LightContribution seen{met.radiance * (1 / (kPi * drawn.pdf)), drawn.L, false, met.distance, drawn.pdf};
          const Vec3f whole = mul(drawn.factor, seen.Cl);
          const float w = light_draws ? power_weight(drawn.pdf, met.pdf) : 1.0f;
          if (w > 0) take(whole, whole * (w * share), drawn.L, met.distance);
        }
      };
      // With a footprint, a light with extent casts one cone shadow ray: its samples light the
      // point as if unoccluded, and their sum is dimmed by the mean transmittance over the cone
      // from the receiving patch to the light (visibility taken as independent of where on the
      // light the light comes from; docs/performance-area-shadows.md measures it).
      LightExtent extent;
      if (footprint && light->casts_shadows() && light->extent_toward(sp.P, extent)) {
        Vec3f unoccluded;
        for_each_sample([&](const Vec3f&, const Vec3f& part, const Vec3f&, float) { unoccluded += part; });
        if (max_component(unoccluded) <= 0) continue;
        if (add_shadowed(*light, unoccluded, unoccluded, extent.L, extent.distance, std::max(extent.half_angle, 1e-6f)))
          continue;
      }
      for_each_sample([&](const Vec3f& whole, const Vec3f& part, const Vec3f& L, float distance) {
        add_shadowed(*light, whole, part, L, distance, 0.0f);
      });
      continue;
    }
    if (!light->illuminate(sp.P, lc, footprint_radius)) continue;
    if (lc.ambient) {
      c += mul(lobes.ambient, lc.Cl);
      continue;
    }
    if (!lobes.lit) continue;
    add_light(*light, lc, 1.0f);
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
    r.time = at.time;
    r.sweeps_shutter = at.sweeps_shutter;
    r.sweep_from = at.sweep_from;
    r.sweep_to = at.sweep_to;
    // What the ray sees if it leaves the scene: the domes that light this point, along it.
    Vec3f beyond{};
    for (const Light* light : shading.lights(at.material)) beyond += light->environment(dir);
    c += mul(factor, tracer.radiance(at, r, fp, PathState{depth + 1, ray_weight}, beyond));
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
