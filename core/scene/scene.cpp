#include "core/scene/scene.h"

namespace darc {

void Scene::build_acceleration(AcceleratorKind kind) {
  curves.shrink_to_fit();  // the scene is complete: no more segments or points
  points.shrink_to_fit();
  std::vector<BBox> boxes;
  boxes.reserve(primitive_count());
  for (size_t i = 0; i < curves.size(); ++i) boxes.push_back(curves.segment_bounds(i));
  for (uint32_t s = 0; s < surfaces.size(); ++s) boxes.push_back(surfaces.bounds(s));
  for (size_t i = 0; i < points.size(); ++i) boxes.push_back(points.bounds(i));
  bounds = BBox{};
  for (const BBox& b : boxes)
    if (!b.empty()) bounds.extend(b);
  accel = Accelerator::build(kind, boxes);
}

}  // namespace darc
