// Builds a frame's acceleration structure, or reuses the previous frame's when the geometry is
// bitwise the same (Scene::geometry_key: every geometry request replayed from the archive cache
// with the same transforms, as in a camera move over a hair archive). The BVH build is
// deterministic, so the reused structure is the one a build would give.
#pragma once

#include <string>

#include "core/scene/scene.h"

namespace darc {

class AccelerationReuse {
 public:
  // Returns true when the previous structure was reused.
  bool build(Scene& scene, AcceleratorKind kind = kDefaultAccelerator) {
    if (!scene.geometry_key.empty() && scene.geometry_key == key_ && kind == kind_) {
      scene.curves.shrink_to_fit();
      scene.accel = accel_;
      scene.bounds = bounds_;
      return true;
    }
    scene.build_acceleration(kind);
    key_ = scene.geometry_key;
    kind_ = kind;
    // Kept only when a later frame can reuse it.
    accel_ = key_.empty() ? Accelerator{} : scene.accel;
    bounds_ = scene.bounds;
    return false;
  }

 private:
  std::string key_;
  AcceleratorKind kind_ = kDefaultAccelerator;
  Accelerator accel_;
  BBox bounds_;
};

}  // namespace darc
