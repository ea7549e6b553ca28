// SceneBuilder's Points request (RI spec 3.2 §5.6): discs of diameter "width" (per point, varying
// or vertex), else "constantwidth", else 1, facing the ray, with per-point or shared Cs, Os and
// st (or s, t: a point is one texel).
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <optional>

#include "core/geometry/points/point_set.h"
#include "core/scene/builder/scene_builder.h"

namespace darc {

namespace {

// One primitive variable of a Points call as floats, `components` per point (vertex and varying:
// one value per point) or one value for all (constant and uniform: Points is one primitive).
struct PointPrimvar {
  const Param* param = nullptr;
  bool per_point = false;
  int components = 1;
  const float* value(size_t point) const { return param->floats.data() + (per_point ? point * size_t(components) : 0); }
};

std::optional<PointPrimvar> point_primvar(const ParamList& params, const char* name, int components, size_t points) {
  const Param* p = params.find(name);
  if (!p) return std::nullopt;
  if (p->decl.is_string() || p->decl.components() != components)
    throw RibError(fmt::format("\"{}\" must have {} number{} per value, declared as {}", name, components,
                               components == 1 ? "" : "s", to_string(p->decl)));
  const StorageClass storage = p->decl.storage;
  if (storage == StorageClass::FaceVarying || storage == StorageClass::FaceVertex)
    throw RibError(fmt::format("\"{}\" is {}: Points has no faces (use vertex, varying, uniform or constant)", name,
                               to_string(storage)));
  const bool per_point = storage == StorageClass::Vertex || storage == StorageClass::Varying;
  const size_t values = per_point ? points : 1;
  const size_t floats = values * size_t(components);
  if (p->floats.size() != floats)
    throw RibError(fmt::format("\"{}\" ({}) needs {} numbers for {} value{}, found {}", name, to_string(storage),
                               floats, values, values == 1 ? "" : "s", p->floats.size()));
  return PointPrimvar{p, per_point, components};
}

void check_finite(const std::vector<float>& values, const char* name) {
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i])) throw RibError(fmt::format("\"{}\" value {} is not finite", name, i));
}

// Values outside a range, clamped into it: how many, and the first (for the warning, worded as
// Curves words it).
struct Clamps {
  size_t count = 0;
  size_t first_value_index = 0;
  int first_component = 0;
  float first_value = 0;

  float apply(float v, float lo, float hi, size_t value_index, int component = 0) {
    if (v >= lo && v <= hi) return v;
    if (count++ == 0) first_value_index = value_index, first_component = component, first_value = v;
    return std::isnan(v) ? lo : std::clamp(v, lo, hi);  // NaN (only through the API): nothing there
  }
  // E.g. "\"Os\" (varying) value 0 component 2 is 1.5, outside [0, 1]: clamped to 1 (2 numbers clamped)".
  std::string message(const PointPrimvar& pv, const char* name, const char* problem, float lo, float hi) const {
    const float used = std::isnan(first_value) ? lo : std::clamp(first_value, lo, hi);
    const std::string which = pv.components == 1
                                  ? fmt::format("value {}", first_value_index)
                                  : fmt::format("value {} component {}", first_value_index, first_component);
    return fmt::format("\"{}\" ({}) {} is {}, {}: clamped to {} ({} number{} clamped)", name,
                       to_string(pv.param->decl.storage), which, first_value, problem, used, count,
                       count == 1 ? "" : "s");
  }
};

constexpr float kFloatMax = std::numeric_limits<float>::max();
constexpr float kDefaultWidth = 1.0f;  // RI spec 3.2 §5.6: Points are 1 unit wide unless told

}  // namespace

