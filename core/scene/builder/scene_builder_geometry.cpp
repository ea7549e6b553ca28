// SceneBuilder's geometry requests: Curves, Sphere and the polygons, turned into world-space
// shapes of the scene being built (the graphics state itself lives in scene_builder.cpp).
#include "core/geometry/curves/curve_builder.h"
#include "core/geometry/curves/curve_set.h"
#include "core/scene/frame_memory.h"
#include "core/scene/builder/polygon_st.h"
#include "core/scene/builder/scene_builder.h"
#include "core/scene/builder/texture_paths.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <limits>

namespace darc {

// ---------------------------------------------------------------- geometry

bool SceneBuilder::building_geometry(const char* request, const SourceLoc& loc) {
  if (!in_world_) throw RibError(std::string(request) + " outside WorldBegin/WorldEnd");
  return !frame_skipped_ && scene_ != nullptr && (void(loc), true);
}

bool SceneBuilder::reserve_frame_memory(uint64_t curve_segments, uint64_t surfaces, uint64_t polygon_points) {
  if (frame_over_memory_) return false;
  if (overrides_.memory_limit_bytes == 0) return true;
  frame_memory_estimate_ += frame_memory_estimate(curve_segments, surfaces, polygon_points);
  if (frame_memory_estimate_ <= overrides_.memory_limit_bytes) return true;
  frame_over_memory_ = true;
  throw RibError(frame_memory_error("with this request"));
}

void SceneBuilder::count_image_memory(const OutputSettings& out) {
  if (overrides_.memory_limit_bytes == 0) return;
  image_memory_ = uint64_t(out.xres) * uint64_t(out.yres) * kFrameBytesPerPixel;
  frame_memory_estimate_ += image_memory_;
}

std::string SceneBuilder::frame_memory_error(const char* with) const {
  // (The parser prefixes the message with the request's name and position.)
  return "the frame would need about " + format_bytes(frame_memory_estimate_) + " " + with + " (its geometry and " +
         format_bytes(image_memory_) + " for its image), more than the " +
         format_bytes(overrides_.memory_limit_bytes) + " a frame may use (" +
         (overrides_.memory_limit_source.empty() ? std::string("--memory-limit") : overrides_.memory_limit_source) +
         "); the frame is not rendered";
}

void SceneBuilder::check_frame_memory_at_world_end(const SourceLoc& loc) {
  if (overrides_.memory_limit_bytes == 0 || frame_over_memory_ || frame_skipped_) return;
  if (frame_memory_estimate_ <= overrides_.memory_limit_bytes) return;
  frame_over_memory_ = true;
  diag_.error(loc, "WorldEnd", frame_memory_error("in all"));
}

uint64_t SceneBuilder::replayed_id() const {
  // Calls replayed from an ObjectBegin block share the ObjectInstance's id: not one request.
  return replaying_ ? 0 : replayed_id_;
}

void SceneBuilder::note_geometry(uint64_t id) {
  if (id == 0) {
    geometry_key_valid_ = false;
    return;
  }
  // The request and the transform it is built with (the basis too, for curves: it is in the
  // key through the attribute state, whose changes are requests of their own in the same archive
  // or before it; the transform alone can move without a request of the archive changing).
  geometry_key_.append(reinterpret_cast<const char*>(&id), sizeof id);
  geometry_key_.append(reinterpret_cast<const char*>(&ctm_.m), sizeof ctm_.m);
  const CurveBasis& b = attributes_.vbasis;
  geometry_key_.append(reinterpret_cast<const char*>(&b.m), sizeof b.m);
  geometry_key_.append(reinterpret_cast<const char*>(&b.step), sizeof b.step);
}

uint32_t SceneBuilder::make_material(const SourceLoc&) {
  // One material per distinct attribute state, not per primitive request (an exporter writing one
  // Curves call per strand would otherwise make, and shade with, thousands of equal materials).
  // Shader parameter lists compare by identity: they are shared while the state is unchanged.
  const bool flip = attributes_.orientation_lh != object_space_left_handed();
  MaterialKey key{attributes_.surface,  attributes_.surface_params, attributes_.color,
                  attributes_.opacity,  attributes_.sides,                flip,
                  attributes_.matte,    attributes_.lights_on,            attributes_.area_light,
                  attributes_.area_light_params, attributes_.area_light_index, attributes_.transmission};
  auto found = material_ids_.find(key);
  if (found != material_ids_.end()) return found->second;
  Material m;
  m.surface = attributes_.surface;
  m.surface_params = *attributes_.surface_params;
  m.surface_loc = attributes_.surface_loc;
  // A texture the builder could not find was cleared (SceneBuilder::surface): it reads nothing.
  m.reads_textures = std::ranges::any_of(m.surface_params.params, [&](const Param& p) {
    return names_a_texture(m.surface, p) && !p.strings.empty() && !p.strings[0].empty();
  });
  m.color = attributes_.color;
  m.opacity = attributes_.opacity;
  m.sides = attributes_.sides;
  m.flip_normals = flip;
  m.matte = attributes_.matte;
  m.lights = attributes_.lights_on;
  m.emissive_area_light = attributes_.area_light;
  m.area_light_params = *attributes_.area_light_params;
  m.area_light = attributes_.area_light_index;
  // An emitter does not shadow the light it sends: its own samples lie on it.
  m.transmission = m.area_light >= 0 ? Transmission::Transparent : attributes_.transmission;
  scene_->materials.push_back(std::move(m));
  const uint32_t id = uint32_t(scene_->materials.size() - 1);
  material_ids_.emplace(std::move(key), id);
  return id;
}

Vec3f SceneBuilder::to_world(const float* p) const {
  return Vec3f(ctm_.transform_point(Vec3d{p[0], p[1], p[2]}));
}

namespace {

bool all_finite(const Vec3f& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

std::optional<PrimvarInput> primvar(const ParamList& params, const char* name, int components) {
  const Param* p = params.find(name);
  if (!p) return std::nullopt;
  if (p->decl.is_string() || p->decl.components() != components)
    throw RibError(std::string("\"") + name + "\" must have " + std::to_string(components) +
                   " numbers per value, declared as " + to_string(p->decl));
  return PrimvarInput{p->decl.storage, p->floats, components};
}

// Reads "P" (3 floats per point) or "Pw" (4, divided by w) as 3-float points.
std::vector<float> read_points(const ParamList& params, const char* request) {
  if (const Param* p = params.find("P")) {
    if (p->decl.components() != 3) throw RibError("\"P\" must be declared with 3 numbers per point");
    return p->floats;
  }
  if (const Param* p = params.find("Pw")) {
    if (p->decl.components() != 4) throw RibError("\"Pw\" must be declared with 4 numbers per point");
    std::vector<float> out;
    out.reserve(p->floats.size() / 4 * 3);
    for (size_t i = 0; i + 3 < p->floats.size(); i += 4) {
      float w = p->floats[i + 3];
      if (w == 0) throw RibError("\"Pw\" has a point with w = 0");
      out.insert(out.end(), {p->floats[i] / w, p->floats[i + 1] / w, p->floats[i + 2] / w});
    }
    return out;
  }
  throw RibError(std::string(request) + " needs \"P\" or \"Pw\"");
}

// What clamp_values changed: how many numbers, and the first of them (index and given value).
struct ClampedValues {
  size_t count = 0;
  size_t first = 0;
  float first_value = 0;
};

// Clamps every number of `values` to [lo, hi] in place, in one pass and without allocating, so
// that it stays cheap for a million-vertex Curves call.
ClampedValues clamp_values(std::vector<float>& values, float lo, float hi) {
  ClampedValues clamped;
  for (size_t i = 0; i < values.size(); ++i) {
    const float v = values[i];
    if (v >= lo && v <= hi) continue;
    if (clamped.count++ == 0) {
      clamped.first = i;
      clamped.first_value = v;
    }
    values[i] = std::clamp(v, lo, hi);
  }
  return clamped;
}

// The warning for what clamp_values changed in primitive variable `name`, e.g.
// "\"width\" (varying) value 3 is -0.01, negative: clamped to 0 (2 numbers clamped)".
std::string clamp_message(const char* name, const PrimvarInput& pv, const ClampedValues& c, const char* problem,
                          float lo, float hi) {
  const float used = std::clamp(c.first_value, lo, hi);
  const std::string which = pv.components == 1 ? fmt::format("value {}", c.first)
                                               : fmt::format("value {} component {}", c.first / size_t(pv.components),
                                                             c.first % size_t(pv.components));
  return fmt::format("\"{}\" ({}) {} is {}, {}: clamped to {} ({} number{} clamped)", name, to_string(pv.storage),
                     which, c.first_value, problem, used, c.count, c.count == 1 ? "" : "s");
}

constexpr float kFloatMax = std::numeric_limits<float>::max();

// What a Curves call clamped, and what append_curves dropped, for the warnings.
struct CurveClamps {
  ClampedValues widths, opacities;
  float constant_width = 0;  // as given
  CurvesAppended appended;
};

void report_curve_clamps(const CurveClamps& c, const CurvesInput& in, Diagnostics& diag, const SourceLoc& loc) {
  if (c.widths.count > 0)
    diag.warning(loc, "Curves", clamp_message("width", *in.width, c.widths, "negative", 0, kFloatMax));
  if (c.constant_width < 0)
    diag.warning(loc, "Curves", fmt::format("\"constantwidth\" {} is negative: clamped to 0", c.constant_width));
  if (c.opacities.count > 0)
    diag.warning(loc, "Curves", clamp_message("Os", *in.Os, c.opacities, "outside [0, 1]", 0, 1));
  const size_t dropped = c.appended.segments_beyond_float_range;
  if (dropped == 1)
    diag.warning(loc, "Curves",
                 fmt::format("1 segment (in curve {}) lies beyond the float range in world space: dropped",
                             c.appended.first_curve_beyond));
  else if (dropped > 1)
    diag.warning(loc, "Curves",
                 fmt::format("{} segments (the first in curve {}) lie beyond the float range in world space: dropped",
                             dropped, c.appended.first_curve_beyond));
}

}  // namespace

void SceneBuilder::curves(const std::string& type, const std::vector<int>& nvertices, const std::string& wrap,
                          const ParamList& params, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.curves(type, nvertices, wrap, params, loc); })) return;
  if (motion_) {
    // A sample of a motion block: built at MotionEnd with the others (end_curves_motion).
    if (count_motion_sample("Curves", loc)) motion_->curves.push_back({type, wrap, nvertices, params, loc});
    return;
  }
  build_curves(type, nvertices, wrap, params, {}, loc);
}

