#include "shading/chiang_hair.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace darc {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float safe_sqrt(float x) { return std::sqrt(std::max(0.0f, x)); }
float safe_asin(float x) { return std::asin(std::clamp(x, -1.0f, 1.0f)); }

// ln I_0(x): the series (20 terms, in double: 1e-10 relative below 12) and above 12 the
// asymptotic form with two correction terms (5e-5). pbrt and Cycles sum 10 terms, whose 2 %
// error at x near 12 shows as a 1 % furnace error (lookdev.md §1.9).
float log_bessel_i0(float x) {
  if (x > 12.0f) {
    const double xd = x;
    return float(xd - 0.5 * std::log(2 * std::numbers::pi * xd) + std::log1p(1 / (8 * xd) + 9 / (128 * xd * xd)));
  }
  const double q = double(x) * double(x) / 4;
  double term = 1, sum = 1;
  for (int k = 1; k < 20; ++k) {
    term *= q / (double(k) * double(k));
    sum += term;
  }
  return float(std::log(sum));
}

// d'Eon et al.'s longitudinal lobe, normalised so that its integral times cos(theta_i) over
// theta_i is 1, in log form (sinh(1/v) overflows a float for v below 0.011).
float longitudinal_lobe(float cos_i, float cos_o, float sin_i, float sin_o, float v) {
  const float a = cos_i * cos_o / v, b = sin_i * sin_o / v;
  const float log_m = log_bessel_i0(a) - b - 1.0f / v - std::log(v) - std::log1p(-std::exp(-2.0f / v));
  return std::exp(log_m);
}

float logistic(float x, float s) {
  x = std::abs(x);
  const float e = std::exp(-x / s);
  return e / (s * (1 + e) * (1 + e));
}
float logistic_cdf(float x, float s) { return 1 / (1 + std::exp(-x / s)); }
// The logistic restricted to [-pi, pi] and renormalised.
float trimmed_logistic(float x, float s) {
  return logistic(x, s) / (logistic_cdf(kPi, s) - logistic_cdf(-kPi, s));
}
float sample_trimmed_logistic(float u, float s) {
  const float k = logistic_cdf(kPi, s) - logistic_cdf(-kPi, s);
  const float x = -s * std::log(1 / (u * k + logistic_cdf(-kPi, s)) - 1);
  return std::clamp(x, -kPi, kPi);
}
// x wrapped into [-pi, pi].
float wrap_angle(float x) { return std::remainder(x, 2 * kPi); }

// The unpolarised Fresnel reflectance of a dielectric of index eta entered from outside at
// cos_i (the dielectric_fresnel of shading/surface_shader.cpp, repeated here so that the model
// depends on nothing but vectors).
float fresnel_entering(float cos_i, float eta) {
  cos_i = std::clamp(cos_i, 0.0f, 1.0f);
  const float sin_t2 = (1 - cos_i * cos_i) / (eta * eta);
  const float cos_t = safe_sqrt(1 - sin_t2);
  const float r_s = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  const float r_p = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5f * (r_s * r_s + r_p * r_p);
}

Vec3f exp3(const Vec3f& v) { return {std::exp(v.x), std::exp(v.y), std::exp(v.z)}; }
float mean(const Vec3f& v) { return (v.x + v.y + v.z) / 3; }

// What depends on where the ray enters (gamma_o = asin h): the refracted angle inside, the lobes'
// attenuations, and from them each lobe's azimuthal centre Phi(p) = 2 p gamma_t - 2 gamma_o + p pi.
struct WidthTerms {
  float gamma_o = 0, gamma_t = 0;
  std::array<Vec3f, 4> A;
  float phi(int p) const { return 2 * float(p) * gamma_t - 2 * gamma_o + float(p) * kPi; }
};

