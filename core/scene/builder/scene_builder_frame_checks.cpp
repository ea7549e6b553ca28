// SceneBuilder's checks of values that are only wrong together, made at WorldBegin when the
// frame's options are final (Format, CropWindow and --res may come in any order before it); the
// graphics state itself lives in scene_builder.cpp, the decisions in docs/parameters.md.
#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/scene/builder/scene_builder.h"

namespace darc {

namespace {

// The widest and narrowest frame aspect ratio whose default screen window (-a, a, -1, 1) or
// (-1, 1, -1/a, 1/a) still fits in a float: orthographic camera rays start on the screen window,
// in float.
constexpr double kMaxFrameAspect = std::numeric_limits<float>::max();
constexpr double kMinFrameAspect = 1 / kMaxFrameAspect;

// Whether the crop range [lo, hi] of a side of `res` pixels keeps a pixel: RI Spec 3.2 keeps the
// pixels ceil(res * lo) to ceil(res * hi - 1), as integrator/render_frame.cpp crops.
bool crop_keeps_a_pixel(int res, double lo, double hi) { return std::ceil(res * hi - 1) + 1 > std::ceil(res * lo); }

}  // namespace

double SceneBuilder::checked_frame_aspect(double aspect, const SourceLoc& world_begin) {
  // Only a pixel aspect ratio near the float limits gets here: FrameAspectRatio's own value is a
  // float, and Format's resolution is at most kMaxResolution.
  if (aspect >= kMinFrameAspect && aspect <= kMaxFrameAspect) return aspect;
  const double clamped = aspect > kMaxFrameAspect ? kMaxFrameAspect : kMinFrameAspect;
  diag_.warning(world_begin, "WorldBegin",
                fmt::format("the frame aspect ratio {} (Format pixel aspect ratio {}) puts the screen window "
                            "beyond the float range: clamped to {}",
                            aspect, options_.output.pixel_aspect, clamped));
  return clamped;
}

Matrix4 SceneBuilder::checked_camera_transform(const SourceLoc& world_begin) {
  // Scale 0 0 0, or a modelling Perspective, before WorldBegin: no ray can be mapped back.
  if (Matrix4 inverse; ctm_.inverse(inverse)) return ctm_;
  diag_.warning(world_begin, "WorldBegin", "the camera transform is singular: the identity is used instead");
  return Matrix4{};
}

void SceneBuilder::check_crop_window(OutputSettings& out, const SourceLoc& world_begin) {
  const double* c = out.crop;
  if (crop_keeps_a_pixel(out.xres, c[0], c[1]) && crop_keeps_a_pixel(out.yres, c[2], c[3])) return;
  // --crop is checked here too: whether it keeps a pixel depends on each frame's resolution.
  const bool from_command_line = overrides_.crop.has_value();
  diag_.error(from_command_line ? world_begin : options_.crop_loc, from_command_line ? "--crop" : "CropWindow",
              fmt::format("[{} {} {} {}] keeps no pixel of the {}x{} image: the whole image is rendered", c[0], c[1],
                          c[2], c[3], out.xres, out.yres));
  out.crop[0] = out.crop[2] = 0;
  out.crop[1] = out.crop[3] = 1;
}

}  // namespace darc
