// The standard RI light shaders (RI Spec 3.2 Appendix A), evaluated in world space.
#pragma once

#include "core/scene/scene.h"
#include "core/math/vec.h"
#include "parser/diagnostics.h"

#include <memory>
#include <vector>

namespace darc {

// Light arriving at a point from one light: L points from the surface towards the light.
struct LightContribution {
  Vec3f Cl;
  Vec3f L;
  bool ambient = false;  // ambient lights have no direction: only ambient() sees them
  float distance = 0;    // to the light position (infinity for distant lights)
  float pdf = 0;         // a sampled light's density per steradian for L (0: not sampled)
};

// Where a ray from a point along a direction meets a light (Light::hit).
struct LightHit {
  float distance = 0;  // infinity for the dome
  Vec3f radiance;      // the light's radiance toward the point
  float pdf = 0;       // the density per steradian the light's own sample() draws that direction with
};

// A light with extent as one shadow ray sees it from a point (Light::extent_toward): the unit
// direction to its centre, how far a shadow ray toward it goes (to its plane, or a sphere's near
// side), and the half-angle of the cone of the disc of the area it shows the point.
struct LightExtent {
  Vec3f L;
  float distance = 0;
  float half_angle = 0;
};

class Light {
 public:
  virtual ~Light() = default;
  // Returns false when the light sends nothing to P. `footprint_radius`: half the width of
  // the footprint a ray gave P (world units; 0 for an exact point): light edges sharper than
  // it (a spot's cone edge) are box-filtered over it, so that one shading point per footprint
  // gives what many exact samples inside it would.
  virtual bool illuminate(const Vec3f& P, LightContribution& out, float footprint_radius) const = 0;
  bool illuminate(const Vec3f& P, LightContribution& out) const { return illuminate(P, out, 0.0f); }
  // Lights with extent (shading/area_lights.h) are sampled instead: samples() points per shading
  // point, each from sample(P, u0, u1) with (u0, u1) in [0, 1)^2, whose Cl is the light's whole
  // contribution as that one point estimates it (the caller averages them). 0: a delta light,
  // illuminate() alone.
  virtual int samples() const { return 0; }
  virtual bool sample(const Vec3f&, float, float, LightContribution&) const { return false; }
  // The same for a point whose response lies in the hemisphere around the unit normal N (a
  // surface), or anywhere (N zero: a strand): lights that surround the point (the dome) sample
  // where that response is.
  virtual bool sample(const Vec3f& P, const Vec3f& /*N*/, float u0, float u1, LightContribution& out) const {
    return sample(P, u0, u1, out);
  }
  // The radiance a ray leaving the scene along unit direction d receives from this light (a
  // dome's, at infinity); black for lights that are not at infinity all around.
  virtual Vec3f environment(const Vec3f& /*d*/) const { return {}; }
  // A light a ray can meet (the area lights' shapes, the dome all around): directions a shader
  // draws can light too, weighed against the light's own samples (multiple importance sampling,
  // integrator/secondary_rays.cpp). hit(): whether the ray from P along unit L meets the light's
  // lit side, where, its radiance and the density sample(P, N, ...) draws L with.
  virtual bool can_be_hit() const { return false; }
  virtual bool hit(const Vec3f& /*P*/, const Vec3f& /*N*/, const Vec3f& /*L*/, LightHit& /*out*/) const { return false; }
  // The same radiance along every direction (a dome without a map): drawing directions by the
  // light then does no better than uniformly, and a shader that can draw by its response should
  // draw them all.
  virtual bool has_constant_radiance() const { return false; }
  // A light at infinity seen as a small disc (a sun): the half-angle of the cone it subtends, in
  // radians (0: none). A tracer with footprints may trace one shadow ray whose footprint widens
  // with that cone instead of samples() rays (SecondaryRayTracer::cone_shadow_transmittance).
  virtual float cone_half_angle() const { return 0.0f; }
  // A light with extent (shading/area_lights.h) as one target: what a single shadow ray whose
  // footprint grows from the receiver to the light's extent aims at
  // (SecondaryRayTracer::cone_shadow_transmittance). False for lights without extent, and where P
  // sees none of it (behind a flat light's lit side, inside a sphere light).
  virtual bool extent_toward(const Vec3f& /*P*/, LightExtent& /*out*/) const { return false; }
  // Whether occluders between P and the light are looked for (LightDesc::casts_shadows).
  bool casts_shadows() const { return casts_shadows_; }
  void set_casts_shadows(bool on) { casts_shadows_ = on; }

 private:
  bool casts_shadows_ = false;
};

// Builds the lights of a scene, in Scene::lights order. PRMan's shadowspot, shadowpoint and
// shadowdistant are spotlight, pointlight and distantlight whose shadows come from their
// "shadowname" (ray-traced: LightDesc::casts_shadows). Unknown light shaders get one
// warning each and fall back: to a spotlight when they have "to" and "coneangle", to a point
// light when they have "from", else to a distant light along +z (documented in README).
// "rectlight", "disklight" and "spherelight" are darc's area lights (shading/area_lights.h), with
// "intensity", "lightcolor" and "nsamples"; "domelight" and "envlight" the dome
// (shading/dome_light.h), with those and "string mapname" (or "envname"), a lat-long image: one
// that cannot be read is a warning, and the dome keeps its colour alone.
std::vector<std::unique_ptr<Light>> make_lights(const std::vector<LightDesc>& descs, Diagnostics& diag);

}  // namespace darc
