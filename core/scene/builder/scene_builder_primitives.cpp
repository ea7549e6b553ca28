// SceneBuilder's one entry point for the geometry requests that reach RiTarget::primitive: the
// checks they share, then the builder the table names for the request. A request without a
// builder is reported as not supported, as the parser reports the requests it does not read.

#include "core/scene/builder/scene_builder.h"
#include "parser/known_requests.h"

#include <fmt/format.h>

#include <algorithm>
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
  // Surfaces a motion block deforms: tessellated at MotionEnd, the quadrics too.
  static constexpr std::string_view kDeformable[] = {"SubdivisionMesh", "Patch", "PatchMesh", "NuPatch",
                                                     "Sphere", "Cone", "Cylinder", "Disk",
                                                     "Paraboloid", "Hyperboloid", "Torus"};
  const bool tessellated = std::find(std::begin(kDeformable), std::end(kDeformable), request.name) != std::end(kDeformable);
  if (motion_) {
    // A sample of a motion block: built at MotionEnd with the others (tessellated alike, or
    // points keyed).
    if (count_motion_sample(request.name, loc)) {
      if (request.name == "Points") {
        motion_->points.push_back({request, params, loc});
      } else if (tessellated) {
        motion_->tessellated.push_back({request, params, loc});
      }
    }
    return;
  }
  if (!building_geometry(request.name.c_str(), loc)) return;
  // Geometry under a moving transform is not the same from frame to frame however its requests
  // are replayed.
  const bool moving_transform = motion_blur() && !ctm_keys_.empty();
  note_geometry(moving_transform ? 0 : replayed_id());
  // Surfaces move with their transform (quadrics as triangles: scene_builder_quadrics.cpp), and
  // so do points, keyed at the transform's times.
  if (moving_transform && request.name == "Points") return add_moving_points({{request, params, loc}}, {});
  (this->*builder)(request, params, loc);
}

void SceneBuilder::add_sphere(const PrimitiveRequest& r, const ParamList&, const SourceLoc& loc) {
  const double radius = r.numbers.at(0), zmin = r.numbers.at(1), zmax = r.numbers.at(2), thetamax = r.numbers.at(3);
  if (radius == 0 || thetamax == 0) return;  // empty surface
  Sphere sphere = Sphere::make(radius, zmin, zmax, thetamax, ctm_);
  if (quadric_moves()) {
    if (sphere.degenerate) return;
    const std::optional<DicingView> view = dicing_view();
    add_triangle_mesh(tessellate_sphere(sphere, moving_quadric_grid(sphere_grid(sphere, view ? &*view : nullptr))),
                      make_material(loc));
    return;
  }
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
  if (captured_meshes_) {
    // A motion sample held until the block's end: counted as the frame's memory, as its keys will
    // be (a block of many samples of a large mesh stops at the memory limit, not past it).
    if (!reserve_frame_memory(0, object_space.triangle_count(), object_space.P.size())) return 0;
    captured_meshes_->push_back({object_space, material});
    return object_space.triangle_count();
  }
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

QuadricGrid SceneBuilder::moving_quadric_grid(const QuadricGrid& own) {
  if (!captured_meshes_) return own;
  if (!captured_grid_) captured_grid_ = own;
  return *captured_grid_;
}

void SceneBuilder::end_tessellated_motion(const MotionBlock& block) {
  const auto& first = block.tessellated.front();
  const std::string& name = first.request.name;
  const PrimitiveBuilder builder = find_primitive_builder(name);
  if (builder == nullptr) return;
  // A frame that is not built (not selected, or over its memory) tessellates nothing.
  try {
    if (!building_geometry(name.c_str(), first.loc)) return;
  } catch (const RibError& e) {
    diag_.error(first.loc, name, e.what());
    return;
  }
  auto build_first_alone = [&] {
    try {
      if (!building_geometry(name.c_str(), first.loc)) return;
      note_geometry(0);
      (this->*builder)(first.request, first.params, first.loc);
    } catch (const RibError& e) {
      diag_.error(first.loc, name, e.what());
    }
  };
  if (block.tessellated.size() == 1 || !motion_blur()) return build_first_alone();
  // Every sample tessellated the same way (the same triangles, as many vertices, the same
  // materials), else no motion blur.
  std::vector<std::vector<CapturedMesh>> meshes(block.tessellated.size());
  bool same = true;
  captured_grid_.reset();
  for (size_t k = 0; k < block.tessellated.size() && same; ++k) {
    const auto& sample = block.tessellated[k];
    captured_meshes_ = &meshes[k];
    try {
      (this->*builder)(sample.request, sample.params, sample.loc);
    } catch (const RibError& e) {
      same = false;
    }
    captured_meshes_ = nullptr;
    same = same && meshes[k].size() == meshes[0].size() && !meshes[k].empty();
    if (k + 1 == block.tessellated.size() || !same) captured_grid_.reset();
    for (size_t i = 0; same && i < meshes[k].size(); ++i) {
      const CapturedMesh &a = meshes[0][i], &b = meshes[k][i];
      same = a.material == b.material && a.mesh.indices == b.mesh.indices && a.mesh.P.size() == b.mesh.P.size();
    }
  }
  if (!same) {
    diag_.warning(first.loc, name,
                  "its motion samples do not tessellate alike (topology, or a dicing rate that changed with the "
                  "shape): the first sample is built without motion blur");
    return build_first_alone();
  }
  if (!building_geometry(name.c_str(), first.loc)) return;
  note_geometry(0);
  for (size_t i = 0; i < meshes[0].size(); ++i) {
    std::vector<PositionSample> samples;
    for (size_t k = 0; k < meshes.size(); ++k) {
      PositionSample s{block.times[k], {}};
      s.P.reserve(3 * meshes[k][i].mesh.P.size());
      for (const Vec3f& p : meshes[k][i].mesh.P) s.P.insert(s.P.end(), {p.x, p.y, p.z});
      samples.push_back(std::move(s));
    }
    add_triangle_mesh(meshes[0][i].mesh, meshes[0][i].material, &samples);
  }
}

}  // namespace darc
