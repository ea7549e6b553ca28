#include "core/scene/builder/scene_builder.h"
#include "core/scene/builder/texture_paths.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/scene/builder/shader_parameter_checks.h"
#include "core/scene/builder/unused_request_checks.h"

namespace darc {

namespace {

const char* block_name(int b) {
  static const char* names[] = {"FrameBegin", "WorldBegin", "AttributeBegin", "TransformBegin", "ObjectBegin"};
  return names[b];
}

}  // namespace

SceneBuilder::SceneBuilder(Diagnostics& diag, Callbacks callbacks, FrameOverrides overrides)
    : diag_(diag), callbacks_(std::move(callbacks)), overrides_(std::move(overrides)) {}

SceneBuilder::~SceneBuilder() = default;

// ---------------------------------------------------------------- blocks

void SceneBuilder::push_block(Block b, const SourceLoc& loc) {
  blocks_.push_back(b);
  block_locs_.push_back(loc);
}

void SceneBuilder::pop_block(Block b, const char* request, const SourceLoc&) {
  if (blocks_.empty() || blocks_.back() != b) {
    std::string open = blocks_.empty() ? std::string("no block is open")
                                       : std::string(block_name(int(blocks_.back()))) + " at " +
                                             block_locs_.back().str() + " is still open";
    throw RibError(std::string("unmatched ") + request + ": " + open);
  }
  blocks_.pop_back();
  block_locs_.pop_back();
}

void SceneBuilder::finish(const SourceLoc& end) {
  // After ErrorHandler "abort" the input was cut short on purpose: what is open is no new error.
  if (diag_.aborted()) return;
  while (!blocks_.empty()) {
    diag_.error(block_locs_.back(), block_name(int(blocks_.back())), "block is never closed");
    Block b = blocks_.back();
    blocks_.pop_back();
    block_locs_.pop_back();
    if (b == Block::World && scene_) {
      scene_.reset();
      in_world_ = false;
      ++frames_failed_;
      if (callbacks_.frame_failed) callbacks_.frame_failed(frame_number_);
    }
  }
  (void)end;
}

void SceneBuilder::frame_begin(int number, const SourceLoc& loc) {
  if (in_frame_ || in_world_) throw RibError("FrameBegin inside a frame or world block");
  push_block(Block::Frame, loc);
  saved_options_.push_back(options_);
  saved_attributes_.push_back(attributes_);
  saved_ctm_.push_back(ctm_);
  saved_ctm_keys_.push_back(ctm_keys_);
  in_frame_ = true;
  frame_number_ = number;
  has_frame_number_ = true;
  frame_skipped_ = callbacks_.frame_selected && !callbacks_.frame_selected(number);
}

void SceneBuilder::frame_end(const SourceLoc& loc) {
  pop_block(Block::Frame, "FrameEnd", loc);
  options_ = saved_options_.back();
  saved_options_.pop_back();
  attributes_ = saved_attributes_.back();
  saved_attributes_.pop_back();
  ctm_ = saved_ctm_.back();
  saved_ctm_.pop_back();
  ctm_keys_ = std::move(saved_ctm_keys_.back());
  saved_ctm_keys_.pop_back();
  in_frame_ = false;
  frame_skipped_ = false;
  has_frame_number_ = false;
}

void SceneBuilder::world_begin(const SourceLoc& loc) {
  if (in_world_) throw RibError("WorldBegin inside a world block");
  // WorldEnd drops the objects, the one being recorded too: it must not be left open across.
  if (recording_) throw RibError("WorldBegin inside an ObjectBegin block");
  push_block(Block::World, loc);
  ++world_blocks_seen_;
  if (!in_frame_) {
    // Without FrameBegin, frames are numbered by world block, from 1.
    frame_number_ = world_blocks_seen_;
    frame_skipped_ = callbacks_.frame_selected && !callbacks_.frame_selected(frame_number_);
  }
  saved_attributes_.push_back(attributes_);
  world_attribute_depth_ = saved_attributes_.size();
  saved_ctm_.push_back(ctm_);
  saved_ctm_keys_.push_back(ctm_keys_);
  in_world_ = true;
  start_scene(loc);
}

void SceneBuilder::start_scene(const SourceLoc& loc) {
  scene_ = std::make_unique<Scene>();
  frame_memory_estimate_ = 0;
  image_memory_ = 0;
  frame_over_memory_ = false;
  geometry_key_.clear();
  geometry_key_valid_ = true;
  material_ids_.clear();
  Scene& s = *scene_;
  OutputSettings out = options_.output;
  if (overrides_.xres > 0) {
    out.xres = overrides_.xres;
    out.yres = overrides_.yres;
  }
  if (overrides_.pixel_samples > 0) out.pixel_samples[0] = out.pixel_samples[1] = overrides_.pixel_samples;
  if (overrides_.crop) std::copy(overrides_.crop->begin(), overrides_.crop->end(), out.crop);
  if (!overrides_.output.empty()) out.display_name = overrides_.output;
  out.frame_number = frame_number_;
  out.has_frame_number = has_frame_number_;
  check_crop_window(out, loc);
  s.output = out;
  count_image_memory(out);

  Camera& cam = s.camera;
  cam.projection = options_.projection;
  cam.fov_degrees = options_.fov_degrees;
  cam.xres = out.xres;
  cam.yres = out.yres;
  double aspect = options_.frame_aspect.value_or(out.xres * out.pixel_aspect / out.yres);
  aspect = checked_frame_aspect(aspect, loc);
  cam.screen = options_.screen_window.value_or(default_screen_window(aspect));
  cam.near_clip = options_.near_clip;
  cam.far_clip = options_.far_clip;
  cam.lens_radius = options_.lens_radius;
  cam.focal_distance = options_.focal_distance;
  cam.world_to_camera = checked_camera_transform(loc);
  cam.finalize();
  camera_to_world_ = cam.camera_to_world;

  named_spaces_.clear();
  scoped_spaces_.clear();
  named_spaces_["world"] = Matrix4{};
  named_spaces_["camera"] = camera_to_world_;
  // A named camera is a coordinate system of its name (as in PRMan); the image is rendered from
  // the camera in effect at WorldBegin.
  for (const auto& [name, world_to_named] : options_.named_cameras) {
    Matrix4 named_to_world;
    if (world_to_named.inverse(named_to_world)) named_spaces_[name] = named_to_world;
  }
  light_handles_.clear();
  area_light_handles_.clear();
  skipped_primitives_.clear();
  attributes_.lights_on.clear();
  for (const PendingLight& pl : options_.pre_world_lights) {
    LightDesc d = pl.desc;
    d.shader_to_world = pl.desc.shader_to_world * camera_to_world_;
    s.lights.push_back(std::move(d));
    uint32_t idx = uint32_t(s.lights.size() - 1);
    light_handles_[pl.handle] = idx;
    attributes_.lights_on.push_back(idx);
  }
  // A moving camera: rendered from where it is at shutter open, while the world moves by
  // W2C(t) W2C(open)^-1, which puts every point where the camera at t sees it. Keys that are
  // all the same (exporters write a still camera's block too) move nothing.
  world_keys_.clear();
  if (motion_blur() && ctm_keys_.size() > 1) {
    const bool still = std::all_of(ctm_keys_.begin(), ctm_keys_.end(),
                                   [&](const TransformKey& k) { return k.m.m == ctm_keys_.front().m.m; });
    if (!still)
      for (const TransformKey& k : ctm_keys_) world_keys_.push_back({k.time, k.m * cam.camera_to_world});
  }
  set_world_relative_ctm(Matrix4{});
  next_strand_id_ = 0;
}

void SceneBuilder::close_blocks_left_open_in_world(const SourceLoc& loc) {
  if (!in_world_) return;  // pop_block reports the unmatched WorldEnd
  while (!blocks_.empty() && blocks_.back() != Block::World) {
    const Block open = blocks_.back();
    diag_.error(loc, "WorldEnd",
                std::string(block_name(int(open))) + " at " + block_locs_.back().str() + " is still open: closed here");
    if (open == Block::Object) {
      object_end(loc);
    } else if (open == Block::Attribute) {
      attribute_end(loc);
    } else {
      transform_end(loc);
    }
  }
}

void SceneBuilder::world_end(const SourceLoc& loc) {
  if (motion_) {
    diag_.error(motion_->loc, "MotionBegin", "block is never closed (no MotionEnd before WorldEnd): its samples are dropped");
    motion_.reset();
  }
  close_blocks_left_open_in_world(loc);
  check_frame_memory_at_world_end(loc);
  pop_block(Block::World, "WorldEnd", loc);
  attributes_ = saved_attributes_.back();
  saved_attributes_.pop_back();
  ctm_ = saved_ctm_.back();
  saved_ctm_.pop_back();
  ctm_keys_ = std::move(saved_ctm_keys_.back());
  saved_ctm_keys_.pop_back();
  in_world_ = false;
  objects_.clear();
  std::unique_ptr<Scene> scene = std::move(scene_);
  if (scene && !frame_skipped_) {
    if (geometry_key_valid_ && !geometry_key_.empty()) scene->geometry_key = std::move(geometry_key_);
    // Curves of replayed calls this frame did not use are not kept for the next one.
    for (auto it = curve_chunks_.begin(); it != curve_chunks_.end();) {
      if (!std::exchange(it->second.used, false)) it = curve_chunks_.erase(it);
      else ++it;
    }
  }
  if (frame_over_memory_ && !frame_skipped_) {
    ++frames_failed_;
    if (callbacks_.frame_failed) callbacks_.frame_failed(frame_number_);
  } else if (!frame_skipped_ && !diag_.aborted()) {
    warn_if_nothing_renderable(*scene, loc);
    ++frames_ready_;
    if (callbacks_.frame_ready) callbacks_.frame_ready(std::move(*scene));
  }
  diag_.end_frame();
}

void SceneBuilder::attribute_begin(const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.attribute_begin(loc); })) return;
  push_block(Block::Attribute, loc);
  saved_attributes_.push_back(attributes_);
  saved_ctm_.push_back(ctm_);
  saved_ctm_keys_.push_back(ctm_keys_);
}