void SceneBuilder::add_points(const PrimitiveRequest&, const ParamList& params, const SourceLoc& loc) {
  const Param* P = params.find("P");
  if (!P) throw RibError("Points needs \"P\"");
  if (P->decl.is_string() || P->decl.components() != 3)
    throw RibError("\"P\" must be declared with 3 numbers per point, declared as " + to_string(P->decl));
  if (P->floats.size() % 3 != 0)
    throw RibError(fmt::format("\"P\" has {} numbers, not a whole number of points", P->floats.size()));
  check_finite(P->floats, "P");
  const size_t count = P->floats.size() / 3;
  const std::optional<PointPrimvar> width = point_primvar(params, "width", 1, count);
  const std::optional<PointPrimvar> constant_width = point_primvar(params, "constantwidth", 1, count);
  if (constant_width && constant_width->per_point)
    throw RibError("\"constantwidth\" is one width for all points: declare it constant or uniform");
  const std::optional<PointPrimvar> cs = point_primvar(params, "Cs", 3, count);
  const std::optional<PointPrimvar> os = point_primvar(params, "Os", 3, count);
  // "st", else "s" and "t" apart (param null: absent).
  const PointPrimvar st = point_primvar(params, "st", 2, count).value_or(PointPrimvar{});
  const PointPrimvar s = st.param ? PointPrimvar{} : point_primvar(params, "s", 1, count).value_or(PointPrimvar{});
  const PointPrimvar t = st.param ? PointPrimvar{} : point_primvar(params, "t", 1, count).value_or(PointPrimvar{});
  if (cs) check_finite(cs->param->floats, "Cs");
  if (count == 0) return;
  // A point costs less than a curve segment (24 bytes against 81) with the same share of the BVH
  // build: counting it as one keeps the estimate above what it needs.
  // Every key of moving points is counted too: their keys are kept as long as the frame.
  if (!reserve_frame_memory(count, 0, 0)) return;

  // Widths are measured in object space: scaled as Curves scales them (the cube root of the
  // volume scale, exact for uniform scale).
  const auto& m = ctm_.m;
  const double det3 = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                      m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                      m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  const double width_scale = std::cbrt(std::abs(det3));
  Clamps width_clamps, opacity_clamps;
  const float given_constant_width = constant_width ? *constant_width->value(0) : kDefaultWidth;
  const float shared_width = width ? 0.0f : width_clamps.apply(given_constant_width, 0, kFloatMax, 0);
  const uint32_t material = make_material(loc);
  size_t beyond_float_range = 0;
  PointSet& points = captured_points_ ? *captured_points_ : scene_->points;
  points.center.reserve(points.size() + count);
  points.radius.reserve(points.size() + count);
  points.material.reserve(points.size() + count);
  points.shading_index.reserve(points.size() + count);
  // Shared (uniform, constant) values are checked once, per-point ones at each point.
  float w = shared_width;
  PointShading shading{attributes_.color, attributes_.opacity};
  for (size_t i = 0; i < count; ++i) {
    if (width && (width->per_point || i == 0)) w = width_clamps.apply(*width->value(i), 0, kFloatMax, i);
    if (cs && (cs->per_point || i == 0)) {
      const float* c = cs->value(i);
      shading.cs = {c[0], c[1], c[2]};
    }
    if (st.param && (st.per_point || i == 0)) shading.st = {st.value(i)[0], st.value(i)[1]};
    if (s.param && (s.per_point || i == 0)) shading.st.x = *s.value(i);
    if (t.param && (t.per_point || i == 0)) shading.st.y = *t.value(i);
    if (os && (os->per_point || i == 0)) {
      const float* o = os->value(i);
      shading.os = {opacity_clamps.apply(o[0], 0, 1, i, 0), opacity_clamps.apply(o[1], 0, 1, i, 1),
                    opacity_clamps.apply(o[2], 0, 1, i, 2)};
    }
    const Vec3f centre = to_world(P->floats.data() + 3 * i);
    const float radius = float(0.5 * double(w) * width_scale);
    if (!std::isfinite(centre.x) || !std::isfinite(centre.y) || !std::isfinite(centre.z) || !std::isfinite(radius)) {
      ++beyond_float_range;
      continue;
    }
    points.add(centre, radius, material, shading);
  }
  if (later_motion_key_) return;  // its warnings were the first key's
  if (width_clamps.count > 0)
    diag_.warning(loc, "Points",
                  width ? width_clamps.message(*width, "width", "negative", 0, kFloatMax)
                        : fmt::format("\"constantwidth\" {} is negative: clamped to 0", given_constant_width));
  if (opacity_clamps.count > 0) diag_.warning(loc, "Points", opacity_clamps.message(*os, "Os", "outside [0, 1]", 0, 1));
  if (beyond_float_range > 0)
    diag_.warning(loc, "Points",
                  fmt::format("{} beyond the float range in world space: dropped",
                              beyond_float_range == 1 ? std::string("1 point lies")
                                                      : fmt::format("{} points lie", beyond_float_range)));
}

