// The Chiang et al. 2016 hair fibre model (shading/chiang_hair.h) against its own invariants,
// the checks pbrt-v4's hair tests make (src/pbrt/bsdfs_test.cpp) with tighter bounds: an exact
// Bessel function leaves the white furnace at quadrature precision, not at pbrt's 5 %.
//
// Reciprocity is not tested: the near-field model ties h to wo, so S(wo, wi) != S(wi, wo) in
// general (pbrt-v4 compiles its reciprocity test out for that reason; lookdev.md §1.8).
#include "shading/chiang_hair.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace darc {
namespace {

constexpr double kPi = std::numbers::pi;

Vec3f direction(double theta, double phi, const Vec3f& T, const Vec3f& Y, const Vec3f& Z) {
  return normalize(T * float(std::sin(theta)) + (Y * float(std::cos(phi)) + Z * float(std::sin(phi))) * float(std::cos(theta)));
}

// The integral of f(wi) over the sphere, on a grid of theta (angle to the fibre's normal plane)
// and phi, midpoints: dw = cos(theta) dtheta dphi.
template <class F>
Vec3f sphere_integral(F&& f, int n_theta, int n_phi) {
  const Vec3f T{0, 0, 1}, Y{1, 0, 0}, Z{0, 1, 0};
  Vec3f sum;
  const double dt = kPi / n_theta, dp = 2 * kPi / n_phi;
  for (int i = 0; i < n_theta; ++i) {
    const double theta = -kPi / 2 + (i + 0.5) * dt;
    Vec3f row;
    for (int j = 0; j < n_phi; ++j) row += f(direction(theta, -kPi + (j + 0.5) * dp, T, Y, Z));
    sum += row * float(std::cos(theta) * dt * dp);
  }
  return sum;
}

ChiangHairParams params(float beta_m, float beta_n, Vec3f sigma_a = {}) {
  ChiangHairParams p;
  p.sigma_a = sigma_a;
  p.beta_m = beta_m;
  p.beta_n = beta_n;
  return p;
}

const Vec3f kTangent{0, 0, 1};

Vec3f view(double theta_o) { return direction(theta_o, 0.3, kTangent, {1, 0, 0}, {0, 1, 0}); }

TEST(ChiangHair, WhiteFurnace) {
  // Without absorption every ray that enters leaves: S integrates to 1 over the sphere, for
  // every roughness, view and entry point.
  const std::pair<float, float> roughness[] = {{0.1f, 0.1f}, {0.1f, 0.9f}, {0.3f, 0.3f}, {0.6f, 0.2f},
                                                {0.2f, 0.6f}, {0.9f, 0.1f}, {0.9f, 0.9f}};
  for (auto [beta_m, beta_n] : roughness) {
      const ChiangHair hair(params(beta_m, beta_n));
      for (double theta_o : {-1.2, 0.9})
        for (float h : {-0.8f, 0.95f}) {
          const Vec3f wo = view(theta_o);
          const Vec3f albedo =
              sphere_integral([&](const Vec3f& wi) { return hair.scattering(kTangent, wo, wi, h); }, 360, 720);
          EXPECT_NEAR(albedo.x, 1.0f, 2e-3f) << "beta_m " << beta_m << " beta_n " << beta_n << " theta_o "
                                              << theta_o << " h " << h;
          EXPECT_NEAR(albedo.z, albedo.x, 1e-6f);
        }
    }
}

TEST(ChiangHair, AbsorptionLosesEnergyAsTheAttenuationsSay) {
  // With absorption the integral is the sum of the lobes' attenuations: below 1, and less for
  // the channel that absorbs more.
  const ChiangHair hair(params(0.3f, 0.3f, {0.2f, 0.5f, 1.0f}));
  for (double theta_o : {-0.7, 0.4})
    for (float h : {-0.5f, 0.3f}) {
      const Vec3f wo = view(theta_o);
      const Vec3f albedo =
          sphere_integral([&](const Vec3f& wi) { return hair.scattering(kTangent, wo, wi, h); }, 240, 480);
      const std::array<Vec3f, 4> A = hair.attenuation(dot(wo, kTangent), h);
      const Vec3f sum = A[0] + A[1] + A[2] + A[3];
      EXPECT_NEAR(albedo.x, sum.x, 2e-3f);
      EXPECT_NEAR(albedo.y, sum.y, 2e-3f);
      EXPECT_NEAR(albedo.z, sum.z, 2e-3f);
      EXPECT_LT(albedo.x, 1.0f);
      EXPECT_LT(albedo.y, albedo.x);
      EXPECT_LT(albedo.z, albedo.y);
    }
  // Without absorption the attenuations are a partition of the light.
  const ChiangHair clear(params(0.3f, 0.3f));
  for (float s : {-0.99f, -0.3f, 0.0f, 0.7f})
    for (float h : {-0.999f, -0.4f, 0.0f, 0.6f, 0.999f}) {
      const std::array<Vec3f, 4> A = clear.attenuation(s, h);
      EXPECT_NEAR((A[0] + A[1] + A[2] + A[3]).x, 1.0f, 1e-5f) << s << " " << h;
    }
}

TEST(ChiangHair, SamplingWeightsAreOneWithoutAbsorption) {
  // Lobes are picked by their share of the (grey) attenuation, so without absorption the density
  // is S itself and every weight S / pdf is 1.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  for (float beta : {0.1f, 0.3f, 0.7f}) {
    const ChiangHair hair(params(beta, beta));
    for (int i = 0; i < 2000; ++i) {
      const Vec3f wo = view(std::asin(2 * double(uni(rng)) - 1));
      const float h = 2 * uni(rng) - 1;
      const HairSample s = hair.sample(kTangent, wo, h, {uni(rng), uni(rng), uni(rng), uni(rng)});
      ASSERT_GT(s.pdf, 0.0f);
      EXPECT_NEAR(s.S.x / s.pdf, 1.0f, 1e-3f);
    }
  }
}