void SceneBuilder::attribute_end(const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.attribute_end(loc); })) return;
  pop_block(Block::Attribute, "AttributeEnd", loc);
  attributes_ = saved_attributes_.back();
  saved_attributes_.pop_back();
  while (!scoped_spaces_.empty() && scoped_spaces_.back().depth > saved_attributes_.size()) scoped_spaces_.pop_back();
  ctm_ = saved_ctm_.back();
  saved_ctm_.pop_back();
  ctm_keys_ = std::move(saved_ctm_keys_.back());
  saved_ctm_keys_.pop_back();
}

// Resource blocks scope Resource requests, which darc does not support: nothing to do.
void SceneBuilder::resource_begin(const SourceLoc&) {}
void SceneBuilder::resource_end(const SourceLoc&) {}

void SceneBuilder::transform_begin(const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.transform_begin(loc); })) return;
  push_block(Block::Transform, loc);
  saved_ctm_.push_back(ctm_);
  saved_ctm_keys_.push_back(ctm_keys_);
}

void SceneBuilder::transform_end(const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.transform_end(loc); })) return;
  pop_block(Block::Transform, "TransformEnd", loc);
  ctm_ = saved_ctm_.back();
  saved_ctm_.pop_back();
  ctm_keys_ = std::move(saved_ctm_keys_.back());
  saved_ctm_keys_.pop_back();
}

