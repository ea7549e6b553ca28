// Shadow, reflection and refraction rays in both hiders against analytic answers and against
// equivalent scenes without the secondary ray: a sphere's shadow boundary, a contact shadow, a
// strand that never shadows itself, a flat mirror against the mirrored scene, glass that bends
// nothing against no glass, total internal reflection, and the pruning and threading contracts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>

#include "support/hider_reference.h"
#include "support/image_compare.h"
#include "support/pixel_measures.h"
#include "support/render.h"
#include "support/test_frames.h"

namespace darc {
namespace {

using test::all_finite;
using test::channel_at;
using test::compare;
using test::kRgb;
using test::orthographic_frame;
using test::perspective_frame;
using test::render_rib;
using test::RenderedFrame;
using test::single_thread;

constexpr HiderKind kHiders[] = {HiderKind::Distance, HiderKind::Stochastic};

bool bitwise_equal(const Image& a, const Image& b) { return a.pixels == b.pixels && a.channel_names == b.channel_names; }

// The orthographic test frames map pixel (i, j) to world x = i + 0.5 - W/2, y = H/2 - j - 0.5.
float world_x(int i, int width) { return float(i) + 0.5f - 0.5f * float(width); }
float world_y(int j, int height) { return 0.5f * float(height) - float(j) - 0.5f; }

// ---------------------------------------------------------------- shadows

// An opaque sphere between a point light and a plane: a plane point is in shadow exactly when the
// segment from it to the light passes within the radius of the centre.
TEST(SecondaryRays, SphereShadowFromAPointLightLandsOnTheAnalyticBoundary) {
  const int w = 96, h = 48;
  const Vec3f light{-30, 0, 0}, centre{0, 0, 10};
  const float radius = 8, plane_z = 20, intensity = 4000, ambient = 0.05f;
  std::ostringstream world;
  world << "LightSource \"ambientlight\" 1 \"intensity\" [" << ambient << "]\n"
        << "LightSource \"pointlight\" 2 \"from\" [" << light.x << " " << light.y << " " << light.z
        << "] \"intensity\" [" << intensity << "] \"string shadowname\" [\"raytrace\"]\n"
        << "Surface \"matte\"\n"
        << "Polygon \"P\" [-60 -40 20  60 -40 20  60 40 20  -60 40 20]\n"
        << "AttributeBegin\nTranslate " << centre.x << " " << centre.y << " " << centre.z << "\nSphere " << radius
        << " " << -radius << " " << radius << " 360\nAttributeEnd\n";
  auto in_shadow = [&](float x, float y) {
    Vec3f p{x, y, plane_z}, d = normalize(light - p);
    Vec3f to_c = centre - p;
    float along = dot(to_c, d);
    return along > 0 && length_squared(to_c - d * along) < radius * radius;
  };
  for (HiderKind hider : kHiders) {
    RenderedFrame f = render_rib(orthographic_frame(w, h, 1, world.str()), single_thread(hider));
    ASSERT_TRUE(all_finite(f.image));
    int shadowed = 0, lit = 0;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const float x = world_x(i, w), y = world_y(j, h);
        if (x * x + y * y < (radius + 2) * (radius + 2)) continue;  // the sphere itself is seen here
        // Pixels whose corners (1.5 pixels out: the footprint reaches past the pixel) agree are
        // wholly on one side of the boundary.
        const bool s = in_shadow(x, y);
        bool decided = true;
        for (float dx : {-1.5f, 1.5f})
          for (float dy : {-1.5f, 1.5f}) decided &= in_shadow(x + dx, y + dy) == s;
        if (!decided) continue;
        auto lit_value = [&](float px, float py) {
          const Vec3f p{px, py, plane_z};
          return ambient + intensity * std::abs(normalize(light - p).z) / length_squared(light - p);
        };
        const float expected = s ? ambient : lit_value(x, y);
        // The stochastic hider's one sample lies anywhere in the pixel: allow the change of the
        // lit value over the pixel, plus rounding.
        float spread = 0;
        if (!s && hider == HiderKind::Stochastic)
          for (float dx : {-0.5f, 0.5f})
            for (float dy : {-0.5f, 0.5f}) spread = std::max(spread, std::abs(lit_value(x + dx, y + dy) - expected));
        EXPECT_NEAR(channel_at(f.image, i, j, "R"), expected, 2e-3f * expected + spread)
            << to_string(hider) << " pixel " << i << "," << j << (s ? " (shadow)" : " (lit)");
        (s ? shadowed : lit) += 1;
      }
    EXPECT_GT(shadowed, 50) << to_string(hider);
    EXPECT_GT(lit, 500) << to_string(hider);
    EXPECT_GT(f.stats.counters.traced_by_kind[int(SecondaryKind::Shadow)], 0u);
  }
}

// A strand lying on a plane, lit from the side at 45 degrees: the plane right beside it is in its
// shadow (an offset as wide as the strand would lose exactly that shadow).
TEST(SecondaryRays, AStrandLyingOnAPlaneCastsAContactShadow) {
  const int w = 32, h = 16;
  const float width = 4, plane_z = 20, ambient = 0.05f;
  std::ostringstream world;
  world << "LightSource \"ambientlight\" 1 \"intensity\" [" << ambient << "]\n"
        << "LightSource \"distantlight\" 2 \"from\" [0 0 0] \"to\" [1 0 1] \"string shadowname\" [\"raytrace\"]\n"
        << "Surface \"matte\"\n"
        << "Polygon \"P\" [-40 -40 20  40 -40 20  40 40 20  -40 40 20]\n"
        << "Curves \"linear\" [2] \"nonperiodic\" \"P\" [0 -20 " << plane_z - width / 2 << "  0 20 "
        << plane_z - width / 2 << "] \"constantwidth\" [" << width << "]\n";
  // The strand (a tube of diameter 4 seen along +z) covers x in [-2, 2]; its shadow along (1, 0, 1)
  // covers x in [2 - 2.83, 2 + 2.83] on the plane.
  const float lit = ambient + std::sqrt(0.5f);
  for (HiderKind hider : kHiders) {
    RenderedFrame f = render_rib(orthographic_frame(w, h, 1, world.str()), single_thread(hider));
    const int row = h / 2;
    for (int i = 0; i < w; ++i) {
      const float x0 = world_x(i, w) - 0.5f, x1 = x0 + 1;
      const float value = channel_at(f.image, i, row, "R");
      if (x0 >= 2 && x1 <= 4.8f) {
        EXPECT_NEAR(value, ambient, 1e-3f) << to_string(hider) << ": the contact shadow at x = " << x0;
      } else if (x0 >= 6 || x1 <= -2) {
        EXPECT_NEAR(value, lit, 1e-3f) << to_string(hider) << ": lit plane at x = " << x0;
      }
    }
  }
}

// A single strand curling around itself, lit by a shadowing light: its shadow rays never see the
// strand they start on, so the image is the one without shadows, bit for bit.
TEST(SecondaryRays, TheOriginStrandNeverShadowsItself) {
  std::ostringstream curl;
  curl << "Surface \"hair\"\nCurves \"cubic\" [13] \"nonperiodic\" \"P\" [";
  for (int k = 0; k < 13; ++k) {
    const float a = 0.9f * float(k);
    curl << 6 * std::cos(a) << " " << 6 * std::sin(a) << " " << 10 + 0.8f * float(k) << "  ";
  }
  curl << "] \"constantwidth\" [1.5]\n";
  auto frame = [&](const char* shadowname) {
    return orthographic_frame(32, 32, 1, std::string("LightSource \"distantlight\" 1 \"from\" [0 0 20] \"to\" [0 0 0] "
                                                     "\"string shadowname\" [\"") +
                                             shadowname + "\"]\n" + curl.str());
  };
  for (HiderKind hider : kHiders) {
    RenderedFrame with = render_rib(frame("raytrace"), single_thread(hider));
    RenderedFrame without = render_rib(frame(""), single_thread(hider));
    EXPECT_GT(with.stats.counters.traced_by_kind[int(SecondaryKind::Shadow)], 0u) << to_string(hider);
    EXPECT_EQ(without.stats.counters.traced_by_kind[int(SecondaryKind::Shadow)], 0u) << to_string(hider);
    EXPECT_TRUE(bitwise_equal(with.image, without.image)) << to_string(hider);
  }
}

// Strands of several widths (a third of a pixel to four pixels) crossing each other over a plane,
// under a shadowing light: the distance hider's shadows converge to the stochastic hider's exact
// ones as its footprints shrink (a shadow ray leaves the part of the footprint the strand fills:
// on its axis when it is thinner than the footprint, where the ray crosses it when wider).
TEST(SecondaryRays, FootprintShadowsConvergeToExactShadows) {
  auto rib = [](int samples) {
    std::ostringstream world;
    world << "LightSource \"ambientlight\" 1 \"intensity\" [0.1]\n"
          << "LightSource \"distantlight\" 2 \"from\" [-1 1 -1] \"to\" [0 0 0] \"string shadowname\" [\"raytrace\"]\n"
          << "AttributeBegin\nSurface \"matte\"\nPolygon \"P\" [-30 -30 30  30 -30 30  30 30 30  -30 30 30]\nAttributeEnd\n"
          << "Surface \"hair\"\n";
    for (int k = 0; k < 12; ++k) {
      const float x = -11 + 2 * float(k), z = 14 + 1.3f * float(k % 5), w = 0.33f + 0.33f * float(k % 12);
      world << "Curves \"cubic\" [4] \"nonperiodic\" \"P\" [" << x << " -14 " << z << "  " << x + 6 << " -5 " << z + 2
            << "  " << x - 6 << " 5 " << z - 2 << "  " << x + 1 << " 14 " << z << "] \"constantwidth\" [" << w << "]\n";
    }
    return orthographic_frame(36, 32, samples, world.str());
  };
  test::HiderComparison c = test::distance_against_stochastic(rib, 6, 24);
  EXPECT_TRUE(c.rgb.all_valid);
  // Measured against stochastic 24x24: 0.0122, 0.0078, 0.0075, 0.0074 at 2x2, 4x4, 6x6, 8x8 (the
  // floor is mostly the reference's noise in the penumbrae); with shadow rays leaving the axis of
  // strands wider than the footprint it was 0.076 to 0.083, growing with the samples.
  EXPECT_LT(c.rgb.rms, 0.015);
}

// Clumps of strands lying side by side over a backdrop, each overlapping its neighbours (axes a
// quarter of a width apart, as combed hair on a scalp), under a point light on the camera's side:
// what the camera sees of each strand is the edge its neighbours leave uncovered, which the light
// reaches; the strand's band as a whole lies under its neighbours' shadows. The distance hider
// shades each strand where its footprint sees it (ABuffer::at_visible_part), as the stochastic
// hider's samples shade what they hit. Measured against stochastic 32x32: distance 1x1 RMSE
// 0.025 (stochastic 2x2: 0.043); shaded on its band's centre it was 0.049.
TEST(SecondaryRays, ClumpedStrandsAreShadedWhereTheyAreSeen) {
  auto rib = [](int samples) {
    std::ostringstream world;
    world << "LightSource \"ambientlight\" 1 \"intensity\" [0.05]\n"
          << "LightSource \"pointlight\" 2 \"from\" [0 15 -20] \"intensity\" [2500] "
             "\"string shadowname\" [\"raytrace\"]\n"
          << "Surface \"matte\"\nColor [0.5 0.5 0.5]\n"
          << "Polygon \"P\" [-40 -30 40.8  40 -30 40.8  40 30 40.8  -40 30 40.8]\nColor [1 0.8 0.6]\n";
    for (int clump = 0; clump < 5; ++clump)
      for (int k = 0; k < 6; ++k) {
        // A fixed jitter of the spacing, so that no two strands are exactly a step apart.
        const float y = -6 + 2.6f * float(clump) + 0.3f * float(k) + 0.04f * float((7 * k + 3 * clump) % 5 - 2);
        world << "Curves \"linear\" [2] \"nonperiodic\" \"P\" [-30 " << y << " 40  30 " << y + 0.8f
              << " 40] \"constantwidth\" [1.2]\n";
      }
    return perspective_frame(48, 32, samples, 60, "", world.str());
  };
  const test::HiderComparison distance = test::distance_against_stochastic(rib, 1, 32);
  const Image reference = render_rib(rib(32), single_thread(HiderKind::Stochastic)).image;
  const Image stochastic = render_rib(rib(2), single_thread(HiderKind::Stochastic)).image;
  const test::RgbComparison two_by_two = test::compare_rgb(stochastic, reference);
  std::printf("distance 1x1 RMSE %.4f, stochastic 2x2 %.4f\n", distance.rgb.rms, two_by_two.rms);
  EXPECT_TRUE(distance.rgb.all_valid);
  EXPECT_LT(distance.rgb.rms, two_by_two.rms);
}

// ---------------------------------------------------------------- reflection and refraction

std::string strands_world(float z) {
  std::ostringstream s;
  s << "AttributeBegin\nSurface \"constant\"\nColor [0.9 0.6 0.3]\n";
  for (int k = -3; k <= 3; ++k)
    s << "Curves \"cubic\" [4] \"nonperiodic\" \"P\" [" << 3 * k << " -5 " << z << "  " << 3 * k + 2 << " -1 " << z << "  "
      << 3 * k - 2 << " 2 " << z << "  " << 3 * k + 1 << " 5 " << z << "] \"constantwidth\" [0.08]\n";
  s << "AttributeEnd\n";
  return s.str();
}

// Hair behind the camera seen in a flat mirror equals the hair mirrored behind the mirror seen
// directly: the reflected footprint is the direct one, so the distance hider at one ray per pixel
// gives the same smooth coverage.
TEST(SecondaryRays, AFlatMirrorShowsTheMirroredScene) {
  const std::string camera = "";
  const float mirror_z = 20, hair_z = -10;
  const std::string mirror =
      "AttributeBegin\nSurface \"mirror\" \"Ks\" [0]\nPolygon \"P\" [-100 -100 20  100 -100 20  100 100 20  -100 100 20]\n"
      "AttributeEnd\n";
  const std::string in_mirror = perspective_frame(48, 48, 1, 40, camera, mirror + strands_world(hair_z));
  const std::string mirrored = perspective_frame(48, 48, 1, 40, camera, strands_world(2 * mirror_z - hair_z));
  for (HiderKind hider : kHiders) {
    RenderedFrame a = render_rib(in_mirror, single_thread(hider));
    RenderedFrame b = render_rib(mirrored, single_thread(hider));
    ASSERT_TRUE(all_finite(a.image));
    EXPECT_GT(a.stats.counters.traced_by_kind[int(SecondaryKind::Reflection)], 0u);
    // Mirror images: x flips in neither (the mirror is perpendicular to the view axis).
    EXPECT_LT(compare(a.image, b.image, kRgb).rmse, 2e-3) << to_string(hider);
  }
}

// Glass with eta 1, no reflection and full transmission bends nothing and hides nothing. Inside
// the glass's silhouette the images agree to rounding; on it the distance hider's glass fragment
// covers part of the footprint while its refracted ray carries the whole footprint, so strands
// crossing the silhouette are counted a little twice there (the bound on the whole image).
TEST(SecondaryRays, GlassWithEtaOneIsNoGlass) {
  const int w = 32, h = 24;
  const float radius = 9;
  const std::string glass =
      "AttributeBegin\nSurface \"glass\" \"eta\" [1] \"Kr\" [0] \"Kt\" [1] \"Ka\" [0] \"Kd\" [0] \"Ks\" [0]\n"
      "Translate 0 0 15\nSphere 9 -9 9 360\nAttributeEnd\n";
  const std::string with_glass = orthographic_frame(w, h, 1, glass + strands_world(30));
  const std::string without = orthographic_frame(w, h, 1, strands_world(30));
  for (HiderKind hider : kHiders) {
    RenderedFrame a = render_rib(with_glass, single_thread(hider));
    RenderedFrame b = render_rib(without, single_thread(hider));
    EXPECT_GT(a.stats.counters.traced_by_kind[int(SecondaryKind::Refraction)], 0u);
    float inside_max = 0;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const float x = world_x(i, w), y = world_y(j, h);
        if (x * x + y * y > (radius - 1.5f) * (radius - 1.5f)) continue;
        for (const char* c : {"R", "G", "B"})
          inside_max = std::max(inside_max, std::abs(channel_at(a.image, i, j, c) - channel_at(b.image, i, j, c)));
      }
    EXPECT_LT(inside_max, 1e-4f) << to_string(hider);
    EXPECT_LT(compare(a.image, b.image, kRgb).rmse, 5e-3) << to_string(hider);
  }
}

