// Surface shaders by RIB name: the RI standard surfaces (RI Spec 3.2 Appendix A) and the ray
// tracing ones of BMRT (mirror, glass), with their default parameters. A shader does not loop
// over lights or trace rays: it describes its lobes (what it emits, its ambient factor, its
// response to one light, the weights of a reflected and a refracted ray) and its opacity, and
// the integrator owns the light loop, visibility and pruning (DESIGN.md, "shading split into
// lobes"). Nothing here calls the tracer.
#pragma once

#include "parser/diagnostics.h"
#include "parser/param_list.h"
#include "shading/lights.h"
#include "shading/shading_point.h"
#include "shading/textures.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace darc {

// What a shader returns at one point. The colour it computes is
//   Ci = Oi * (emission + ambient * (sum of ambient lights) + sum over lights of response(light)
//              + reflection * (colour seen along R) + transmission * (colour seen along T)),
// the form of every RI shader here (Ci = Os * (...)).
struct SurfaceLobes {
  Vec3f Oi;
  Vec3f emission;      // light-independent colour
  Vec3f ambient;       // factor on the ambient lights' sum
  Vec3f reflection;    // weight of the mirror-reflected ray (Kr * Fresnel, tinted); zero: none
  Vec3f transmission;  // weight of the refracted ray (Kt * (1 - Fresnel), tinted); zero: none
  float eta = 1;       // n_from / n_to across the surface for the refracted ray
  Vec3f Nf;            // unit normal facing the incoming ray, that R and T are taken about
  bool lit = false;    // response() is not zero for every light: the light loop is needed
};

class SurfaceShader {
 public:
  virtual ~SurfaceShader() = default;
  // The shader's patterns: what it reads from textures into the point's inputs (paintedplastic
  // multiplies Cs by its texture). Called once per shaded point, before lobes().
  virtual void apply_patterns(ShadingPoint&) const {}
  virtual SurfaceLobes lobes(const ShadingPoint& sp) const = 0;
  // The light sent toward the eye for one non-ambient light's contribution `lc` (its Cl already
  // attenuated by the light itself, not yet by occluders), before Oi. `lobes` is lobes(sp).
  virtual Vec3f response(const ShadingPoint&, const SurfaceLobes&, const LightContribution&) const { return {}; }

  // Directions drawn where the response is large, for a light that can be seen along any
  // direction (the dome: its samples and these are weighed by multiple importance sampling in
  // integrator/secondary_rays.cpp). Shaders that cannot draw (the default) leave the light to
  // sample alone. The response to light Cl arriving along L is mul(factor, Cl) (every shader here
  // is linear in Cl); pdf is per steradian.
  struct ResponseSample {
    Vec3f L;
    Vec3f factor;
    float pdf = 0;
  };
  virtual bool can_sample_response(const ShadingPoint&) const { return false; }
  // The angular width (radians, a standard deviation) of the narrowest part of the response the
  // draws follow: what decides whether drawing by the response beats the light's own strata.
  virtual float response_lobe_width(const ShadingPoint&) const { return 0.0f; }
  // `u`: four uniform numbers in [0, 1). False: no direction (the draw failed).
  virtual bool sample_response(const ShadingPoint&, const SurfaceLobes&, const std::array<float, 4>& /*u*/,
                               ResponseSample&) const {
    return false;
  }
  // response(lc), and in `pdf` the density sample_response draws lc.L with (0 for shaders that
  // cannot draw), in one evaluation.
  virtual Vec3f response_and_pdf(const ShadingPoint& sp, const SurfaceLobes& l, const LightContribution& lc,
                                 float& pdf) const {
    pdf = 0;
    return response(sp, l, lc);
  }
};

// The lights a primitive sees (pointers into the scene's light list).
using LightList = std::vector<const Light*>;

// The colour and opacity of a shader lit by `lights` without shadows or traced rays (reflection
// and refraction see black): what the shader computes when nothing is traced. For tests and for
// callers that need no integrator.
struct ShadeResult {
  Vec3f Ci;  // premultiplied by Oi
  Vec3f Oi;
};
ShadeResult shade_unshadowed(const SurfaceShader& shader, const ShadingPoint& sp, const LightList& lights);

// Makes the shader for a RIB Surface call. Unknown names get one warning each and
// "defaultsurface" (documented in README). Known names: constant, matte, plastic,
// paintedplastic (plastic with Cs times the texture "texturename", read through `textures`;
// without them, or when the file cannot be read (a warning), plastic: shading/color_texture.h,
// which also gives any shader the PxrTexture colour a RIS Bxdf maps to), metal, shinymetal (Kr
// traces a reflection ray where RSL reads an environment map), mirror, glass, hair = kajiyakay
// (Kajiya-Kay, PRMan application note 19), chianghair, defaultsurface.
std::unique_ptr<SurfaceShader> make_surface_shader(const std::string& name, const ParamList& params,
                                                   const SourceLoc& loc, Diagnostics& diag,
                                                   Textures* textures = nullptr);

// An emissive surface for geometry inside an AreaLightSource block: Ci = intensity * lightcolor.
std::unique_ptr<SurfaceShader> make_area_light_surface(const ParamList& light_params);

// The dielectric Fresnel reflectance for unpolarized light (RSL fresnel()'s Kr) of a ray with
// cos_i = -dot(I, Nf) > 0 crossing into a medium with relative index 1 / eta (eta = n_from /
// n_to). 1 on total internal reflection.
float dielectric_fresnel(float cos_i, float eta);

}  // namespace darc