// ---------------------------------------------------------------- transforms

void SceneBuilder::set_ctm(const Matrix4& m) {
  ctm_ = m;
  ctm_keys_.clear();
}

void SceneBuilder::set_world_relative_ctm(const Matrix4& m) {
  set_ctm(m);
  if (!in_world_ || world_keys_.empty()) return;
  for (const TransformKey& k : world_keys_) ctm_keys_.push_back({k.time, m * k.m});
  ctm_ = transform_at(ctm_keys_, options_.output.shutter_open);
}

void SceneBuilder::concat(const Matrix4& m) {
  // Each factor is finite (the lexer refuses anything else), but repeated large ones can overflow
  // the product: every point would then be infinite or NaN.
  auto checked = [](const Matrix4& product) {
    for (const auto& row : product.m)
      for (double v : row)
        if (!std::isfinite(v)) throw RibError("the current transform would overflow (an entry beyond the double range)");
    return product;
  };
  const Matrix4 product = checked(m * ctm_);
  std::vector<TransformKey> keys = ctm_keys_;
  for (TransformKey& k : keys) k.m = checked(m * k.m);
  ctm_ = product;
  ctm_keys_ = std::move(keys);
}

void SceneBuilder::identity(const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.identity(loc); })) return;
  // Inside the world block, Identity means world space (Aqsis, PRMan).
  if (transform_sample("Identity", Matrix4{}, true, loc)) return;
  set_world_relative_ctm(Matrix4{});
}

