// The helpers the hard-case tests share (this folder is one test executable, so they are
// defined once here and declared where used): parse a RIB string, build its one frame, render
// it in memory, and small measures over the result.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>

#include "hardcases/render_rib.h"

#include "core/scene/builder/scene_builder.h"
#include "integrator/render_frame.h"
#include "parser/rib_parser.h"

namespace darc::test {


// Alpha above 1 by less than this is float rounding of a sum of filter weights.
constexpr float kAlphaRounding = 1e-5f;

RenderOptions single_thread(HiderKind hider) {
  RenderOptions o;
  o.hider = hider;
  o.threads = 1;
  return o;
}

RenderedFrame render_rib(const std::string& rib, const RenderOptions& options) {
  int errors = 0;
  Diagnostics diag([&](const Diagnostic& d) {
    if (d.severity == Severity::Error) {
      ++errors;
      ADD_FAILURE() << d.str();
    }
  });
  std::optional<Scene> scene;
  SceneBuilder::Callbacks callbacks;
  callbacks.frame_ready = [&](Scene&& s) { scene.emplace(std::move(s)); };
  SceneBuilder builder(diag, callbacks);
  RibParser parser(builder, diag);
  parser.parse_string(rib, "test.rib");
  builder.finish(SourceLoc{});
  RenderedFrame out;
  if (!scene) {
    ADD_FAILURE() << "the RIB gave no frame (" << errors << " errors)";
    return out;
  }
  scene->build_acceleration();
  out.image = render_frame(*scene, options, diag, out.stats);
  return out;
}

std::string orthographic_frame(int width, int height, int samples, const std::string& world) {
  std::ostringstream s;
  s << std::setprecision(9) << "Format " << width << " " << height << " 1\n"
    << "PixelSamples " << samples << " " << samples << "\n"
    << "PixelFilter \"box\" 1 1\n"
    << "Projection \"orthographic\"\n"
    << "ScreenWindow " << -0.5 * width << " " << 0.5 * width << " " << -0.5 * height << " " << 0.5 * height << "\n"
    << "WorldBegin\nSurface \"constant\"\n"
    << world << "WorldEnd\n";
  return s.str();
}

std::string perspective_frame(int width, int height, int samples, float fov_degrees, const std::string& camera,
                              const std::string& world) {
  std::ostringstream s;
  s << std::setprecision(9) << "Format " << width << " " << height << " 1\n"
    << "PixelSamples " << samples << " " << samples << "\n"
    << "PixelFilter \"box\" 1 1\n"
    << "Projection \"perspective\" \"fov\" [" << fov_degrees << "]\n"
    << camera << "\nWorldBegin\nSurface \"constant\"\n"
    << world << "WorldEnd\n";
  return s.str();
}

float alpha_at(const Image& image, int x, int y) { return image.at(x, y, image.channel_index("A")); }

AlphaComparison compare_alpha(const Image& test, const Image& reference) {
  AlphaComparison c;
  double sum_test = 0;
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x) {
      float a = alpha_at(test, x, y), r = alpha_at(reference, x, y);
      if (!std::isfinite(a) || a < 0.0f || a > 1.0f + kAlphaRounding) c.all_valid = false;
      c.max_pixel = std::max(c.max_pixel, std::abs(a - r));
      sum_test += a;
      c.reference_total += r;
    }
  c.total_relative = c.reference_total > 0 ? std::abs(sum_test - c.reference_total) / c.reference_total : sum_test;
  return c;
}

AlphaComparison distance_against_reference(const std::function<std::string(int samples)>& rib, CoverageModel model) {
  RenderOptions reference_options = single_thread(HiderKind::Stochastic);
  Image reference = render_rib(rib(kReferenceSamples), reference_options).image;
  RenderOptions options = single_thread(HiderKind::Distance);
  options.distance.coverage = model;
  Image image = render_rib(rib(1), options).image;
  AlphaComparison c = compare_alpha(image, reference);
  if (std::getenv("DARC_TEST_DUMP_ALPHA")) {  // debugging aid: both alpha maps, side by side
    for (int y = 0; y < reference.height; ++y) {
      for (int x = 0; x < reference.width; ++x) std::fprintf(stderr, "%5.2f", alpha_at(image, x, y));
      std::fprintf(stderr, "   |");
      for (int x = 0; x < reference.width; ++x) std::fprintf(stderr, "%5.2f", alpha_at(reference, x, y));
      std::fprintf(stderr, "\n");
    }
  }
  // The reference must itself be valid: the stochastic hider meets the same hard case.
  AlphaComparison self = compare_alpha(reference, reference);
  c.all_valid = c.all_valid && self.all_valid;
  return c;
}

RgbComparison compare_rgb(const Image& test, const Image& reference) {
  RgbComparison c;
  double sum_squares = 0;
  long count = 0;
  for (const char* name : {"R", "G", "B"}) {
    const int ct = test.channel_index(name), cr = reference.channel_index(name);
    for (int y = 0; y < reference.height; ++y)
      for (int x = 0; x < reference.width; ++x) {
        float a = test.at(x, y, ct), r = reference.at(x, y, cr);
        if (!std::isfinite(a) || a < 0.0f || !std::isfinite(r) || r < 0.0f) c.all_valid = false;
        c.max_pixel = std::max(c.max_pixel, std::abs(a - r));
        sum_squares += double(a - r) * double(a - r);
        ++count;
      }
  }
  c.rms = count > 0 ? std::sqrt(sum_squares / double(count)) : 0.0;
  return c;
}

HiderComparison distance_against_stochastic(const std::function<std::string(int samples)>& rib, int distance_samples,
                                            int reference_samples) {
  Image reference = render_rib(rib(reference_samples), single_thread(HiderKind::Stochastic)).image;
  Image image = render_rib(rib(distance_samples), single_thread(HiderKind::Distance)).image;
  HiderComparison c{compare_alpha(image, reference), compare_rgb(image, reference)};
  AlphaComparison self = compare_alpha(reference, reference);
  RgbComparison self_rgb = compare_rgb(reference, reference);
  c.alpha.all_valid = c.alpha.all_valid && self.all_valid;
  c.rgb.all_valid = c.rgb.all_valid && self_rgb.all_valid;
  return c;
}

}  // namespace darc::test