// Points move linearly between keys, but a turning transform moves them along arcs: between
// keys whose transforms turn the object, more keys, until the middle of every interval is within
// kArcTolerance of the object's size of where the transform puts it (the sagitta R(1 - cos(a/2))
// of a turn by a: about 7 degrees per interval).
std::vector<double> SceneBuilder::refine_turning_keys(const std::vector<double>& times,
                                                      const std::vector<float>& P) const {
  constexpr double kArcTolerance = 2e-3;
  constexpr int kMaxSplits = 6;  // 64 intervals between two keys at most
  if (P.size() < 3) return times;
  Vec3d lo{P[0], P[1], P[2]}, hi = lo;
  for (size_t i = 0; i + 2 < P.size(); i += 3) {
    const Vec3d p{P[i], P[i + 1], P[i + 2]};
    lo = min(lo, p);
    hi = max(hi, p);
  }
  std::vector<Vec3d> corners;
  for (int c = 0; c < 8; ++c) corners.push_back({c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z});
  auto deviation = [&](double a, double b, double& size) {
    const Matrix4 ma = ctm_at(a), mb = ctm_at(b), mm = ctm_at(0.5 * (a + b));
    double worst = 0;
    Vec3d wlo = ma.transform_point(corners[0]), whi = wlo;
    for (const Vec3d& c : corners) {
      const Vec3d pa = ma.transform_point(c), pb = mb.transform_point(c);
      wlo = min(wlo, pa);
      whi = max(whi, pa);
      worst = std::max(worst, length(mm.transform_point(c) - (pa + pb) * 0.5));
    }
    size = length(whi - wlo);
    return worst;
  };
  std::vector<double> out{times.front()};
  std::function<void(double, double, int)> split = [&](double a, double b, int depth) {
    double size = 0;
    const double d = deviation(a, b, size);
    if (depth < kMaxSplits && d > kArcTolerance * size && out.size() + 2 < kMaxCurveMotionKeys) {
      split(a, 0.5 * (a + b), depth + 1);
      split(0.5 * (a + b), b, depth + 1);
    } else {
      out.push_back(b);
    }
  };
  for (size_t k = 1; k < times.size(); ++k) split(times[k - 1], times[k], 0);
  return out;
}

