#include "bench/embree_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace darc::bench {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The 3D points of loop `k` of a polygon: the kept 2D coordinates plus the dropped one solved
// from the plane equation dot(normal, p) = plane_offset (the shape keeps only the projection).
std::vector<Vec3f> loop_points_3d(const PolygonShape& shape, size_t k) {
  const int d = shape.drop_axis, a = (d + 1) % 3, b = (d + 2) % 3;
  const double n[3] = {shape.normal.x, shape.normal.y, shape.normal.z};
  std::vector<Vec3f> points;
  for (uint32_t i = shape.loop_starts[k]; i < shape.loop_starts[k + 1]; ++i) {
    double p[3];
    p[a] = shape.points_2d[i].x;
    p[b] = shape.points_2d[i].y;
    p[d] = (shape.plane_offset - n[a] * p[a] - n[b] * p[b]) / n[d];
    points.push_back(Vec3f{float(p[0]), float(p[1]), float(p[2])});
  }
  return points;
}

// True when the polygon is one loop whose 2D outline turns the same way at every vertex, so a
// fan of triangles from its first vertex covers exactly its inside.
bool is_convex_single_loop(const PolygonShape& shape) {
  if (shape.loop_starts.size() != 2) return false;
  const uint32_t begin = shape.loop_starts[0], count = shape.loop_starts[1] - begin;
  if (count < 3) return false;
  int sign = 0;
  for (uint32_t i = 0; i < count; ++i) {
    Vec2f p0 = shape.points_2d[begin + i], p1 = shape.points_2d[begin + (i + 1) % count],
          p2 = shape.points_2d[begin + (i + 2) % count];
    double turn = double(p1.x - p0.x) * double(p2.y - p1.y) - double(p1.y - p0.y) * double(p2.x - p1.x);
    int s = (turn > 0) - (turn < 0);
    if (s == 0) continue;  // collinear vertices do not break a fan
    if (sign != 0 && s != sign) return false;
    sign = s;
  }
  return sign != 0;
}

void user_bounds(const RTCBoundsFunctionArguments* args) {
  const auto* g = static_cast<const EmbreeGeometry*>(args->geometryUserPtr);
  const BBox b = g->scene->surfaces.bounds(g->source[args->primID]);
  *args->bounds_o = RTCBounds{b.lo.x, b.lo.y, b.lo.z, 0, b.hi.x, b.hi.y, b.hi.z, 0};
}

// darc's own surface intersection inside Embree's traversal, with darc's one-sided
// culling (Sides 1 seen from behind is not a hit, as integrator/tracer.cpp). Only rtcIntersect1
// is used, so rays come one at a time (N == 1).
void user_intersect(const RTCIntersectFunctionNArguments* args) {
  if (args->N != 1 || !args->valid[0]) return;
  const auto* g = static_cast<const EmbreeGeometry*>(args->geometryUserPtr);
  const Scene& scene = *g->scene;
  auto* rayhit = reinterpret_cast<RTCRayHit*>(args->rayhit);
  const RTCRay& r = rayhit->ray;
  Ray ray{{r.org_x, r.org_y, r.org_z}, {r.dir_x, r.dir_y, r.dir_z}, r.tnear, r.tfar};
  const uint32_t i = g->source[args->primID];
  SurfaceHit h;
  if (!scene.surfaces.intersect(i, ray, h)) return;
  const Material& m = scene.materials[scene.surfaces.material(i)];
  if (m.hides_back_of(h.ng, ray.d)) return;
  rayhit->ray.tfar = h.t;
  rayhit->hit.u = h.u;
  rayhit->hit.v = h.v;
  rayhit->hit.Ng_x = h.ng.x;
  rayhit->hit.Ng_y = h.ng.y;
  rayhit->hit.Ng_z = h.ng.z;
  rayhit->hit.primID = args->primID;
  rayhit->hit.geomID = args->geomID;
  rayhit->hit.instID[0] = args->context->instID[0];
}

bool memory_monitor(void* user, ssize_t bytes, bool /*post*/) {
  static_cast<EmbreeMemoryMonitor*>(user)->add(int64_t(bytes));
  return true;  // never refuse an allocation
}

}  // namespace