void SceneBuilder::add_moving_points(const std::vector<MotionBlockSample>& samples, const std::vector<double>& times) {
  const MotionBlockSample& first = samples.front();
  // The floats of parameter `name` of every sample, when each has it with as many (else none).
  auto parameter_samples = [&](const char* name) {
    std::vector<PositionSample> out;
    if (samples.size() < 2) return out;
    for (size_t k = 0; k < samples.size(); ++k) {
      const Param* p = samples[k].params.find(name);
      if (!p || p->decl.is_string() || (k > 0 && p->floats.size() != out.front().P.size())) return std::vector<PositionSample>{};
      out.push_back({times.at(k), p->floats});
    }
    return out;
  };
  const std::vector<PositionSample> positions = parameter_samples("P");
  const std::vector<PositionSample> widths = parameter_samples("width");
  auto alone = [&] {
    note_geometry(0);
    add_points(first.request, first.params, first.loc);
  };
  if (!motion_blur() || (samples.size() > 1 && positions.empty())) {
    if (samples.size() > 1)
      diag_.error(first.loc, "Points",
                  "its motion samples do not have as many points (\"P\"): the first sample is built without motion "
                  "blur");
    return alone();
  }
  const Param* P = first.params.find("P");
  const std::vector<double> key_times = motion_key_times(positions, P ? P->floats : std::vector<float>{});
  // The request built at every key time: its positions (and widths) then, moved by the transform
  // then, into a set of its own.
  std::vector<PointSet> keys(key_times.size());
  const Matrix4 saved_ctm = ctm_;
  const std::vector<TransformKey> saved_keys = ctm_keys_;
  bool same = true;
  for (size_t k = 0; k < key_times.size() && same; ++k) {
    ParamList params = first.params;
    for (Param& p : params.params) {
      if (p.name == "P" && !positions.empty()) p.floats = positions_at(positions, key_times[k]);
      if (p.name == "width" && !widths.empty()) p.floats = positions_at(widths, key_times[k]);
    }
    ctm_ = ctm_at(key_times[k]);
    ctm_keys_.clear();
    captured_points_ = &keys[k];
    later_motion_key_ = k > 0;
    try {
      add_points(first.request, params, first.loc);
    } catch (...) {
      captured_points_ = nullptr;
      later_motion_key_ = false;
      ctm_ = saved_ctm;
      ctm_keys_ = saved_keys;
      throw;
    }
    captured_points_ = nullptr;
    later_motion_key_ = false;
    ctm_ = saved_ctm;
    ctm_keys_ = saved_keys;
    // A point beyond the float range at one key is dropped there: the keys no longer match.
    same = keys[k].size() == keys[0].size();
  }
  if (!same) {
    diag_.warning(first.loc, "Points",
                  "a point lies beyond the float range at one motion key but not at another: built at shutter "
                  "open without motion blur");
    keys.resize(1);
  }
  note_geometry(0);
  PointSet& points = scene_->points;
  if (!reserve_frame_memory(keys[0].size(), 0, 0)) return;
  const double open = options_.output.shutter_open, close = options_.output.shutter_close;
  std::vector<float> normalised;
  for (double t : key_times) normalised.push_back(float((t - open) / (close - open)));
  const uint32_t times_offset = keys.size() > 1 ? points.add_motion_times(normalised) : 0;
  std::vector<Vec3f> centers(keys.size());
  std::vector<float> radii(keys.size());
  for (size_t i = 0; i < keys[0].size(); ++i) {
    const PointSet& open_key = keys[0];
    points.add(open_key.center[i], open_key.radius[i], open_key.material[i], open_key.shading[open_key.shading_index[i]]);
    if (keys.size() < 2) continue;
    for (size_t k = 0; k < keys.size(); ++k) {
      centers[k] = keys[k].center[i];
      radii[k] = keys[k].radius[i];
    }
    points.set_motion(points.size() - 1, times_offset, centers, radii);
  }
}

}  // namespace darc