WidthTerms width_terms(const ChiangHairParams& prm, const Vec3f& sigma_a, float sin_o, float cos_o, float sin_gamma_o,
                       float cos_gamma_o) {
  WidthTerms w;
  w.gamma_o = safe_asin(sin_gamma_o);
  // Inside: sin(theta_t) = sin(theta_o) / eta, and the azimuthal index eta' = sqrt(eta^2 -
  // sin^2 theta_o) / cos theta_o gives sin(gamma_t) = h / eta' (written without the division by
  // cos theta_o, which is 0 at grazing).
  const float eta = prm.eta;
  const float sin_t = sin_o / eta, cos_t = safe_sqrt(1 - sin_t * sin_t);
  const float sin_gamma_t = sin_gamma_o * cos_o / safe_sqrt(eta * eta - sin_o * sin_o);
  w.gamma_t = safe_asin(sin_gamma_t);
  const float cos_gamma_t = safe_sqrt(1 - sin_gamma_t * sin_gamma_t);
  // One pass through the fibre: a chord of length 2 cos(gamma_t) / cos(theta_t) radii.
  const Vec3f Ta = exp3(sigma_a * (-2 * cos_gamma_t / std::max(cos_t, 1e-6f)));
  const float f = fresnel_entering(cos_o * cos_gamma_o, eta);
  w.A[0] = Vec3f{f, f, f};
  w.A[1] = Ta * ((1 - f) * (1 - f));
  w.A[2] = mul(w.A[1], Ta) * f;
  // Every longer path: the geometric series of A_2 f Ta.
  const Vec3f fTa = Ta * f;
  auto rest = [](float a2, float fta) { return fta < 1 ? a2 * fta / (1 - fta) : 0.0f; };
  w.A[3] = Vec3f{rest(w.A[2].x, fTa.x), rest(w.A[2].y, fTa.y), rest(w.A[2].z, fTa.z)};
  return w;
}

}  // namespace

struct ChiangHair::Frame {
  Vec3f T, Y, Z;
  float sin_o = 0, cos_o = 1;
  // theta_o of each lobe turned by the scales' tilt: R by -2 alpha, TT by alpha, TRT by 4 alpha,
  // the residual not at all.
  std::array<float, 4> sin_op, cos_op;
};

ChiangHair::ChiangHair(const ChiangHairParams& params) : p_(params) {
  p_.beta_m = std::clamp(p_.beta_m, 0.01f, 1.0f);
  p_.beta_n = std::clamp(p_.beta_n, 0.01f, 1.0f);
  const float v = longitudinal_variance(p_.beta_m);
  v_ = {v, 0.25f * v, 4 * v, 4 * v};
  s_ = azimuthal_scale(p_.beta_n);
  const float alpha = p_.alpha_degrees * kPi / 180;
  for (int k = 0; k < 3; ++k) {
    const float a = alpha * float(1 << k);
    sin_2k_alpha_[size_t(k)] = std::sin(a);
    cos_2k_alpha_[size_t(k)] = std::cos(a);
  }
  // The azimuthal centres of R move by 2 radians per radian of entry angle (and TT, TRT by at
  // most as much): points pi / n apart put neighbouring centres 2 pi / n apart, which the
  // logistic (standard deviation 1.81 s) smooths to a ripple of about 1 % when that is at most
  // 2 of its standard deviations. Capped at 64 points (beta_n below 0.12 ripples more).
  const int n = std::clamp(int(std::ceil(kPi / (1.81f * s_))), 4, 64);
  const float step = kPi / float(n);
  float sum = 0;
  for (int j = 0; j < n; ++j) {
    const float g = -kPi / 2 + (float(j) + 0.5f) * step;
    width_sin_.push_back(std::sin(g));
    width_cos_.push_back(std::cos(g));
    width_weight_.push_back(std::cos(g));
    sum += std::cos(g);
  }
  for (float& w : width_weight_) w /= sum;
}

float ChiangHair::longitudinal_variance(float beta_m) {
  const float b = std::clamp(beta_m, 0.01f, 1.0f);
  const float x = 0.726f * b + 0.812f * b * b + 3.7f * std::pow(b, 20.0f);
  return x * x;
}

float ChiangHair::azimuthal_scale(float beta_n) {
  const float b = std::clamp(beta_n, 0.01f, 1.0f);
  return std::sqrt(kPi / 8) * (0.265f * b + 1.194f * b * b + 5.372f * std::pow(b, 22.0f));
}

