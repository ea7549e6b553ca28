#include "core/scene.h"

namespace darc {

void Scene::build_acceleration(AcceleratorKind kind) {
  curves.shrink_to_fit();  // the scene is complete: no more segments
  std::vector<BBox> boxes;
  boxes.reserve(primitive_count());
  for (size_t i = 0; i < curves.size(); ++i) boxes.push_back(curves.segment_bounds(i));
  for (const Sphere& s : spheres) boxes.push_back(s.bounds());
  for (const PolygonShape& p : polygons) boxes.push_back(p.bounds());
  bounds = BBox{};
  for (const BBox& b : boxes)
    if (!b.empty()) bounds.extend(b);
  accel = Accelerator::build(kind, boxes);
}

}  // namespace darc