void SceneBuilder::build_curves(const std::string& type, const std::vector<int>& nvertices, const std::string& wrap,
                                const ParamList& params, const std::vector<PositionSample>& samples,
                                const SourceLoc& loc) {
  if (!building_geometry("Curves", loc)) return;
  if (type != "linear" && type != "cubic")
    throw RibError("curve type must be \"linear\" or \"cubic\", found \"" + type + "\"");
  if (wrap != "periodic" && wrap != "nonperiodic")
    throw RibError("wrap must be \"periodic\" or \"nonperiodic\", found \"" + wrap + "\"");
  // A Curves call replayed from a cached archive with the transform, basis and colours of the
  // last time it was built: its segments are copied (bitwise the same as building them again).
  // Moving curves (motion samples of their own, or a moving transform) are built anew each time.
  const bool moves = motion_blur() && (samples.size() > 1 || !ctm_keys_.empty());
  const uint64_t id = moves ? 0 : replayed_id();
  note_geometry(id);
  if (id != 0) {
    auto it = curve_chunks_.find(id);
    if (it != curve_chunks_.end()) {
      CurveChunk& chunk = it->second;
      if (chunk.ctm == ctm_ && chunk.basis.m == attributes_.vbasis.m && chunk.basis.step == attributes_.vbasis.step &&
          chunk.color == attributes_.color && chunk.opacity == attributes_.opacity) {
        if (!reserve_frame_memory(chunk.segments.size(), 0, 0)) return;
        chunk.used = true;
        scene_->curves.append(chunk.segments, make_material(loc), next_strand_id_);
        next_strand_id_ += chunk.strands;
        return;
      }
    }
  }
  CurvesInput in;
  in.cubic = type == "cubic";
  in.periodic = wrap == "periodic";
  in.nvertices = nvertices;
  in.basis = attributes_.vbasis;
  in.P = read_points(params, "Curves");
  // Samples of a motion block: the shape at shutter open (at times outside the samples', the
  // nearest sample's).
  const double open = options_.output.shutter_open, close = options_.output.shutter_close;
  if (!samples.empty()) in.P = positions_at(samples, open);
  in.p_components = 3;
  in.width = primvar(params, "width", 1);
  if (const Param* cw = params.find("constantwidth")) {
    if (cw->decl.is_string() || cw->floats.size() != 1)
      throw RibError(fmt::format("\"constantwidth\" must be one number, found {}",
                                 cw->decl.is_string() ? "a string" : fmt::format("{} numbers", cw->floats.size())));
    in.constantwidth = cw->floats[0];
  }
  in.N = primvar(params, "N", 3);
  in.Cs = primvar(params, "Cs", 3);
  in.Os = primvar(params, "Os", 3);
  in.st = primvar(params, "st", 2);
  if (!in.st) {
    in.s = primvar(params, "s", 1);
    in.t = primvar(params, "t", 1);
  }
  in.default_cs = attributes_.color;
  in.default_os = attributes_.opacity;
  in.object_to_world = ctm_;
  const CurvesTopology topology{in.cubic, in.periodic, in.basis.step, in.nvertices};
  validate_topology(topology);
  uint64_t segments = 0;
  for (int nv : in.nvertices) segments += segments_in_curve(topology, nv);
  if (!reserve_frame_memory(segments, 0, 0)) return;
  // Negative widths (a cubic width overshooting at a tip, an exporter's rounding) mean "nothing
  // there": clamped to 0, so the strand keeps its other segments. Opacity is a fraction.
  CurveClamps clamps;
  clamps.widths = in.width ? clamp_values(in.width->values, 0, kFloatMax) : ClampedValues{};
  clamps.opacities = in.Os ? clamp_values(in.Os->values, 0, 1) : ClampedValues{};
  clamps.constant_width = in.constantwidth.value_or(0);
  if (clamps.constant_width < 0) in.constantwidth = 0.0f;
  uint32_t material = make_material(loc);
  if (moves) {
    const std::vector<double> times = motion_key_times(samples, in.P);
    std::vector<CurveSet> keys(times.size());
    std::vector<float> key_times(times.size());
    uint32_t strands = 0;
    for (size_t k = 0; k < times.size(); ++k) {
      CurvesInput at = in;
      if (k > 0 && !samples.empty()) at.P = positions_at(samples, times[k]);
      at.object_to_world = ctm_at(times[k]);
      uint32_t key_strands = 0;
      const CurvesAppended appended = append_curves(keys[k], at, material, key_strands);
      if (k == 0) {
        clamps.appended = appended;
        strands = key_strands;
      } else if (keys[k].size() != keys[0].size()) {
        // Segments whose points all coincide are dropped: a shape that collapses at one key.
        diag_.error(loc, "Curves",
                    fmt::format("its motion samples give {} and {} segments (points that coincide at one time): "
                                "built at shutter open without motion blur",
                                keys[0].size(), keys[k].size()));
        keys.resize(1);
        break;
      }
      key_times[k] = float((times[k] - open) / (close - open));
    }
    if (keys.size() > 1) {
      std::vector<const CurveSet*> key_sets;
      for (const CurveSet& k : keys) key_sets.push_back(&k);
      keys[0].add_motion(0, key_times, key_sets);
    }
    scene_->curves.append(keys[0], material, next_strand_id_);
    next_strand_id_ += strands;
  } else if (id == 0) {
    clamps.appended = append_curves(scene_->curves, in, material, next_strand_id_);
  } else {
    CurveChunk chunk{ctm_, attributes_.vbasis, attributes_.color, attributes_.opacity, CurveSet{}, 0, true};
    clamps.appended = append_curves(chunk.segments, in, material, chunk.strands);
    chunk.segments.shrink_to_fit();
    scene_->curves.append(chunk.segments, material, next_strand_id_);
    next_strand_id_ += chunk.strands;
    curve_chunks_.insert_or_assign(id, std::move(chunk));
  }
  // Warnings only once the request is known to be valid (append_curves throws for bad counts).
  report_curve_clamps(clamps, in, diag_, loc);
}