TEST(ChiangHair, SampleAgreesWithScatteringAndPdf) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  const ChiangHair hair(params(0.25f, 0.4f, {0.3f, 0.6f, 1.2f}));
  for (int i = 0; i < 500; ++i) {
    const Vec3f wo = view(std::asin(2 * double(uni(rng)) - 1));
    const float h = 2 * uni(rng) - 1;
    const HairSample s = hair.sample(kTangent, wo, h, {uni(rng), uni(rng), uni(rng), uni(rng)});
    ASSERT_GT(s.pdf, 0.0f);
    const Vec3f S = hair.scattering(kTangent, wo, s.wi, h);
    EXPECT_NEAR(s.S.y, S.y, 1e-4f * std::max(1.0f, S.y));
    EXPECT_NEAR(s.pdf, hair.pdf(kTangent, wo, s.wi, h), 1e-4f * std::max(1.0f, s.pdf));
  }
}

TEST(ChiangHair, PdfIntegratesToOne) {
  const ChiangHair hair(params(0.3f, 0.3f, {0.4f, 0.4f, 0.4f}));
  for (double theta_o : {-0.5, 0.8}) {
    const Vec3f wo = view(theta_o);
    const Vec3f total = sphere_integral(
        [&](const Vec3f& wi) {
          const float p = hair.pdf(kTangent, wo, wi, 0.35f);
          return Vec3f{p, p, p};
        },
        240, 480);
    EXPECT_NEAR(total.x, 1.0f, 2e-3f);
  }
}

// A histogram of directions drawn by `draw(u)` over (sin theta_i, phi) cells against each cell's
// probability from `pdf(wi)`: the chi-square statistic stays within what chance gives.
template <class Draw, class Pdf>
void expect_directions_follow(Draw&& draw, Pdf&& pdf, unsigned seed) {
  constexpr int kRows = 16, kCols = 32, kSamples = 400000;
  std::vector<double> count(kRows * kCols, 0.0), expected(kRows * kCols, 0.0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  for (int i = 0; i < kSamples; ++i) {
    const HairSample s = draw(std::array<float, 4>{uni(rng), uni(rng), uni(rng), uni(rng)});
    const double z = std::clamp(double(s.wi.z), -1.0, 1.0), phi = std::atan2(double(s.wi.y), double(s.wi.x));
    const int r = std::min(kRows - 1, int((z + 1) / 2 * kRows)), c = std::min(kCols - 1, int((phi + kPi) / (2 * kPi) * kCols));
    count[size_t(r * kCols + c)] += 1;
  }
  // dw = d(sin theta) dphi: each cell integrated on an 8 x 8 grid of its own.
  for (int r = 0; r < kRows; ++r)
    for (int c = 0; c < kCols; ++c) {
      double p = 0;
      for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b) {
          const double z = -1 + (r + (a + 0.5) / 8) * 2.0 / kRows, phi = -kPi + (c + (b + 0.5) / 8) * 2 * kPi / kCols;
          const double ct = std::sqrt(std::max(0.0, 1 - z * z));
          const Vec3f wi{float(ct * std::cos(phi)), float(ct * std::sin(phi)), float(z)};
          p += pdf(wi);
        }
      expected[size_t(r * kCols + c)] = p / 64 * (2.0 / kRows) * (2 * kPi / kCols) * kSamples;
    }
  double chi2 = 0, total_expected = 0;
  int cells = 0;
  for (size_t i = 0; i < count.size(); ++i) {
    total_expected += expected[i];
    if (expected[i] < 5) continue;
    chi2 += (count[i] - expected[i]) * (count[i] - expected[i]) / expected[i];
    ++cells;
  }
  EXPECT_NEAR(total_expected, kSamples, 0.01 * kSamples);
  // Mean cells - 1, standard deviation sqrt(2 (cells - 1)): six deviations is never chance.
  EXPECT_LT(chi2, cells + 6 * std::sqrt(2.0 * cells)) << cells << " cells";
}

