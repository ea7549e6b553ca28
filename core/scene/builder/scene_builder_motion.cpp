// SceneBuilder's motion blur requests: Shutter, and MotionBegin/MotionEnd blocks around a
// transform (the current transform then moves: ctm_keys_), around Curves (deformation: the
// samples' positions, built in scene_builder_geometry.cpp), around polygons (deformation: a
// moving triangle mesh), around tessellated surfaces and quadrics (each sample tessellated alike:
// scene_builder_primitives.cpp) or around Points (keyed: scene_builder_points.cpp). A block that
// breaks the rules (times that do not increase, a count of samples other than the times', two
// kinds of request) is an error (RI RIE_BADMOTION) and keeps its first sample.
#include "core/scene/builder/scene_builder.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <span>

namespace darc {

namespace {

// At most this many times in a block (RenderPipe's cap; Embree's is 129): more is surely an error.
constexpr size_t kMaxMotionTimes = 64;

std::string format_times(const std::vector<double>& times) {
  std::string s = "[";
  for (size_t i = 0; i < times.size(); ++i) {
    if (i > 0) s += ' ';
    s += fmt::format("{}", times[i]);
  }
  return s + "]";
}

}  // namespace

void SceneBuilder::shutter(double open, double close, const SourceLoc& loc) {
  if (!option_allowed("Shutter", loc)) return;
  if (!(close >= open))
    throw RibError(fmt::format("close time {} is before the open time {}: the shutter is left as it was", close, open));
  options_.output.shutter_open = open;
  options_.output.shutter_close = close;
}

void SceneBuilder::motion_begin(const std::vector<double>& times, const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.motion_begin(times, loc); })) return;
  if (motion_) throw RibError("MotionBegin inside the motion block opened at " + motion_->loc.str());
  MotionBlock block;
  block.times = times;
  block.loc = loc;
  if (times.empty() || times.size() > kMaxMotionTimes) {
    diag_.error(loc, "MotionBegin",
                fmt::format("takes 1 to {} times, found {}: the block keeps its first sample", kMaxMotionTimes,
                            times.size()));
    block.failed = true;
  } else if (std::adjacent_find(times.begin(), times.end(), std::greater_equal<double>()) != times.end()) {
    diag_.error(loc, "MotionBegin",
                fmt::format("times must increase, found {}: the block keeps its first sample", format_times(times)));
    block.failed = true;
  }
  motion_ = std::move(block);
}

bool SceneBuilder::count_motion_sample(const std::string& request, const SourceLoc& loc) {
  MotionBlock& block = *motion_;
  if (block.samples == 0) block.request = request;
  ++block.samples;
  if (block.failed) return block.samples == 1;
  if (request != block.request) {
    diag_.error(loc, request,
                fmt::format("a motion block holds one kind of request: {} after {} (block at {}); the block keeps "
                            "its first sample",
                            request, block.request, block.loc.str()));
    block.failed = true;
    return false;
  }
  return true;
}

bool SceneBuilder::transform_sample(const char* request, const Matrix4& m, bool absolute, const SourceLoc& loc) {
  if (!motion_) return false;
  if (count_motion_sample(request, loc)) {
    motion_->matrices.push_back(m);
    motion_->absolute = absolute;
  }
  return true;
}

void SceneBuilder::motion_end(const SourceLoc& loc) {
  if (record([=](SceneBuilder& b) { b.motion_end(loc); })) return;
  if (!motion_) throw RibError("MotionEnd without MotionBegin");
  MotionBlock block = std::move(*motion_);
  motion_.reset();
  // A block of requests that do not move at all (Color, Surface: shading blur) is applied as
  // given; only the requests that move are counted.
  if (!block.failed && block.samples > 0 && block.samples != int(block.times.size())) {
    diag_.error(loc, "MotionEnd",
                fmt::format("the block at {} has {} times but {} requests: it keeps its first sample",
                            block.loc.str(), block.times.size(), block.samples));
    block.failed = true;
  }
  if (block.failed) {
    // The first sample alone, as a renderer without motion blur would.
    block.times.resize(1, 0.0);
    block.matrices.resize(std::min<size_t>(block.matrices.size(), 1));
    block.curves.resize(std::min<size_t>(block.curves.size(), 1));
    block.polygons.resize(std::min<size_t>(block.polygons.size(), 1));
    block.tessellated.resize(std::min<size_t>(block.tessellated.size(), 1));
    block.points.resize(std::min<size_t>(block.points.size(), 1));
  }
  if (!block.matrices.empty()) end_transform_motion(block);
  if (!block.curves.empty()) end_curves_motion(block);
  if (!block.polygons.empty()) end_polygons_motion(block);
  if (!block.tessellated.empty()) end_tessellated_motion(block);
  if (!block.points.empty()) {
    try {
      if (!building_geometry("Points", block.points.front().loc)) return;
      add_moving_points(block.points, block.times);
    } catch (const RibError& e) {
      diag_.error(block.points.front().loc, "Points", e.what());
    }
  }
}

std::vector<float> SceneBuilder::positions_at(const std::vector<PositionSample>& samples, double t) {
  if (samples.empty()) return {};
  size_t k = 1;
  while (k < samples.size() && samples[k].time < t) ++k;
  if (t <= samples.front().time) return samples.front().P;
  if (k == samples.size()) return samples.back().P;
  const PositionSample &a = samples[k - 1], &b = samples[k];
  const float s = float((t - a.time) / (b.time - a.time));
  std::vector<float> P(a.P.size());
  for (size_t i = 0; i < P.size(); ++i) P[i] = (1 - s) * a.P[i] + s * b.P[i];
  return P;
}

