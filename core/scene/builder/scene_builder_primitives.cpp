// SceneBuilder's one entry point for the geometry requests that reach RiTarget::primitive: the
// checks they share, then the builder the table names for the request. A request without a
// builder is reported as not supported, as the parser reports the requests it does not read.

#include "core/scene/builder/scene_builder.h"
#include "parser/known_requests.h"

#include <fmt/format.h>

#include <cmath>
#include <string_view>
#include <utility>

namespace darc {

namespace {

bool all_finite(const Vec3f& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace

SceneBuilder::PrimitiveBuilder SceneBuilder::find_primitive_builder(const std::string& request) {
  static constexpr std::pair<std::string_view, PrimitiveBuilder> kBuilders[] = {
      {"Sphere", &SceneBuilder::add_sphere},
      {"Cone", &SceneBuilder::add_cone},
      {"Cylinder", &SceneBuilder::add_cylinder},
      {"Disk", &SceneBuilder::add_disk},
      {"Paraboloid", &SceneBuilder::add_paraboloid},
      {"Hyperboloid", &SceneBuilder::add_hyperboloid},
      {"Torus", &SceneBuilder::add_torus},
      {"SubdivisionMesh", &SceneBuilder::add_subdivision_mesh},
      {"Patch", &SceneBuilder::add_patch},
      {"PatchMesh", &SceneBuilder::add_patch_mesh},
      {"NuPatch", &SceneBuilder::add_nu_patch},
      {"Points", &SceneBuilder::add_points},
  };
  for (const auto& [name, builder] : kBuilders)
    if (name == request) return builder;
  return nullptr;
}

void SceneBuilder::primitive(const PrimitiveRequest& request, const ParamList& params, const SourceLoc& loc) {
  const PrimitiveBuilder builder = find_primitive_builder(request.name);
  if (builder == nullptr) {
    const std::optional<KnownRequest> known = find_known_request(request.name);
    const std::string origin = known ? fmt::format(" ({})", describe(known->origin)) : std::string();
    diag_.warning_once("unsupported request " + request.name, loc, request.name,
                       fmt::format("request \"{}\"{} is not supported: skipped", request.name, origin));
    skipped_primitive(request.name, loc);
    return;
  }
  if (record([=](SceneBuilder& b) { b.primitive(request, params, loc); })) return;
  if (skip_motion_sample(request.name)) return;
  if (!building_geometry(request.name.c_str(), loc)) return;
  note_geometry(replayed_id());
  (this->*builder)(request, params, loc);
}

void SceneBuilder::add_sphere(const PrimitiveRequest& r, const ParamList&, const SourceLoc& loc) {
  const double radius = r.numbers.at(0), zmin = r.numbers.at(1), zmax = r.numbers.at(2), thetamax = r.numbers.at(3);
  if (radius == 0 || thetamax == 0) return;  // empty surface
  Sphere sphere = Sphere::make(radius, zmin, zmax, thetamax, ctm_);
  const BBox box = sphere.bounds();
  // The whole request would be dropped, so it is an error (a Curves segment or a polygon face
  // beyond the range is only a part of its request: those are dropped with a warning).
  if (!sphere.degenerate && !(all_finite(box.lo) && all_finite(box.hi)))
    throw RibError(fmt::format("radius {} lies beyond the float range in world space", radius));
  if (!reserve_frame_memory(0, 1, 0)) return;
  scene_->surfaces.spheres.push_back(std::move(sphere));
  scene_->surfaces.sphere_material.push_back(make_material(loc));
}

size_t SceneBuilder::add_triangle_mesh(const TriangleMeshData& object_space, uint32_t material) {
  if (!reserve_frame_memory(0, object_space.triangle_count(), object_space.P.size())) return 0;
  TriangleMeshData world;
  world.P.reserve(object_space.P.size());
  for (const Vec3f& p : object_space.P) world.P.push_back(Vec3f(ctm_.transform_point(Vec3d(p))));
  // Normals go by the inverse transpose. The faces are wound in world space, as the polygons'
  // Newell normals are, so that Orientation acts on both alike; the store keeps each vertex
  // normal on its face's side (a mirroring transform reverses the winding's normal).
  Matrix4 world_to_object;
  if (!object_space.N.empty() && ctm_.inverse(world_to_object)) {
    world.N.reserve(object_space.N.size());
    for (const Vec3f& n : object_space.N)
      world.N.push_back(Vec3f(normalize(world_to_object.transform_normal_by_inverse(Vec3d(n)))));
  }
  world.uv = object_space.uv;
  world.indices = object_space.indices;
  const size_t kept = scene_->surfaces.triangles.add(world, material);
  scene_->surfaces.triangle_material.resize(scene_->surfaces.triangles.size(), material);
  return kept;
}

}  // namespace darc