TEST(ChiangHair, SampledDirectionsFollowThePdf) {
  const ChiangHair hair(params(0.35f, 0.35f, {0.25f, 0.25f, 0.25f}));
  const Vec3f wo = view(0.45);
  const float h = -0.3f;
  expect_directions_follow([&](const std::array<float, 4>& u) { return hair.sample(kTangent, wo, h, u); },
                           [&](const Vec3f& wi) { return hair.pdf(kTangent, wo, wi, h); }, 3);
}

// Across the width (what the shader draws under a dome, shading/surface_shader.cpp): the entry
// point is drawn from the width quadrature, and the density is the quadrature's mean.
TEST(ChiangHair, DirectionsDrawnAcrossTheWidthFollowTheirPdf) {
  const Vec3f sigma_a{0.25f, 0.5f, 1.0f};
  const ChiangHair hair(params(0.3f, 0.3f));
  const Vec3f wo = view(-0.6);
  expect_directions_follow([&](const std::array<float, 4>& u) { return hair.sample_across(kTangent, wo, sigma_a, u); },
                           [&](const Vec3f& wi) { return hair.evaluate_across(kTangent, wo, wi, sigma_a).pdf; }, 5);
}

TEST(ChiangHair, SamplesAcrossTheWidthCarryScatteringAcrossAndTheirDensity) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  const Vec3f sigma_a{0.3f, 0.6f, 1.2f};
  const ChiangHair hair(params(0.25f, 0.4f));
  for (int i = 0; i < 300; ++i) {
    const Vec3f wo = view(std::asin(2 * double(uni(rng)) - 1));
    const HairSample s = hair.sample_across(kTangent, wo, sigma_a, {uni(rng), uni(rng), uni(rng), uni(rng)});
    ASSERT_GT(s.pdf, 0.0f);
    const Vec3f S = hair.scattering_across(kTangent, wo, s.wi, sigma_a);
    EXPECT_NEAR(s.S.z, S.z, 1e-5f * std::max(1.0f, S.z));
    EXPECT_NEAR(s.pdf, hair.evaluate_across(kTangent, wo, s.wi, sigma_a).pdf, 1e-5f * std::max(1.0f, s.pdf));
  }
  // The density across the width integrates to one over the sphere.
  for (double theta_o : {-0.9, 0.2}) {
    const Vec3f wo = view(theta_o);
    const Vec3f total = sphere_integral(
        [&](const Vec3f& wi) {
          const float p = hair.evaluate_across(kTangent, wo, wi, sigma_a).pdf;
          return Vec3f{p, p, p};
        },
        240, 480);
    EXPECT_NEAR(total.x, 1.0f, 2e-3f) << theta_o;
  }
}

TEST(ChiangHair, DrawingAcrossTheWidthEstimatesTheFurnaceWithLittleNoise) {
  // Without absorption the fibre's S across the width integrates to 1. Drawn by its lobes, 256
  // random directions estimate it within 2 % even for narrow lobes (beta 0.1), where directions
  // drawn uniformly over the sphere scatter by far more (the spread checked too).
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  for (float beta : {0.1f, 0.3f, 0.7f}) {
    const ChiangHair hair(params(beta, beta));
    for (double theta_o : {-1.0, 0.0, 0.7}) {
      const Vec3f wo = view(theta_o);
      double lobes = 0, uniform = 0, uniform_sq = 0;
      constexpr int kN = 256;
      for (int i = 0; i < kN; ++i) {
        const HairSample s = hair.sample_across(kTangent, wo, {}, {uni(rng), uni(rng), uni(rng), uni(rng)});
        ASSERT_GT(s.pdf, 0.0f);
        lobes += s.S.x / s.pdf;
        const float z = 1 - 2 * uni(rng), phi = float(2 * kPi) * uni(rng), r = std::sqrt(std::max(0.0f, 1 - z * z));
        const double u = 4 * kPi * hair.scattering_across(kTangent, wo, {r * std::cos(phi), r * std::sin(phi), z}).x;
        uniform += u;
        uniform_sq += u * u;
      }
      EXPECT_NEAR(lobes / kN, 1.0, 0.02) << "beta " << beta << " theta_o " << theta_o;
      if (beta <= 0.3f) {
        const double sd = std::sqrt(std::max(0.0, uniform_sq / kN - (uniform / kN) * (uniform / kN)) / kN);
        EXPECT_GT(sd, 0.05) << "uniform directions' standard error, beta " << beta;
      }
    }
  }
}