void SceneBuilder::transform(const std::array<double, 16>& m, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.transform(m, loc); })) return;
  const Matrix4 matrix = Matrix4::from_row_major(m.data());
  if (transform_sample("Transform", matrix, true, loc)) return;
  set_world_relative_ctm(matrix);
}

void SceneBuilder::concat_transform(const std::array<double, 16>& m, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.concat_transform(m, loc); })) return;
  const Matrix4 matrix = Matrix4::from_row_major(m.data());
  if (transform_sample("ConcatTransform", matrix, false, loc)) return;
  concat(matrix);
}

void SceneBuilder::translate(double dx, double dy, double dz, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.translate(dx, dy, dz, loc); })) return;
  const Matrix4 matrix = Matrix4::translate({dx, dy, dz});
  if (transform_sample("Translate", matrix, false, loc)) return;
  concat(matrix);
}

void SceneBuilder::rotate(double angle, double ax, double ay, double az, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.rotate(angle, ax, ay, az, loc); })) return;
  if (ax == 0 && ay == 0 && az == 0) throw RibError("Rotate axis is the zero vector");
  const Matrix4 matrix = Matrix4::rotate(angle, {ax, ay, az});
  if (transform_sample("Rotate", matrix, false, loc)) return;
  concat(matrix);
}

void SceneBuilder::scale(double sx, double sy, double sz, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.scale(sx, sy, sz, loc); })) return;
  const Matrix4 matrix = Matrix4::scale({sx, sy, sz});
  if (transform_sample("Scale", matrix, false, loc)) return;
  concat(matrix);
}

void SceneBuilder::perspective(double fov, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.perspective(fov, loc); })) return;
  if (!(fov > 0 && fov < 180)) throw RibError("Perspective fov must be in (0, 180)");
  const Matrix4 matrix = Matrix4::perspective(fov);
  if (transform_sample("Perspective", matrix, false, loc)) return;
  concat(matrix);
}

void SceneBuilder::coordinate_system(const std::string& name, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.coordinate_system(name, loc); })) return;
  if (!in_world_) {
    diag_.warning(loc, "CoordinateSystem", "named spaces before WorldBegin are not supported: ignored");
    return;
  }
  named_spaces_[name] = ctm_;
}

void SceneBuilder::scoped_coordinate_system(const std::string& name, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.scoped_coordinate_system(name, loc); })) return;
  if (!in_world_) {
    diag_.warning(loc, "ScopedCoordinateSystem", "named spaces before WorldBegin are not supported: ignored");
    return;
  }
  // Named until the attribute block it is given in ends (attribute_end drops it), over a space
  // of the same name given outside.
  scoped_spaces_.push_back({name, ctm_, saved_attributes_.size()});
}

void SceneBuilder::coord_sys_transform(const std::string& name, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.coord_sys_transform(name, loc); })) return;
  if (!in_world_) throw RibError("unknown coordinate system \"" + name + "\"");
  for (auto scoped = scoped_spaces_.rbegin(); scoped != scoped_spaces_.rend(); ++scoped)
    if (scoped->name == name) return set_world_relative_ctm(scoped->to_world);
  auto it = named_spaces_.find(name);
  if (it == named_spaces_.end()) throw RibError("unknown coordinate system \"" + name + "\"");
  // Under a moving camera the world moves, and what is placed in a coordinate system of the world
  // moves with it; camera space stays with the camera the image is rendered from.
  if (name == "camera") {
    set_ctm(it->second);
  } else {
    set_world_relative_ctm(it->second);
  }
}

// ---------------------------------------------------------------- attributes

