// The hair fibre model of Chiang, Bitterli, Tappan & Burley, "A Practical and Controllable Hair
// and Fur Model for Production Path Tracing" (Computer Graphics Forum 35(2), Eurographics 2016),
// as pbrt-v4's HairBxDF and Cycles' Principled Hair implement it (docs: ../shared/docs/lookdev.md
// §1): the R, TT and TRT lobes of a dielectric cylinder plus one residual lobe for every longer
// path, each a longitudinal lobe (d'Eon et al. 2011) times an azimuthal logistic, attenuated by
// Fresnel and by absorption inside the fibre.
//
// Frame: T is the fibre's unit tangent, wo points to the viewer, wi to the light. h in (-1, 1) is
// where across the fibre's width the ray enters. The scattering function returned is S, the
// fibre's f times the cosine to the fibre (pbrt's f * |cos|): the light scattered toward wo is the
// integral of S L_i over the sphere of wi, and with no absorption that integral is 1 for every wo
// and h (the white furnace).
#pragma once

#include "core/math/vec.h"

#include <array>
#include <vector>

namespace darc {

struct ChiangHairParams {
  Vec3f sigma_a{0.06f, 0.1f, 0.2f};  // absorption per unit fibre radius (pbrt's sigma_a)
  float eta = 1.55f;                 // index of refraction of the fibre
  float beta_m = 0.3f;               // longitudinal roughness, in [0.01, 1]
  float beta_n = 0.3f;               // azimuthal roughness, in [0.01, 1]
  float alpha_degrees = 2.0f;        // tilt of the cuticle scales
};

struct HairSample {
  Vec3f wi;      // toward the light (unit)
  Vec3f S;       // the scattering function at wi
  float pdf = 0;  // per unit solid angle; 0: no sample
  int lobe = 0;  // 0 R, 1 TT, 2 TRT, 3 the residual
};

class ChiangHair {
 public:
  explicit ChiangHair(const ChiangHairParams& params);

  const ChiangHairParams& params() const { return p_; }

  // S(wo, wi) for a ray entering at h.
  Vec3f scattering(const Vec3f& T, const Vec3f& wo, const Vec3f& wi, float h) const;
  // S averaged over the fibre's width (h uniform in [-1, 1]): what a fibre thinner than the
  // footprint that sees it sends, whichever hider sees it (no noise from where a sample lands
  // across it). A quadrature in the entry angle asin(h), whose points are close enough for the
  // azimuthal lobes (azimuthal_roughness) to overlap: width_points() of them.
  Vec3f scattering_across(const Vec3f& T, const Vec3f& wo, const Vec3f& wi) const;
  // The same with another absorption (a colour given per point), the roughness kept.
  Vec3f scattering_across(const Vec3f& T, const Vec3f& wo, const Vec3f& wi, const Vec3f& sigma_a) const;
  int width_points() const { return int(width_sin_.size()); }

  // Importance sampling of S for a ray entering at h (u: four uniform numbers in [0, 1)): the
  // lobe by its share of the attenuation (grey), the longitudinal angle from its lobe (d'Eon,
  // Marschner & Hanika 2013), the azimuth from its trimmed logistic.
  HairSample sample(const Vec3f& T, const Vec3f& wo, float h, const std::array<float, 4>& u) const;
  // The density sample() draws wi with.
  float pdf(const Vec3f& T, const Vec3f& wo, const Vec3f& wi, float h) const;

  // Importance sampling of scattering_across with absorption sigma_a: an entry point of the width
  // quadrature drawn by its weight, then sample() there (u[0] chooses both: the point, then the
  // lobe within what is left of its interval). The sample's S is scattering_across at wi and its
  // pdf the density of the whole draw, pdf_across: so S / pdf estimates what the fibre sends
  // without bias, and the two can be weighed against another technique (MIS).
  HairSample sample_across(const Vec3f& T, const Vec3f& wo, const Vec3f& sigma_a, const std::array<float, 4>& u) const;
  // scattering_across and the density sample_across draws wi with (the quadrature's mean of the
  // entry points' densities), in one pass over the width.
  struct Across {
    Vec3f S;
    float pdf = 0;
  };
  Across evaluate_across(const Vec3f& T, const Vec3f& wo, const Vec3f& wi, const Vec3f& sigma_a) const;

  // The attenuation of each lobe (A_0 .. A_2, and A_3 for every longer path) at h for a
  // direction wo at sin(theta_o) = sin_theta_o along the fibre. Without absorption they sum to 1.
  std::array<Vec3f, 4> attenuation(float sin_theta_o, float h) const;

  // Absorption from the colour a hair volume should have (Chiang §4.2: the multiple-scattering
  // albedo, not one fibre's): sigma_a = (ln c / D(beta_n))^2. c is clamped to [1e-4, 1].
  static Vec3f sigma_a_from_reflectance(const Vec3f& c, float beta_n);
  // The colour sigma_a_from_reflectance inverts: c = exp(-sqrt(sigma_a) D(beta_n)).
  static Vec3f reflectance_from_sigma_a(const Vec3f& sigma_a, float beta_n);
  // Absorption from melanin concentrations, with pbrt-v4's coefficients (so that pbrt scenes port
  // unchanged; brown hair is eumelanin 1.3, blonde about 0.3, black about 8).
  static Vec3f sigma_a_from_melanin(float eumelanin, float pheomelanin);
  // The beta_m whose R lobe has a longitudinal standard deviation sqrt(v) of `degrees`.
  static float beta_m_for_cone_angle(float degrees);
  // The longitudinal variance of the R lobe (Chiang §4): v = (0.726 b + 0.812 b^2 + 3.7 b^20)^2.
  static float longitudinal_variance(float beta_m);
  // The logistic scale s of the azimuthal lobes: sqrt(pi/8) (0.265 b + 1.194 b^2 + 5.372 b^22).
  static float azimuthal_scale(float beta_n);

 private:
  struct Frame;
  Frame frame(const Vec3f& T, const Vec3f& wo) const;
  // sample() at the entry point of sine sin_g (cosine cos_g), absorption sigma_a; without
  // `evaluate` only the direction and lobe (sample_across evaluates over the whole width).
  HairSample sample_at(const Frame& f, const Vec3f& sigma_a, float sin_g, float cos_g, const std::array<float, 4>& u,
                       bool evaluate = true) const;
  Across evaluate_across(const Frame& f, const Vec3f& wi, const Vec3f& sigma_a) const;
  // The longitudinal lobes M_p(theta_i) of the four lobes.
  std::array<float, 4> longitudinal(const Frame& f, float sin_theta_i, float cos_theta_i) const;

  ChiangHairParams p_;
  std::array<float, 4> v_;        // longitudinal variance per lobe
  float s_;                       // azimuthal logistic scale
  std::array<float, 3> sin_2k_alpha_, cos_2k_alpha_;  // sin and cos of alpha, 2 alpha, 4 alpha
  // The quadrature across the width: entry angles gamma_o = asin(h) at the midpoints of equal
  // steps of [-pi/2, pi/2], with sin, cos and the weight (step * cos / 2, so that they sum to 1).
  std::vector<float> width_sin_, width_cos_, width_weight_;
};

}  // namespace darc
