// SceneBuilder's check that a finished frame can show anything: a frame whose primitives were
// all skipped (kinds darc does not support, errors) or whose camera looks away from all of its
// geometry renders an empty image without any error, which looks like a renderer bug. One
// warning says which of those it is.
#include <fmt/format.h>

#include <algorithm>

#include "core/scene/builder/scene_builder.h"

namespace darc {

namespace {

// "Cylinder, SubdivisionMesh x3" for the skipped primitive requests.
std::string list_requests(const std::map<std::string, int>& counts) {
  std::string out;
  for (const auto& [request, count] : counts) {
    if (!out.empty()) out += ", ";
    out += count > 1 ? fmt::format("{} x{}", request, count) : request;
  }
  return out;
}

BBox world_bounds(const Scene& scene) {
  BBox box;
  for (size_t i = 0; i < scene.curves.size(); ++i) box.extend(scene.curves.segment_bounds(i));
  for (uint32_t s = 0; s < scene.surfaces.size(); ++s) box.extend(scene.surfaces.bounds(s));
  for (size_t i = 0; i < scene.points.size(); ++i) box.extend(scene.points.bounds(i));
  return box;
}

// Why the camera sees none of `box`, or "" when it may see some of it. Conservative: the box
// of all geometry is tested, not each primitive, so a frame is only reported when no part of
// that box can reach the image.
std::string why_camera_sees_nothing(const Camera& camera, const BBox& box, double filter_width) {
  if (box.empty()) return "";
  std::array<Vec3d, 8> world, corners;  // corners: in camera space
  for (size_t i = 0; i < 8; ++i) {
    world[i] = {(i & 1) ? box.hi.x : box.lo.x, (i & 2) ? box.hi.y : box.lo.y, (i & 4) ? box.hi.z : box.lo.z};
    corners[i] = camera.world_to_camera.transform_point(world[i]);
  }
  const bool all_before_near =
      std::all_of(corners.begin(), corners.end(), [&](const Vec3d& c) { return c.z < camera.near_clip; });
  if (all_before_near) return "all of its geometry is behind the camera or nearer than the near clipping plane";
  const bool all_beyond_far =
      std::all_of(corners.begin(), corners.end(), [&](const Vec3d& c) { return c.z > camera.far_clip; });
  if (all_beyond_far) return "all of its geometry is beyond the far clipping plane";
  // A box reaching behind the camera may cover any part of the image: no verdict.
  if (std::any_of(corners.begin(), corners.end(), [&](const Vec3d& c) { return c.z < camera.near_clip; })) return "";
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (const Vec3d& p : world) {
    double rx = 0, ry = 0;
    if (!camera.world_to_raster(p, rx, ry)) return "";
    xmin = std::min(xmin, rx), xmax = std::max(xmax, rx);
    ymin = std::min(ymin, ry), ymax = std::max(ymax, ry);
  }
  // The pixel filter reaches this far outside a pixel: geometry just off the image still counts.
  const double margin = filter_width / 2 + 1;
  if (xmax < -margin || xmin > camera.xres + margin || ymax < -margin || ymin > camera.yres + margin)
    return "all of its geometry is outside the camera's view";
  return "";
}

}  // namespace

void SceneBuilder::skipped_primitive(const std::string& request, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.skipped_primitive(request, loc); })) return;
  if (in_world_) ++skipped_primitives_[request];
}

void SceneBuilder::warn_if_nothing_renderable(const Scene& scene, const SourceLoc& loc) {
  std::string reason;
  if (scene.primitive_count() == 0) {
    const std::int64_t errors = diag_.frame_errors().count;
    if (!skipped_primitives_.empty() && errors == 0) {
      reason = "every primitive in it is of a kind darc does not support (" + list_requests(skipped_primitives_) + ")";
    } else if (!skipped_primitives_.empty()) {
      reason = fmt::format("its primitives are of kinds darc does not support ({}) or were skipped for errors ({})",
                           list_requests(skipped_primitives_), errors);
    } else if (errors > 0) {
      reason = fmt::format("no primitive was built (the frame has {} error{})", errors, errors == 1 ? "" : "s");
    } else {
      reason = "its world block has no primitive";
    }
  } else {
    const double filter = std::max(scene.output.filter_width[0], scene.output.filter_width[1]);
    reason = why_camera_sees_nothing(scene.camera, world_bounds(scene), filter);
  }
  if (reason.empty()) return;
  diag_.warning(loc, "WorldEnd", fmt::format("nothing renderable in frame {}: {}", frame_number_, reason));
}

}  // namespace darc