// A ray leaving glass past the critical angle is reflected entirely (no refracted ray); a glass
// sphere's silhouette gives grazing rays. Neither gives a NaN or a negative value.
TEST(SecondaryRays, TotalInternalReflectionAndGrazingRaysStayFinite) {
  // The polygon's normal points away from the camera (+z), so camera rays leave the glass
  // (eta 1.5 -> 1) at 60 degrees: past the critical angle of 41.8 degrees.
  const std::string leaving =
      "LightSource \"distantlight\" 1 \"from\" [0 0 0] \"to\" [0 0 1]\n"
      "AttributeBegin\nSurface \"glass\"\nRotate 60 0 1 0\n"
      "Polygon \"P\" [-100 -100 30  100 -100 30  100 100 30  -100 100 30]\nAttributeEnd\n";
  const std::string sphere =
      "LightSource \"distantlight\" 1 \"from\" [0 0 0] \"to\" [0 0 1]\n"
      "AttributeBegin\nSurface \"glass\"\nTranslate 0 0 20\nSphere 10 -10 10 360\nAttributeEnd\n" +
      strands_world(40);
  for (HiderKind hider : kHiders) {
    RenderedFrame tir = render_rib(orthographic_frame(24, 24, 1, leaving), single_thread(hider));
    EXPECT_TRUE(all_finite(tir.image)) << to_string(hider);
    EXPECT_GT(tir.stats.counters.traced_by_kind[int(SecondaryKind::Reflection)], 0u);
    EXPECT_EQ(tir.stats.counters.traced_by_kind[int(SecondaryKind::Refraction)], 0u)
        << to_string(hider) << ": total internal reflection everywhere";
    RenderedFrame grazing = render_rib(orthographic_frame(24, 24, 2, sphere), single_thread(hider));
    EXPECT_TRUE(all_finite(grazing.image)) << to_string(hider);
    for (float v : grazing.image.pixels) EXPECT_GE(v, 0.0f);
  }
}