void SceneBuilder::polygon(const ParamList& params, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.polygon(params, loc); })) return;
  std::vector<float> P = read_points(params, "Polygon");
  if (P.size() < 9) throw RibError("a polygon needs at least 3 vertices, found " + std::to_string(P.size() / 3));
  std::vector<int> indices(P.size() / 3);
  for (size_t i = 0; i < indices.size(); ++i) indices[i] = int(i);
  polygons_request("Polygon", {1}, {int(indices.size())}, indices, params, loc);
}

void SceneBuilder::general_polygon(const std::vector<int>& nverts_per_loop, const ParamList& params,
                                   const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.general_polygon(nverts_per_loop, params, loc); })) return;
  size_t total = 0;
  for (int n : nverts_per_loop) {
    if (n < 3) throw RibError("each loop needs at least 3 vertices, found " + std::to_string(n));
    total += size_t(n);
  }
  // The loops take the points in order: a count beyond them fails before the index list is
  // allocated (else "GeneralPolygon [2000000000]" in a 50-byte file asks for 8 GB).
  const size_t points = read_points(params, "GeneralPolygon").size() / 3;
  if (total > points)
    throw RibError("the loops have " + std::to_string(total) + " vertices but only " + std::to_string(points) +
                   " points are given");
  // Fewer: the loops take the points in order, so a point no loop takes is a count mismatch.
  if (total < points) throw RibError(fmt::format("the loops have {} vertices but {} points are given", total, points));
  std::vector<int> indices(total);
  for (size_t i = 0; i < total; ++i) indices[i] = int(i);
  polygons_request("GeneralPolygon", {int(nverts_per_loop.size())}, nverts_per_loop, indices, params, loc);
}