ChiangHair::Frame ChiangHair::frame(const Vec3f& T, const Vec3f& wo) const {
  Frame f;
  f.T = T;
  f.sin_o = std::clamp(dot(wo, T), -1.0f, 1.0f);
  f.cos_o = safe_sqrt(1 - f.sin_o * f.sin_o);
  f.Y = normalize(wo - T * f.sin_o);
  if (length_squared(f.Y) == 0.0f) {  // wo along the fibre: any direction across it
    const Vec3f a = std::abs(T.x) < 0.9f ? Vec3f{1, 0, 0} : Vec3f{0, 1, 0};
    f.Y = normalize(cross(T, a));
  }
  f.Z = cross(T, f.Y);
  const float s = f.sin_o, c = f.cos_o;
  f.sin_op = {s * cos_2k_alpha_[1] - c * sin_2k_alpha_[1], s * cos_2k_alpha_[0] + c * sin_2k_alpha_[0],
              s * cos_2k_alpha_[2] + c * sin_2k_alpha_[2], s};
  f.cos_op = {std::abs(c * cos_2k_alpha_[1] + s * sin_2k_alpha_[1]), std::abs(c * cos_2k_alpha_[0] - s * sin_2k_alpha_[0]),
              std::abs(c * cos_2k_alpha_[2] - s * sin_2k_alpha_[2]), c};
  return f;
}

std::array<float, 4> ChiangHair::longitudinal(const Frame& f, float sin_i, float cos_i) const {
  std::array<float, 4> m;
  for (size_t p = 0; p < 4; ++p) m[p] = longitudinal_lobe(cos_i, f.cos_op[p], sin_i, f.sin_op[p], v_[p]);
  return m;
}

std::array<Vec3f, 4> ChiangHair::attenuation(float sin_theta_o, float h) const {
  const float s = std::clamp(sin_theta_o, -1.0f, 1.0f);
  return width_terms(p_, p_.sigma_a, s, safe_sqrt(1 - s * s), h, safe_sqrt(1 - h * h)).A;
}

Vec3f ChiangHair::scattering(const Vec3f& T, const Vec3f& wo, const Vec3f& wi, float h) const {
  const Frame f = frame(T, wo);
  const float sin_i = std::clamp(dot(wi, T), -1.0f, 1.0f), cos_i = safe_sqrt(1 - sin_i * sin_i);
  const float phi = std::atan2(dot(wi, f.Z), dot(wi, f.Y));
  const std::array<float, 4> M = longitudinal(f, sin_i, cos_i);
  h = std::clamp(h, -1.0f, 1.0f);
  const WidthTerms w = width_terms(p_, p_.sigma_a, f.sin_o, f.cos_o, h, safe_sqrt(1 - h * h));
  Vec3f S = w.A[3] * (M[3] / (2 * kPi));
  for (int p = 0; p < 3; ++p) S += w.A[size_t(p)] * (M[size_t(p)] * trimmed_logistic(wrap_angle(phi - w.phi(p)), s_));
  return S;
}

Vec3f ChiangHair::scattering_across(const Vec3f& T, const Vec3f& wo, const Vec3f& wi) const {
  return scattering_across(T, wo, wi, p_.sigma_a);
}

Vec3f ChiangHair::scattering_across(const Vec3f& T, const Vec3f& wo, const Vec3f& wi, const Vec3f& sigma_a) const {
  const Frame f = frame(T, wo);
  const float sin_i = std::clamp(dot(wi, T), -1.0f, 1.0f), cos_i = safe_sqrt(1 - sin_i * sin_i);
  const float phi = std::atan2(dot(wi, f.Z), dot(wi, f.Y));
  const std::array<float, 4> M = longitudinal(f, sin_i, cos_i);
  Vec3f S;
  for (size_t j = 0; j < width_sin_.size(); ++j) {
    const WidthTerms w = width_terms(p_, sigma_a, f.sin_o, f.cos_o, width_sin_[j], width_cos_[j]);
    Vec3f Sj = w.A[3] * (M[3] / (2 * kPi));
    for (int p = 0; p < 3; ++p)
      Sj += w.A[size_t(p)] * (M[size_t(p)] * trimmed_logistic(wrap_angle(phi - w.phi(p)), s_));
    S += Sj * width_weight_[j];
  }
  return S;
}

namespace {

// Each lobe's probability of being sampled: its share of the grey attenuation.
std::array<float, 4> lobe_pdf(const std::array<Vec3f, 4>& A) {
  std::array<float, 4> pdf;
  float sum = 0;
  for (size_t p = 0; p < 4; ++p) sum += pdf[p] = mean(A[p]);
  for (float& x : pdf) x = sum > 0 ? x / sum : 0.25f;
  return pdf;
}

}  // namespace

