// Rendering in process, without the darc command: a Scene or the one frame of a RIB text into an
// Image (and the frame's counters), with the options a test chooses. Scene or render errors fail
// the calling test (non-fatally).
#pragma once

#include <string>

#include "core/scene/scene.h"
#include "integrator/render_frame.h"

namespace darc::test {

// One rendered frame: the image and what the render counted.
struct RenderedFrame {
  Image image;
  FrameStats stats;
};

// `hider` on `threads` threads, every other option at its default. One thread is the tests'
// usual choice (deterministic either way, and light on a shared machine); tests of the thread
// contract pass 2.
RenderOptions render_options(HiderKind hider, int threads = 1);
inline RenderOptions single_thread(HiderKind hider) { return render_options(hider, 1); }

// `scene` (its acceleration structure built) rendered with `options`.
RenderedFrame render(const Scene& scene, const RenderOptions& options);

// The one frame of `rib` built (scenes_from_rib.h: build_frame) and rendered with `options`; an
// empty RenderedFrame when the RIB gives no frame (which fails the test).
RenderedFrame render_rib(const std::string& rib, const RenderOptions& options);

// Only the image, for the tests that choose just the hider and the thread count.
Image render_image(const Scene& scene, HiderKind hider, int threads = 1);
Image render_image(const std::string& rib, HiderKind hider, int threads = 1);

// The options and camera of a square image `size` pixels wide, one box-filtered sample per pixel,
// orthographic over [-half, half]^2 of the world's xy plane seen from z = -10 (the camera looks
// along +z; image rows run down world y): the RIB text before WorldBegin.
std::string ortho_view(int size, double half);

}  // namespace darc::test