void SceneBuilder::attribute(const std::string& category, const ParamList& params, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.attribute(category, params, loc); })) return;
  if (category == "light" || category == "visibility" || category == "render") {
    for (const Param& p : params.params) ray_tracing_attribute(category, p, loc);
    return;
  }
  if (category == "Ri") return ri_attribute(params, loc);
  // One warning per category: real files repeat vendor attributes on every object.
  diag_.warning_once("attribute:" + category, loc, "Attribute",
                     "Attribute \"" + category + "\" has no effect in darc: ignored");
}

bool SceneBuilder::object_space_left_handed() const {
  // Camera space is left-handed; a transform with a negative determinant flips handedness.
  double det = in_world_ ? (ctm_ * scene_->camera.world_to_camera).determinant() : ctm_.determinant();
  return det >= 0;
}

void SceneBuilder::orientation(const std::string& name, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.orientation(name, loc); })) return;
  if (name == "lh") attributes_.orientation_lh = true;
  else if (name == "rh") attributes_.orientation_lh = false;
  else if (name == "outside") attributes_.orientation_lh = object_space_left_handed();
  else if (name == "inside") attributes_.orientation_lh = !object_space_left_handed();
  else throw RibError("unknown orientation \"" + name + "\" (expected outside, inside, lh or rh)");
}

void SceneBuilder::reverse_orientation(const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.reverse_orientation(loc); })) return;
  attributes_.orientation_lh = !attributes_.orientation_lh;
}

void SceneBuilder::sides(int n, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.sides(n, loc); })) return;
  if (n != 1 && n != 2) throw RibError("Sides must be 1 or 2, found " + std::to_string(n));
  attributes_.sides = n;
}

void SceneBuilder::color(const std::array<float, 3>& rgb, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.color(rgb, loc); })) return;
  attributes_.color = {rgb[0], rgb[1], rgb[2]};
}

void SceneBuilder::opacity(const std::array<float, 3>& rgb, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.opacity(rgb, loc); })) return;
  // Compositing takes opacity as a fraction: outside [0, 1] it would add or remove light.
  const Vec3f clamped{std::clamp(rgb[0], 0.0f, 1.0f), std::clamp(rgb[1], 0.0f, 1.0f), std::clamp(rgb[2], 0.0f, 1.0f)};
  if (clamped != Vec3f{rgb[0], rgb[1], rgb[2]})
    diag_.warning(loc, "Opacity",
                  fmt::format("[{} {} {}] is outside [0, 1]: clamped to [{} {} {}]", rgb[0], rgb[1], rgb[2], clamped.x,
                              clamped.y, clamped.z));
  attributes_.opacity = clamped;
}

void SceneBuilder::surface(const std::string& name, const ParamList& params, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.surface(name, params, loc); })) return;
  ParamList list = checked_shader_parameters("Surface", name, params, diag_, loc);
  resolve_texture_names("Surface", name, list, "shades without it", loc);
  auto checked = std::make_shared<const ParamList>(std::move(list));
  attributes_.surface = name;
  attributes_.surface_params = std::move(checked);
  attributes_.surface_loc = loc;
}

void SceneBuilder::resolve_texture_names(const char* request, const std::string& shader, ParamList& params,
                                         const char* fallback, const SourceLoc& loc) {
  // Texture files are found now, where the RIB names them, and reported at its position.
  for (Param& p : params.params) {
    if (!names_a_texture(shader, p) || p.strings.empty() || p.strings[0].empty()) continue;
    if (const auto found = find_texture(p.strings[0], options_.texture_search_path, loc.file_name())) {
      p.strings[0] = *found;
      continue;
    }
    diag_.warning_once("texture:" + p.strings[0], loc, request,
                       fmt::format("texture \"{}\" not found (searched beside the RIB file{}): {} {}", p.strings[0],
                                   options_.texture_search_path.empty() ? "" : " and along the texture searchpath",
                                   shader, fallback));
    p.strings[0].clear();
  }
}

void SceneBuilder::displacement(const std::string& name, const ParamList&, const SourceLoc& loc) {
  if (name != "null")
    diag_.warning_once("displacement", loc, "Displacement", "displacement shaders are not supported: ignored");
}