std::vector<double> SceneBuilder::motion_key_times(const std::vector<PositionSample>& samples,
                                                   const std::vector<float>& P) const {
  const double open = options_.output.shutter_open, close = options_.output.shutter_close;
  std::vector<double> times{open, close};
  for (const PositionSample& p : samples)
    if (p.time > open && p.time < close) times.push_back(p.time);
  for (const TransformKey& k : ctm_keys_)
    if (k.time > open && k.time < close) times.push_back(k.time);
  times = merge_times(times, {});
  if (!ctm_keys_.empty()) times = refine_turning_keys(times, P);
  return times;
}

void SceneBuilder::polygons_request(const char* request, const std::vector<int>& nloops_per_face,
                                    const std::vector<int>& nverts_per_loop, const std::vector<int>& indices,
                                    const ParamList& params, const SourceLoc& loc) {
  if (motion_) {
    // A sample of a motion block: built at MotionEnd with the others (end_polygons_motion).
    if (count_motion_sample(request, loc))
      motion_->polygons.push_back({request, nloops_per_face, nverts_per_loop, indices, params, loc});
    return;
  }
  add_polygons(nloops_per_face, nverts_per_loop, indices, params, request, loc);
}

namespace {

// Whether the face with the object-space corners P[3 i] for i in `face` is convex (and planar
// enough that a fan from its first corner covers it): every turn goes the way of its Newell
// normal.
bool convex_face(const std::vector<float>& P, std::span<const int> face) {
  const size_t n = face.size();
  auto at = [&](size_t k) {
    const size_t i = 3 * size_t(face[k % n]);
    return Vec3d{P[i], P[i + 1], P[i + 2]};
  };
  Vec3d normal{};
  for (size_t k = 0; k < n; ++k) {
    const Vec3d a = at(k), b = at(k + 1);
    normal += Vec3d{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  if (n == 3) return true;
  for (size_t k = 0; k < n; ++k) {
    const Vec3d turn = cross(at(k + 1) - at(k), at(k + 2) - at(k + 1));
    if (dot(turn, normal) < -1e-9 * length(turn) * length(normal)) return false;
  }
  return true;
}

}  // namespace

bool SceneBuilder::add_moving_polygons(const std::vector<int>& nloops_per_face, const std::vector<int>& nverts_per_loop,
                                       const std::vector<int>& indices, const std::vector<float>& P,
                                       uint32_t material, const std::vector<PositionSample>& samples) {
  TriangleMeshData mesh;
  mesh.P.resize(P.size() / 3);
  for (size_t i = 0; i < mesh.P.size(); ++i) mesh.P[i] = {P[3 * i], P[3 * i + 1], P[3 * i + 2]};
  size_t loop = 0, first = 0;
  for (int loops : nloops_per_face) {
    if (loops != 1) return false;
    const size_t n = size_t(nverts_per_loop.at(loop));
    const std::span<const int> face(indices.data() + first, n);
    for (int v : face)
      if (v < 0 || size_t(v) >= mesh.P.size()) return false;
    if (!convex_face(P, face)) return false;
    for (size_t k = 1; k + 1 < n; ++k)
      mesh.indices.insert(mesh.indices.end(), {uint32_t(face[0]), uint32_t(face[k]), uint32_t(face[k + 1])});
    ++loop;
    first += n;
  }
  add_triangle_mesh(mesh, material, &samples);
  return true;
}

// The transform moves: at each time of the block or of the transform it is given in, the
// sample at that time (interpolated, held outside the block's times) after the transform then.
void SceneBuilder::end_transform_motion(const MotionBlock& block) {
  std::vector<TransformKey> samples;
  for (size_t k = 0; k < block.matrices.size(); ++k) samples.push_back({block.times[k], block.matrices[k]});
  if (!motion_blur() || samples.size() == 1) {
    // Nothing moves: the transform at shutter open.
    const Matrix4 m = transform_at(samples, options_.output.shutter_open);
    if (block.absolute) {
      set_world_relative_ctm(m);
    } else {
      concat(m);
    }
    return;
  }
  std::vector<double> times = block.times;
  for (const TransformKey& k : ctm_keys_) times.push_back(k.time);
  const bool world_moves = block.absolute && in_world_ && !world_keys_.empty();
  if (world_moves)
    for (const TransformKey& k : world_keys_) times.push_back(k.time);
  times = merge_times(times, {});
  std::vector<TransformKey> keys;
  for (double t : times) {
    const Matrix4 local = transform_at(samples, t);
    // An absolute transform inside the world is relative to the world, which moves under a moving
    // camera.
    const Matrix4 m = block.absolute ? (world_moves ? local * transform_at(world_keys_, t) : local) : local * ctm_at(t);
    for (const auto& row : m.m)
      for (double v : row)
        if (!std::isfinite(v))
          throw RibError("the current transform would overflow (an entry beyond the double range)");
    keys.push_back({t, m});
  }
  ctm_keys_ = std::move(keys);
  ctm_ = transform_at(ctm_keys_, options_.output.shutter_open);
}

}  // namespace darc