TEST(ChiangHair, AcrossTheWidthIsTheMeanOverEntryPoints) {
  // scattering_across is the mean of S over h in [-1, 1]: against a fine midpoint rule in h.
  for (float beta_n : {0.2f, 0.3f, 0.6f}) {
    const ChiangHair hair(params(0.3f, beta_n, {0.1f, 0.3f, 0.6f}));
    const Vec3f wo = view(0.3);
    double worst = 0, peak = 0;
    for (int k = 0; k < 72; ++k) {
      const Vec3f wi = direction(-0.2, -kPi + (k + 0.5) * 2 * kPi / 72, kTangent, {1, 0, 0}, {0, 1, 0});
      Vec3f fine;
      constexpr int kH = 4000;
      for (int j = 0; j < kH; ++j) fine += hair.scattering(kTangent, wo, wi, -1 + (j + 0.5f) * 2.0f / kH);
      fine = fine * (1.0f / kH);
      const Vec3f across = hair.scattering_across(kTangent, wo, wi);
      worst = std::max(worst, double(std::abs(across.x - fine.x)));
      peak = std::max(peak, double(fine.x));
    }
    EXPECT_LT(worst, 0.02 * peak) << "beta_n " << beta_n << ": " << hair.width_points() << " points";
  }
}

TEST(ChiangHair, EdgesAndGrazingGiveFiniteValues) {
  const ChiangHair hair(params(0.01f, 0.01f));
  for (float h : {-1.0f, 1.0f, 0.0f})
    for (const Vec3f& wo : {kTangent, -kTangent, Vec3f{1, 0, 0}}) {
      const Vec3f S = hair.scattering(kTangent, wo, normalize(Vec3f{0.3f, 0.2f, 0.9f}), h);
      EXPECT_TRUE(std::isfinite(S.x) && std::isfinite(S.y) && std::isfinite(S.z)) << h;
      EXPECT_GE(S.x, 0.0f);
      const HairSample s = hair.sample(kTangent, wo, h, {0.5f, 0.0f, 0.99f, 0.999f});
      EXPECT_TRUE(std::isfinite(s.pdf) && std::isfinite(s.wi.x) && std::isfinite(s.S.x));
    }
}

TEST(ChiangHair, ColourInversionRoundTrips) {
  for (float beta_n : {0.0f, 0.3f, 1.0f})
    for (float c = 0.01f; c <= 1.0f; c += 0.0625f) {
      const Vec3f back =
          ChiangHair::reflectance_from_sigma_a(ChiangHair::sigma_a_from_reflectance({c, c, c}, beta_n), beta_n);
      EXPECT_NEAR(back.x, c, 1e-5f);
    }
  // Darker colours absorb more; white absorbs nothing.
  const Vec3f s = ChiangHair::sigma_a_from_reflectance({1.0f, 0.5f, 0.1f}, 0.3f);
  EXPECT_EQ(s.x, 0.0f);
  EXPECT_LT(s.y, s.z);
  // lookdev.md §1.4: c = 0.1 and 0.5 at beta_n 0.3 give 0.153 and 0.0139.
  EXPECT_NEAR(ChiangHair::sigma_a_from_reflectance({0.1f, 0.5f, 0.5f}, 0.3f).x, 0.153f, 1e-3f);
  EXPECT_NEAR(ChiangHair::sigma_a_from_reflectance({0.1f, 0.5f, 0.5f}, 0.3f).y, 0.0139f, 1e-4f);
  // pbrt-v4's melanin coefficients: eumelanin absorbs blue most.
  const Vec3f brown = ChiangHair::sigma_a_from_melanin(1.3f, 0);
  EXPECT_NEAR(brown.x, 1.3f * 0.419f, 1e-6f);
  EXPECT_LT(brown.x, brown.z);
}

TEST(ChiangHair, ConeAngleMapsToLongitudinalRoughness) {
  // lookdev.md §1.6: a cone of 8 degrees is beta_m 0.163, of 2 degrees 0.046.
  EXPECT_NEAR(ChiangHair::beta_m_for_cone_angle(8), 0.163f, 2e-3f);
  EXPECT_NEAR(ChiangHair::beta_m_for_cone_angle(2), 0.046f, 2e-3f);
  for (float deg : {3.0f, 10.0f, 30.0f}) {
    const float b = ChiangHair::beta_m_for_cone_angle(deg);
    EXPECT_NEAR(std::sqrt(ChiangHair::longitudinal_variance(b)) * 180 / float(kPi), deg, 1e-3f);
  }
}

}  // namespace
}  // namespace darc