void SceneBuilder::add_light(const std::string& name, const std::string& handle, const ParamList& params,
                             const SourceLoc& loc, std::optional<bool> casts_shadows, const char* request) {
  check_light_positions(params, ctm_);  // before WorldBegin: in camera space
  ParamList checked = checked_shader_parameters("LightSource", name, params, diag_, loc);
  resolve_texture_names(request, name, checked, "lights with its colour alone", loc);
  const bool shadows = casts_shadows ? *casts_shadows : light_casts_shadows(handle, params, loc);
  LightDesc d{name, std::move(checked), ctm_, loc, shadows};
  if (!in_world_) {
    diag_.warning_once("prelight", loc, "LightSource",
                       "light declared before WorldBegin: placed relative to the camera and used for every frame");
    options_.pre_world_lights.push_back({std::move(d), handle});
    return;
  }
  scene_->lights.push_back(std::move(d));
  uint32_t idx = uint32_t(scene_->lights.size() - 1);
  light_handles_[handle] = idx;
  area_light_handles_.erase(handle);  // a handle names the latest light declared with it
  attributes_.lights_on.push_back(idx);
}

void SceneBuilder::light_source(const std::string& name, const std::string& handle, const ParamList& params,
                                const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.light_source(name, handle, params, loc); })) return;
  add_light(name, handle, params, loc);
}

void SceneBuilder::area_light_source(const std::string& name, const std::string& handle, const ParamList& params,
                                     const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.area_light_source(name, handle, params, loc); })) return;
  auto checked =
      std::make_shared<const ParamList>(checked_shader_parameters("AreaLightSource", name, params, diag_, loc));
  attributes_.area_light = name;
  attributes_.area_light_params = checked;
  // The light, whose shape is the geometry that follows in this attribute block (RI Spec 3.2,
  // RiAreaLightSource): on, and in the current light list, like a LightSource.
  const bool shadows = light_casts_shadows(handle, params, loc);
  LightDesc d{name, *checked, ctm_, loc, shadows};
  d.geometry = true;
  if (!in_world_) {
    diag_.warning_once("prearealight", loc, "AreaLightSource",
                       "area light declared before WorldBegin: it has no geometry there and lights nothing");
    attributes_.area_light_index = -1;
    area_light_handles_.insert(handle);
    return;
  }
  scene_->lights.push_back(std::move(d));
  const uint32_t idx = uint32_t(scene_->lights.size() - 1);
  attributes_.area_light_index = int(idx);
  light_handles_[handle] = idx;
  area_light_handles_.erase(handle);
  attributes_.lights_on.push_back(idx);
}

void SceneBuilder::illuminate(const std::string& handle, bool on, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.illuminate(handle, on, loc); })) return;
  auto it = light_handles_.find(handle);
  if (it == light_handles_.end()) {
    // An area light lights nothing here (its geometry is drawn emissive whatever Illuminate
    // says), so switching it changes nothing; its handle is valid all the same.
    if (area_light_handles_.count(handle)) return;
    throw RibError("unknown light handle \"" + handle + "\"");
  }
  auto& v = attributes_.lights_on;
  auto pos = std::find(v.begin(), v.end(), it->second);
  if (on && pos == v.end()) v.push_back(it->second);
  if (!on && pos != v.end()) v.erase(pos);
}

void SceneBuilder::basis(const BasisArg& u, int ustep, const BasisArg& v, int vstep, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.basis(u, ustep, v, vstep, loc); })) return;
  auto resolve = [&](const BasisArg& a, int step) -> CurveBasis {
    if (step < 1) throw RibError("basis step must be at least 1, found " + std::to_string(step));
    if (a.name.empty()) return basis_from_matrix(a.matrix, step);
    auto b = standard_basis(a.name);
    if (!b) throw RibError("unknown basis \"" + a.name + "\"");
    b->step = step;
    return *b;
  };
  CurveBasis ub = resolve(u, ustep), vb = resolve(v, vstep);
  attributes_.ubasis = ub;
  attributes_.vbasis = vb;
}

// Version and Declare change nothing in a scene (the parser keeps the declarations).
void SceneBuilder::version(double, const SourceLoc&) {}
void SceneBuilder::declare(const std::string&, const std::string&, const SourceLoc&) {}

}  // namespace darc