void SceneBuilder::points_polygons(const std::vector<int>& nverts_per_face, const std::vector<int>& indices,
                                   const ParamList& params, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.points_polygons(nverts_per_face, indices, params, loc); })) return;
  std::vector<int> loops(nverts_per_face.size(), 1);
  polygons_request("PointsPolygons", loops, nverts_per_face, indices, params, loc);
}

void SceneBuilder::points_general_polygons(const std::vector<int>& nloops_per_face,
                                           const std::vector<int>& nverts_per_loop, const std::vector<int>& indices,
                                           const ParamList& params, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.points_general_polygons(nloops_per_face, nverts_per_loop, indices, params, loc); }))
    return;
  polygons_request("PointsGeneralPolygons", nloops_per_face, nverts_per_loop, indices, params, loc);
}

void SceneBuilder::add_polygons(const std::vector<int>& nloops_per_face, const std::vector<int>& nverts_per_loop,
                                const std::vector<int>& indices, const ParamList& params, const char* request,
                                const SourceLoc& loc, const std::vector<PositionSample>* samples) {
  if (!building_geometry(request, loc)) return;
  const bool moves = motion_blur() && ((samples && samples->size() > 1) || !ctm_keys_.empty());
  note_geometry(moves ? 0 : replayed_id());
  if (!reserve_frame_memory(0, nloops_per_face.size(), indices.size())) return;
  std::vector<float> P = read_points(params, request);
  if (samples && !samples->empty()) P = positions_at(*samples, options_.output.shutter_open);
  if (moves) {
    const std::vector<PositionSample> none;
    if (add_moving_polygons(nloops_per_face, nverts_per_loop, indices, P, make_material(loc), samples ? *samples : none))
      return;
    diag_.warning_once("motion:polygons", loc, request,
                       "motion blur of polygons with holes or concave faces is not supported: built at shutter open");
  }
  std::vector<Vec3f> world(P.size() / 3);
  size_t beyond_float_range = 0;
  for (size_t i = 0; i < world.size(); ++i) {
    world[i] = to_world(&P[3 * i]);
    beyond_float_range += !all_finite(world[i]);
  }
  std::string error;
  std::vector<PolygonShape> shapes =
      make_points_general_polygons(nloops_per_face, nverts_per_loop, indices, world, error);
  if (!error.empty()) throw RibError(error);
  // PolygonShape::make drops a face with such a point.
  if (beyond_float_range > 0)
    diag_.warning(loc, request,
                  fmt::format("{} beyond the float range in world space: the faces that use {} are dropped",
                              beyond_float_range == 1 ? std::string("1 point lies")
                                                      : fmt::format("{} points lie", beyond_float_range),
                              beyond_float_range == 1 ? "it" : "them"));
  if (const std::string warning = fit_polygon_st(params, nloops_per_face, nverts_per_loop, indices, world, shapes);
      !warning.empty())
    diag_.warning(loc, request, warning);
  uint32_t material = make_material(loc);
  // The faces of a mesh (or a non-planar face's fan) meet edge to edge and may each be smaller
  // than a footprint: pieces of one surface (SurfaceSet::is_piece).
  const bool pieces = shapes.size() > 1;
  for (PolygonShape& s : shapes) {
    s.piece = pieces;
    s.layer = material;
    scene_->surfaces.polygons.push_back(std::move(s));
    scene_->surfaces.polygon_material.push_back(material);
  }
}

}  // namespace darc

