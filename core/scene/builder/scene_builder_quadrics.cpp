// SceneBuilder's builders for the RI quadrics other than the sphere (RI Spec 3.2, 5.3): Cone,
// Cylinder, Disk, Paraboloid, Hyperboloid and Torus, kept analytic in the surface set (as triangles
// when they move: quadric_tessellation.h). The
// parser has checked the argument counts (parser/primitive_signatures.cpp); these read the
// numbers in the spec's order.

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "core/scene/builder/scene_builder.h"

namespace darc {

namespace {

bool all_finite(const Vec3f& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace

void SceneBuilder::add_cone(const PrimitiveRequest& r, const ParamList&, const SourceLoc& loc) {
  const std::vector<double>& n = r.numbers;
  add_quadric(Quadric::cone(n.at(0), n.at(1), n.at(2), ctm_), r, loc);
}

void SceneBuilder::add_cylinder(const PrimitiveRequest& r, const ParamList&, const SourceLoc& loc) {
  const std::vector<double>& n = r.numbers;
  add_quadric(Quadric::cylinder(n.at(0), n.at(1), n.at(2), n.at(3), ctm_), r, loc);
}

void SceneBuilder::add_disk(const PrimitiveRequest& r, const ParamList&, const SourceLoc& loc) {
  const std::vector<double>& n = r.numbers;
  add_quadric(Quadric::disk(n.at(0), n.at(1), n.at(2), ctm_), r, loc);
}

void SceneBuilder::add_paraboloid(const PrimitiveRequest& r, const ParamList&, const SourceLoc& loc) {
  const std::vector<double>& n = r.numbers;
  add_quadric(Quadric::paraboloid(n.at(0), n.at(1), n.at(2), n.at(3), ctm_), r, loc);
}

void SceneBuilder::add_hyperboloid(const PrimitiveRequest& r, const ParamList&, const SourceLoc& loc) {
  const std::vector<double>& n = r.numbers;
  add_quadric(Quadric::hyperboloid({n.at(0), n.at(1), n.at(2)}, {n.at(3), n.at(4), n.at(5)}, n.at(6), ctm_), r, loc);
}

void SceneBuilder::add_torus(const PrimitiveRequest& r, const ParamList&, const SourceLoc& loc) {
  const std::vector<double>& n = r.numbers;
  add_quadric(Quadric::torus(n.at(0), n.at(1), n.at(2), n.at(3), n.at(4), ctm_), r, loc);
}

void SceneBuilder::add_quadric(Quadric quadric, const PrimitiveRequest& r, const SourceLoc& loc) {
  // Zero area or zero sweep (RI allows them): nothing to draw, as for a Sphere of radius 0.
  if (quadric.degenerate) return;
  // A moving quadric: a moving triangle mesh (quadric_tessellation.h).
  if (quadric_moves()) {
    const std::optional<DicingView> view = dicing_view();
    add_triangle_mesh(tessellate_quadric(quadric, moving_quadric_grid(quadric_grid(quadric, view ? &*view : nullptr))),
                      make_material(loc));
    return;
  }
  const BBox box = quadric.bounds();
  // The whole request would be dropped, so it is an error, as for the Sphere.
  if (!(all_finite(box.lo) && all_finite(box.hi)))
    throw RibError(fmt::format("this {} lies beyond the float range in world space", r.name));
  if (!reserve_frame_memory(0, 1, 0)) return;
  scene_->surfaces.quadrics.push_back(std::move(quadric));
  scene_->surfaces.quadric_material.push_back(make_material(loc));
}

}  // namespace darc
