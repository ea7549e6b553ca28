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
  // Geometry under a moving transform is not the same from frame to frame however its requests
  // are replayed.
  const bool moving_transform = motion_blur() && !ctm_keys_.empty();
  note_geometry(moving_transform ? 0 : replayed_id());
  // Tessellated surfaces (patches, NURBS, subdivision meshes) move with their transform; the
  // quadrics and points do not.
  const bool tessellated = request.name == "SubdivisionMesh" || request.name == "Patch" ||
                           request.name == "PatchMesh" || request.name == "NuPatch";
  if (moving_transform && !tessellated)
    diag_.warning_once("motion:transform " + request.name, loc, request.name,
                       fmt::format("motion blur of {} under a moving transform is not supported: built where the "
                                   "transform is at shutter open",
                                   request.name));
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

namespace {

// The mesh moved by object_to_world: positions, and normals by the inverse transpose.
TriangleMeshData mesh_in_world(const TriangleMeshData& object_space, const Matrix4& object_to_world) {
  TriangleMeshData world;
  world.P.reserve(object_space.P.size());
  for (const Vec3f& p : object_space.P) world.P.push_back(Vec3f(object_to_world.transform_point(Vec3d(p))));
  // The faces are wound in world space, as the polygons' Newell normals are, so that Orientation
  // acts on both alike; the store keeps each vertex normal on its face's side (a mirroring
  // transform reverses the winding's normal).
  Matrix4 world_to_object;
  if (!object_space.N.empty() && object_to_world.inverse(world_to_object)) {
    world.N.reserve(object_space.N.size());
    for (const Vec3f& n : object_space.N)
      world.N.push_back(Vec3f(normalize(world_to_object.transform_normal_by_inverse(Vec3d(n)))));
  }
  world.uv = object_space.uv;
  world.indices = object_space.indices;
  return world;
}

}  // namespace

size_t SceneBuilder::add_triangle_mesh(const TriangleMeshData& object_space, uint32_t material,
                                       const std::vector<PositionSample>* samples) {
  const bool moves = motion_blur() && ((samples && samples->size() > 1) || !ctm_keys_.empty());
  size_t kept = 0;
  if (!moves) {
    if (!reserve_frame_memory(0, object_space.triangle_count(), object_space.P.size())) return 0;
    kept = scene_->surfaces.triangles.add(mesh_in_world(object_space, ctm_), material);
  } else {
    // Keys at shutter open and close and at every sample or transform key between: the mesh
    // with the samples' positions at that time, moved by the transform then.
    std::vector<float> flat;
    flat.reserve(3 * object_space.P.size());
    for (const Vec3f& p : object_space.P) flat.insert(flat.end(), {p.x, p.y, p.z});
    const std::vector<PositionSample> none;
    const std::vector<PositionSample>& given = samples ? *samples : none;
    const std::vector<double> times = motion_key_times(given, flat);
    if (!reserve_frame_memory(0, object_space.triangle_count(), object_space.P.size() * times.size())) return 0;
    const double open = options_.output.shutter_open, close = options_.output.shutter_close;
    std::vector<TriangleMeshData> keys;
    std::vector<float> key_times;
    for (double t : times) {
      TriangleMeshData at = object_space;
      if (!given.empty()) {
        const std::vector<float> P = positions_at(given, t);
        for (size_t i = 0; i < at.P.size() && 3 * i + 2 < P.size(); ++i) at.P[i] = {P[3 * i], P[3 * i + 1], P[3 * i + 2]};
      }
      keys.push_back(mesh_in_world(at, ctm_at(t)));
      key_times.push_back(float((t - open) / (close - open)));
    }
    kept = scene_->surfaces.triangles.add_moving(key_times, keys, material);
  }
  scene_->surfaces.triangle_material.resize(scene_->surfaces.triangles.size(), material);
  return kept;
}

}  // namespace darc