HairSample ChiangHair::sample(const Vec3f& T, const Vec3f& wo, float h, const std::array<float, 4>& u) const {
  h = std::clamp(h, -1.0f, 1.0f);
  return sample_at(frame(T, wo), p_.sigma_a, h, safe_sqrt(1 - h * h), u);
}

HairSample ChiangHair::sample_at(const Frame& f, const Vec3f& sigma_a, float sin_g, float cos_g,
                                 const std::array<float, 4>& u, bool evaluate) const {
  const Vec3f& T = f.T;
  const WidthTerms w = width_terms(p_, sigma_a, f.sin_o, f.cos_o, sin_g, cos_g);
  const std::array<float, 4> lobe_p = lobe_pdf(w.A);
  HairSample out;
  int p = 0;
  float acc = 0;
  for (; p < 3; ++p) {
    acc += lobe_p[size_t(p)];
    if (u[0] < acc) break;
  }
  out.lobe = p;
  // theta_i about the lobe's specular cone (theta_i = -theta_o'), as a direction on a von
  // Mises-Fisher lobe whose projection on T has M_p as its density.
  const float v = v_[size_t(p)];
  const float u1 = std::max(u[1], 1e-5f);
  const float cos_theta = 1 + v * std::log(u1 + (1 - u1) * std::exp(-2 / v));
  const float sin_theta = safe_sqrt(1 - cos_theta * cos_theta);
  const float cos_phi = std::cos(2 * kPi * u[2]);
  const float sin_i = std::clamp(-cos_theta * f.sin_op[size_t(p)] + sin_theta * cos_phi * f.cos_op[size_t(p)], -1.0f, 1.0f);
  const float cos_i = safe_sqrt(1 - sin_i * sin_i);
  const float dphi = p < 3 ? w.phi(p) + sample_trimmed_logistic(u[3], s_) : 2 * kPi * u[3];
  out.wi = normalize(T * sin_i + (f.Y * std::cos(dphi) + f.Z * std::sin(dphi)) * cos_i);
  if (!evaluate) return out;
  // The density of the mixture at wi, and S there.
  const float phi = std::atan2(dot(out.wi, f.Z), dot(out.wi, f.Y));
  const float sin_w = std::clamp(dot(out.wi, T), -1.0f, 1.0f), cos_w = safe_sqrt(1 - sin_w * sin_w);
  const std::array<float, 4> M = longitudinal(f, sin_w, cos_w);
  out.pdf = M[3] * lobe_p[3] / (2 * kPi);
  out.S = w.A[3] * (M[3] / (2 * kPi));
  for (int q = 0; q < 3; ++q) {
    const float n = trimmed_logistic(wrap_angle(phi - w.phi(q)), s_);
    out.pdf += M[size_t(q)] * lobe_p[size_t(q)] * n;
    out.S += w.A[size_t(q)] * (M[size_t(q)] * n);
  }
  if (!(out.pdf > 0) || !std::isfinite(out.pdf)) out.pdf = 0;
  return out;
}

HairSample ChiangHair::sample_across(const Vec3f& T, const Vec3f& wo, const Vec3f& sigma_a,
                                     const std::array<float, 4>& u) const {
  const Frame f = frame(T, wo);
  // The entry point j with probability width_weight_[j]; u[0] rescaled to what is left of j's
  // interval chooses the lobe.
  size_t j = 0;
  float below = 0;
  for (; j + 1 < width_weight_.size() && u[0] >= below + width_weight_[j]; ++j) below += width_weight_[j];
  std::array<float, 4> v = u;
  v[0] = std::clamp((u[0] - below) / width_weight_[j], 0.0f, 0.99999994f);
  HairSample out = sample_at(f, sigma_a, width_sin_[j], width_cos_[j], v, false);
  const Across a = evaluate_across(f, out.wi, sigma_a);
  out.S = a.S;
  out.pdf = a.pdf > 0 && std::isfinite(a.pdf) ? a.pdf : 0.0f;
  return out;
}

ChiangHair::Across ChiangHair::evaluate_across(const Vec3f& T, const Vec3f& wo, const Vec3f& wi,
                                               const Vec3f& sigma_a) const {
  return evaluate_across(frame(T, wo), wi, sigma_a);
}