std::unique_ptr<EmbreeScene> EmbreeScene::build(const Scene& scene, int threads, EmbreeBuildStats& stats,
                                                std::string& error) {
  std::unique_ptr<EmbreeScene> es(new EmbreeScene(scene));
  std::string config = threads > 0 ? "threads=" + std::to_string(threads) : "";
  es->device_ = rtcNewDevice(config.empty() ? nullptr : config.c_str());
  if (!es->device_) {
    error = "rtcNewDevice failed (error " + std::to_string(int(rtcGetDeviceError(nullptr))) + ")";
    return nullptr;
  }
  rtcSetDeviceMemoryMonitorFunction(es->device_, memory_monitor, es->memory_.get());
  Clock::time_point t0 = Clock::now();
  es->scene_ = rtcNewScene(es->device_);
  // The brief's "traditional method done well": a static scene, the best (slowest) build.
  rtcSetSceneFlags(es->scene_, RTC_SCENE_FLAG_NONE);
  rtcSetSceneBuildQuality(es->scene_, RTC_BUILD_QUALITY_HIGH);
  es->add_curves(false, stats);
  es->add_curves(true, stats);
  es->add_polygons(stats);
  stats.setup_seconds = seconds_since(t0);
  Clock::time_point t1 = Clock::now();
  rtcCommitScene(es->scene_);
  stats.seconds = seconds_since(t1);
  stats.embree_bytes = uint64_t(std::max<int64_t>(0, es->memory_->peak.load()));
  if (RTCError e = rtcGetDeviceError(es->device_); e != RTC_ERROR_NONE) {
    error = "Embree error " + std::to_string(int(e)) + " while building the scene";
    return nullptr;
  }
  return es;
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

void EmbreeScene::add_curves(bool oriented, EmbreeBuildStats& stats) {
  const CurveSet& cs = source_.curves;
  auto g = std::make_unique<EmbreeGeometry>();
  g->kind = oriented ? EmbreeGeometry::Kind::OrientedCurves : EmbreeGeometry::Kind::FlatCurves;
  g->scene = &source_;
  for (uint32_t i = 0; i < cs.size(); ++i) {
    if (cs.oriented(i) != oriented) continue;
    const float* w = cs.widths(i);
    if (std::max({w[0], w[1], w[2], w[3]}) <= 0) continue;  // hidden everywhere
    g->source.push_back(i);
  }
  if (g->source.empty()) return;
  const size_t n = g->source.size();
  RTCGeometry geom = rtcNewGeometry(device_, oriented ? RTC_GEOMETRY_TYPE_NORMAL_ORIENTED_BEZIER_CURVE
                                                      : RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                               4 * sizeof(float), kControlPointsPerSegment * n));
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned), n));
  float* normals = nullptr;
  if (oriented)
    normals = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_NORMAL, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), kControlPointsPerSegment * n));
  for (size_t k = 0; k < n; ++k) {
    const uint32_t i = g->source[k];
    const Vec3f* cp = cs.control_points(i);
    const float* w = cs.widths(i);
    indices[k] = unsigned(kControlPointsPerSegment * k);
    for (size_t j = 0; j < kControlPointsPerSegment; ++j) {
      float* v = vertices + 4 * (kControlPointsPerSegment * k + j);
      v[0] = cp[j].x, v[1] = cp[j].y, v[2] = cp[j].z, v[3] = std::max(0.0f, w[j] * 0.5f);
      if (normals) {
        Vec3f nj = lerp(float(j) / 3.0f, cs.end_normal(i, 0), cs.end_normal(i, 1));
        float* nv = normals + 3 * (kControlPointsPerSegment * k + j);
        nv[0] = nj.x, nv[1] = nj.y, nv[2] = nj.z;
      }
    }
  }
  rtcSetGeometryTessellationRate(geom, kCurveTessellationRate);
  rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_HIGH);
  rtcCommitGeometry(geom);
  rtcAttachGeometryByID(scene_, geom, unsigned(geometries_.size()));
  rtcReleaseGeometry(geom);
  stats.curve_segments += n;
  geometries_.push_back(std::move(g));
}

// Convex single-loop polygons become Embree triangles; every other surface (spheres, other
// polygons, the triangles of tessellated surfaces, quadrics) is user geometry.
void EmbreeScene::add_polygons(EmbreeBuildStats& stats) {
  const SurfaceSet& surfaces = source_.surfaces;
  std::vector<uint32_t> general;  // surface indices for user geometry
  const uint32_t spheres = uint32_t(surfaces.spheres.size()), polygons = uint32_t(surfaces.polygons.size());
  for (uint32_t i = 0; i < spheres; ++i)
    if (!surfaces.spheres[i].degenerate) general.push_back(i);
  auto g = std::make_unique<EmbreeGeometry>();
  g->kind = EmbreeGeometry::Kind::PolygonTriangles;
  g->scene = &source_;
  std::vector<Vec3f> points;
  std::vector<unsigned> triangles;
  for (uint32_t i = 0; i < source_.surfaces.polygons.size(); ++i) {
    const PolygonShape& shape = source_.surfaces.polygons[i];
    if (!is_convex_single_loop(shape)) {
      general.push_back(spheres + i);
      continue;
    }
    std::vector<Vec3f> loop = loop_points_3d(shape, 0);
    const unsigned base = unsigned(points.size());
    points.insert(points.end(), loop.begin(), loop.end());
    for (unsigned k = 1; k + 1 < loop.size(); ++k) {
      triangles.insert(triangles.end(), {base, base + k, base + k + 1});
      g->source.push_back(i);
    }
  }
  if (!g->source.empty()) {
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), points.size()));
    for (size_t k = 0; k < points.size(); ++k) v[3 * k] = points[k].x, v[3 * k + 1] = points[k].y, v[3 * k + 2] = points[k].z;
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), g->source.size()));
    std::copy(triangles.begin(), triangles.end(), idx);
    rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_HIGH);
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(scene_, geom, unsigned(geometries_.size()));
    rtcReleaseGeometry(geom);
    stats.triangles += g->source.size();
    geometries_.push_back(std::move(g));
  }
  for (uint32_t i = spheres + polygons; i < surfaces.size(); ++i) general.push_back(i);
  add_user_geometry(std::move(general), stats);
}

void EmbreeScene::add_user_geometry(std::vector<uint32_t> surfaces, EmbreeBuildStats& stats) {
  if (surfaces.empty()) return;
  auto g = std::make_unique<EmbreeGeometry>();
  g->kind = EmbreeGeometry::Kind::Surfaces;
  g->scene = &source_;
  g->source = std::move(surfaces);
  RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geom, unsigned(g->source.size()));
  rtcSetGeometryUserData(geom, g.get());
  rtcSetGeometryBoundsFunction(geom, user_bounds, nullptr);
  rtcSetGeometryIntersectFunction(geom, user_intersect);
  rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_HIGH);
  rtcCommitGeometry(geom);
  rtcAttachGeometryByID(scene_, geom, unsigned(geometries_.size()));
  rtcReleaseGeometry(geom);
  stats.user_primitives += g->source.size();
  geometries_.push_back(std::move(g));
}

}  // namespace darc::bench
