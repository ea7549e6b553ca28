#include "support/render.h"

#include <gtest/gtest.h>

#include <optional>
#include <sstream>

#include "support/scenes_from_rib.h"

namespace darc::test {

RenderOptions render_options(HiderKind hider, int threads) {
  RenderOptions options;
  options.hider = hider;
  options.threads = threads;
  return options;
}

RenderedFrame render(const Scene& scene, const RenderOptions& options) {
  Diagnostics diag([](const Diagnostic& d) {
    if (d.severity == Severity::Error) ADD_FAILURE() << d.str();
  });
  RenderedFrame out;
  out.image = render_frame(scene, options, diag, out.stats);
  return out;
}

RenderedFrame render_rib(const std::string& rib, const RenderOptions& options) {
  const std::optional<Scene> scene = build_frame(rib);
  if (!scene) return {};
  return render(*scene, options);
}

Image render_image(const Scene& scene, HiderKind hider, int threads) {
  return render(scene, render_options(hider, threads)).image;
}

Image render_image(const std::string& rib, HiderKind hider, int threads) {
  return render_rib(rib, render_options(hider, threads)).image;
}

std::string ortho_view(int size, double half) {
  std::ostringstream s;
  s << "Format " << size << " " << size << " 1\nPixelSamples 1 1\nPixelFilter \"box\" 1 1\n"
    << "Projection \"orthographic\"\nScreenWindow " << -half << " " << half << " " << -half << " " << half
    << "\nTranslate 0 0 10\n";
  return s.str();
}

}  // namespace darc::test