ChiangHair::Across ChiangHair::evaluate_across(const Frame& f, const Vec3f& wi, const Vec3f& sigma_a) const {
  const float sin_i = std::clamp(dot(wi, f.T), -1.0f, 1.0f), cos_i = safe_sqrt(1 - sin_i * sin_i);
  const float phi = std::atan2(dot(wi, f.Z), dot(wi, f.Y));
  const std::array<float, 4> M = longitudinal(f, sin_i, cos_i);
  Across a;
  for (size_t j = 0; j < width_sin_.size(); ++j) {
    const WidthTerms w = width_terms(p_, sigma_a, f.sin_o, f.cos_o, width_sin_[j], width_cos_[j]);
    const std::array<float, 4> lobe_p = lobe_pdf(w.A);
    Vec3f Sj = w.A[3] * (M[3] / (2 * kPi));
    float pdf_j = M[3] * lobe_p[3] / (2 * kPi);
    for (int q = 0; q < 3; ++q) {
      const float n = trimmed_logistic(wrap_angle(phi - w.phi(q)), s_);
      Sj += w.A[size_t(q)] * (M[size_t(q)] * n);
      pdf_j += M[size_t(q)] * lobe_p[size_t(q)] * n;
    }
    a.S += Sj * width_weight_[j];
    a.pdf += pdf_j * width_weight_[j];
  }
  return a;
}

float ChiangHair::pdf(const Vec3f& T, const Vec3f& wo, const Vec3f& wi, float h) const {
  const Frame f = frame(T, wo);
  h = std::clamp(h, -1.0f, 1.0f);
  const WidthTerms w = width_terms(p_, p_.sigma_a, f.sin_o, f.cos_o, h, safe_sqrt(1 - h * h));
  const std::array<float, 4> lobe_p = lobe_pdf(w.A);
  const float sin_i = std::clamp(dot(wi, T), -1.0f, 1.0f), cos_i = safe_sqrt(1 - sin_i * sin_i);
  const float phi = std::atan2(dot(wi, f.Z), dot(wi, f.Y));
  const std::array<float, 4> M = longitudinal(f, sin_i, cos_i);
  float pdf = M[3] * lobe_p[3] / (2 * kPi);
  for (int q = 0; q < 3; ++q) pdf += M[size_t(q)] * lobe_p[size_t(q)] * trimmed_logistic(wrap_angle(phi - w.phi(q)), s_);
  return pdf;
}

namespace {

// Chiang §4.2's fit of the colour of a hair volume against sqrt(sigma_a), by beta_n.
float reflectance_fit(float beta_n) {
  const float b = beta_n;
  return 5.969f - 0.215f * b + 2.532f * b * b - 10.73f * b * b * b + 5.574f * b * b * b * b +
         0.245f * b * b * b * b * b;
}

}  // namespace

Vec3f ChiangHair::sigma_a_from_reflectance(const Vec3f& c, float beta_n) {
  const float d = reflectance_fit(std::clamp(beta_n, 0.0f, 1.0f));
  auto one = [&](float x) {
    const float l = std::log(std::clamp(x, 1e-4f, 1.0f)) / d;
    return l * l;
  };
  return {one(c.x), one(c.y), one(c.z)};
}

Vec3f ChiangHair::reflectance_from_sigma_a(const Vec3f& sigma_a, float beta_n) {
  const float d = reflectance_fit(std::clamp(beta_n, 0.0f, 1.0f));
  auto one = [&](float s) { return std::exp(-std::sqrt(std::max(s, 0.0f)) * d); };
  return {one(sigma_a.x), one(sigma_a.y), one(sigma_a.z)};
}

Vec3f ChiangHair::sigma_a_from_melanin(float eumelanin, float pheomelanin) {
  const Vec3f eu{0.419f, 0.697f, 1.37f}, pheo{0.187f, 0.4f, 1.05f};
  return eu * std::max(eumelanin, 0.0f) + pheo * std::max(pheomelanin, 0.0f);
}

float ChiangHair::beta_m_for_cone_angle(float degrees) {
  const float target = std::max(degrees, 0.0f) * kPi / 180;
  float lo = 0.01f, hi = 1.0f;
  if (std::sqrt(longitudinal_variance(lo)) >= target) return lo;
  if (std::sqrt(longitudinal_variance(hi)) <= target) return hi;
  for (int i = 0; i < 40; ++i) {
    const float mid = 0.5f * (lo + hi);
    (std::sqrt(longitudinal_variance(mid)) < target ? lo : hi) = mid;
  }
  return 0.5f * (lo + hi);
}

}  // namespace darc