// ---------------------------------------------------------------- pruning and determinism

std::string shadowed_hair_scene() {
  std::ostringstream world;
  world << "LightSource \"ambientlight\" 1 \"intensity\" [0.1]\n"
        << "LightSource \"spotlight\" 2 \"from\" [-20 10 -10] \"to\" [0 0 20] \"intensity\" [1500] "
           "\"coneangle\" [0.8] \"string shadowname\" [\"raytrace\"]\n"
        << "AttributeBegin\nSurface \"matte\"\nPolygon \"P\" [-30 -30 25  30 -30 25  30 30 25  -30 30 25]\nAttributeEnd\n"
        << "AttributeBegin\nSurface \"shinymetal\" \"Kr\" [0.3]\nTranslate 8 -6 18\nSphere 5 -5 5 360\nAttributeEnd\n"
        << "AttributeBegin\nSurface \"hair\"\nOpacity [0.6 0.6 0.6]\n";
  for (int k = 0; k < 40; ++k) {
    const float x = -15 + 0.75f * float(k), z = 12 + 0.2f * float(k % 7);
    world << "Curves \"cubic\" [4] \"nonperiodic\" \"P\" [" << x << " -12 " << z << "  " << x + 2 << " -4 " << z - 1
          << "  " << x - 2 << " 4 " << z + 1 << "  " << x + 1 << " 12 " << z << "] \"constantwidth\" [0.3]\n";
  }
  world << "AttributeEnd\n";
  return orthographic_frame(48, 32, 1, world.str());
}

