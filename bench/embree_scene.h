// darc's Scene as an Embree 3 scene, for the benchmark's Embree peer (bench/embree_peer.cpp and
// speed_vs_error): "the traditional method done well", to measure darc against. Only built when
// Embree is found (bench/CMakeLists.txt); the renderer never depends on it.
//
// The geometry is the same as darc's, not an approximation of it, except where noted:
// - Curve segments: CurveSet already holds world-space cubic Bézier control points and Bézier
//   coefficients of the width, and Embree's Bézier curves interpolate a radius per control point
//   with the same basis, so radius = width / 2 per coefficient is exact. Ribbons facing the ray
//   are RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE; oriented ones (RIB N) are
//   RTC_GEOMETRY_TYPE_NORMAL_ORIENTED_BEZIER_CURVE with Bézier normal coefficients (n0, 2/3 n0 +
//   1/3 n1, 1/3 n0 + 2/3 n1, n1): the Bézier form of darc's linear interpolation of the end
//   normals, so the ribbon's direction is the same (not validated yet: on a 3-strand test scene
//   with N, Embree's oriented ribbons cover about 7 % less than darc's, at their edges; no
//   benchmark scene uses N). Embree intersects flat curves as
//   kCurveTessellationRate linear pieces. Negative width coefficients (darc hides those parts)
//   are clamped to 0; segments with no positive width coefficient are left out.
// - Spheres: user geometry calling darc's own Sphere::intersect (exact: darc's spheres are
//   clipped, swept and transformed quadrics, which Embree's point spheres are not).
// - Polygons: convex single-loop polygons as a triangle fan (RTC_GEOMETRY_TYPE_TRIANGLE); others
//   (holes, concave outlines) as user geometry calling darc's PolygonShape::intersect.
#pragma once

#include <embree3/rtcore.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace darc::bench {

// Embree's tessellation rate for curves (the brief's setting; Embree's default is 4): the
// number of linear pieces per segment of its flat-curve intersector.
inline constexpr float kCurveTessellationRate = 16;

// What a geometry id of the Embree scene is, and for each of its primitives the index of the
// darc primitive it came from: a curve segment (curves), a polygon (convex polygons given to
// Embree as triangle fans), or a surface of Scene::surfaces (every other surface: darc's own
// intersector as Embree user geometry, through the SurfaceSet interface).
struct EmbreeGeometry {
  enum class Kind { FlatCurves, OrientedCurves, PolygonTriangles, Surfaces };
  Kind kind = Kind::FlatCurves;
  std::vector<uint32_t> source;  // primID -> darc index
  const Scene* scene = nullptr;  // for the user geometry callbacks
};

struct EmbreeBuildStats {
  double seconds = 0;         // rtcCommitScene (the BVH build) only
  double setup_seconds = 0;   // filling Embree's buffers from the Scene
  uint64_t embree_bytes = 0;  // peak bytes Embree allocated (its memory monitor): buffers + BVH
  uint64_t curve_segments = 0, triangles = 0, user_primitives = 0;
};

// Bytes Embree holds now and at most, fed by its memory monitor callback (atomic: Embree builds
// in parallel).
struct EmbreeMemoryMonitor {
  std::atomic<int64_t> current{0}, peak{0};
  void add(int64_t bytes) {
    int64_t now = current.fetch_add(bytes) + bytes;
    int64_t seen = peak.load();
    while (now > seen && !peak.compare_exchange_weak(seen, now)) {
    }
  }
};

// An Embree device and committed scene over a darc Scene, which must outlive it (user geometry
// points into it). Move-only; releases the Embree objects on destruction.
class EmbreeScene {
 public:
  // `threads` > 0 limits Embree's build threads (0: all cores). Returns nullptr with `error` set
  // when Embree fails (e.g. an unsupported CPU).
  static std::unique_ptr<EmbreeScene> build(const Scene& scene, int threads, EmbreeBuildStats& stats, std::string& error);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  RTCScene handle() const { return scene_; }
  const Scene& source() const { return source_; }
  const EmbreeGeometry& geometry(unsigned geom_id) const { return *geometries_[geom_id]; }

 private:
  explicit EmbreeScene(const Scene& source) : source_(source) {}
  void add_curves(bool oriented, EmbreeBuildStats& stats);
  void add_polygons(EmbreeBuildStats& stats);
  void add_user_geometry(std::vector<uint32_t> surfaces, EmbreeBuildStats& stats);

  const Scene& source_;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  // Indexed by geomID (attached in order from 0); on the heap so that the pointers Embree's user
  // geometry holds stay valid.
  std::vector<std::unique_ptr<EmbreeGeometry>> geometries_;
  // Owned here, never global; on the heap so that its address (given to Embree) is stable.
  std::unique_ptr<EmbreeMemoryMonitor> memory_ = std::make_unique<EmbreeMemoryMonitor>();
};

}  // namespace darc::bench