namespace darc {

// A motion block of Curves (scene_builder_motion.cpp checks the block itself): the samples must
// be one shape at each time, of which only the positions move.
void SceneBuilder::end_curves_motion(const MotionBlock& block) {
  const auto& first = block.curves.front();
  std::vector<PositionSample> samples;
  for (size_t k = 0; k < block.curves.size(); ++k) {
    const auto& c = block.curves[k];
    if (c.type != first.type || c.wrap != first.wrap || c.nvertices != first.nvertices) {
      diag_.error(c.loc, "Curves",
                  fmt::format("motion sample {} is not the same curves as the first (type, wrap and vertex counts "
                              "must agree): the first sample is built without motion blur",
                              k + 1));
      samples.clear();
      break;
    }
    samples.push_back({block.times[k], read_points(c.params, "Curves")});
    if (samples.back().P.size() != samples.front().P.size()) {
      diag_.error(c.loc, "Curves",
                  fmt::format("motion sample {} has {} points where the first has {}: the first sample is built "
                              "without motion blur",
                              k + 1, samples.back().P.size() / 3, samples.front().P.size() / 3));
      samples.clear();
      break;
    }
  }
  // Without samples (a mismatch), the first sample alone. Its errors are the Curves request's.
  try {
    build_curves(first.type, first.nvertices, first.wrap, first.params, samples, first.loc);
  } catch (const RibError& e) {
    diag_.error(first.loc, "Curves", e.what());
  }
}

// A motion block of polygons: the samples must be one mesh at each time (the same faces, loops
// and indices, as many points), of which only the positions move.
void SceneBuilder::end_polygons_motion(const MotionBlock& block) {
  const auto& first = block.polygons.front();
  std::vector<PositionSample> samples;
  for (size_t k = 0; k < block.polygons.size(); ++k) {
    const auto& p = block.polygons[k];
    if (p.nloops != first.nloops || p.nverts != first.nverts || p.indices != first.indices) {
      diag_.error(p.loc, p.request,
                  fmt::format("motion sample {} is not the same mesh as the first (faces, loops and vertex indices "
                              "must agree): the first sample is built without motion blur",
                              k + 1));
      samples.clear();
      break;
    }
    try {
      samples.push_back({block.times[k], read_points(p.params, p.request.c_str())});
    } catch (const RibError& e) {
      diag_.error(p.loc, p.request, e.what());
      samples.clear();
      break;
    }
    if (samples.back().P.size() != samples.front().P.size()) {
      diag_.error(p.loc, p.request,
                  fmt::format("motion sample {} has {} points where the first has {}: the first sample is built "
                              "without motion blur",
                              k + 1, samples.back().P.size() / 3, samples.front().P.size() / 3));
      samples.clear();
      break;
    }
  }
  try {
    add_polygons(first.nloops, first.nverts, first.indices, first.params, first.request.c_str(), first.loc,
                 samples.size() > 1 ? &samples : nullptr);
  } catch (const RibError& e) {
    diag_.error(first.loc, first.request, e.what());
  }
}

}  // namespace darc