// Threshold 0 traces every secondary ray; a threshold below every non-zero weight prunes only
// rays that could not change anything, so the image is the same bit for bit; a large threshold
// prunes, and what it costs is measured by the benchmark (docs/performance-secondary.md).
TEST(SecondaryRays, ThresholdZeroTracesEveryRay) {
  const std::string rib = shadowed_hair_scene();
  for (HiderKind hider : kHiders) {
    RenderOptions all = single_thread(hider);
    all.contribution_threshold = 0;
    RenderOptions tiny = all;
    tiny.contribution_threshold = std::numeric_limits<float>::denorm_min();
    RenderOptions coarse = all;
    coarse.contribution_threshold = 0.1f;
    RenderedFrame a = render_rib(rib, all), b = render_rib(rib, tiny), c = render_rib(rib, coarse);
    EXPECT_EQ(a.stats.counters.pruned_rays, 0u) << to_string(hider);
    for (int k = 0; k < kSecondaryKinds; ++k) EXPECT_EQ(a.stats.counters.pruned_by_kind[k], 0u);
    EXPECT_GT(a.stats.counters.traced_by_kind[int(SecondaryKind::Shadow)], 0u);
    EXPECT_GT(a.stats.counters.traced_by_kind[int(SecondaryKind::Reflection)], 0u);
    EXPECT_TRUE(bitwise_equal(a.image, b.image)) << to_string(hider);
    EXPECT_GT(c.stats.counters.pruned_rays, 0u) << to_string(hider);
    // Each ray the pruned render considered (traced or pruned) is one the full render traced.
    EXPECT_GE(a.stats.counters.secondary_rays, c.stats.counters.secondary_rays + c.stats.counters.pruned_rays)
        << to_string(hider);
    EXPECT_TRUE(all_finite(c.image));
  }
}

TEST(SecondaryRays, OneAndTwoThreadsGiveTheSameImage) {
  const std::string rib = shadowed_hair_scene();
  for (HiderKind hider : kHiders) {
    RenderOptions one = single_thread(hider), two = one;
    two.threads = 2;
    RenderedFrame a = render_rib(rib, one), b = render_rib(rib, two);
    EXPECT_TRUE(bitwise_equal(a.image, b.image)) << to_string(hider);
    EXPECT_EQ(a.stats.counters.secondary_rays, b.stats.counters.secondary_rays);
  }
}

}  // namespace
}  // namespace darc
