// SceneBuilder's answer about a procedural's bound (RiTarget::procedural_bound). The parser
// expands a procedural unless it is not wanted, and passes RunProgram the bound's area in the
// image as its detail (RI Spec 3.2: the size of the bound on screen, for level of detail).
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/scene/builder/scene_builder.h"

namespace darc {

ProceduralBound SceneBuilder::procedural_bound(const std::array<double, 6>& bound, const SourceLoc&) {
  ProceduralBound answer;
  // Outside a frame's world there is no camera yet, and an object is seen wherever it is
  // instanced: wanted, detail unknown.
  if (!in_world_ || recording_ || !scene_) return answer;
  // Geometry is not built for a frame --frames did not select or one already over its memory
  // limit: what the procedural would produce is dropped anyway.
  if (frame_skipped_ || frame_over_memory_) {
    answer.wanted = false;
    return answer;
  }
  const Camera& camera = scene_->camera;
  const double width = camera.xres, height = camera.yres;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double x0 = kInf, x1 = -kInf, y0 = kInf, y1 = -kInf;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3d p{bound[corner & 1], bound[2 + ((corner >> 1) & 1)], bound[4 + ((corner >> 2) & 1)]};
    double rx = 0, ry = 0;
    // A corner behind the eye spreads the bound over the whole image (its projection is unbounded).
    if (!camera.world_to_raster(ctm_.transform_point(p), rx, ry) || !std::isfinite(rx) || !std::isfinite(ry)) {
      answer.raster_area = width * height;
      return answer;
    }
    x0 = std::min(x0, rx), x1 = std::max(x1, rx), y0 = std::min(y0, ry), y1 = std::max(y1, ry);
  }
  // The projected box, clipped to the image.
  const double w = std::min(x1, width) - std::max(x0, 0.0);
  const double h = std::min(y1, height) - std::max(y0, 0.0);
  answer.raster_area = w > 0 && h > 0 ? w * h : 0;
  return answer;
}

}  // namespace darc
