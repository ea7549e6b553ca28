// One frame's scene, world space, immutable once built: the camera, the output settings from
// the RIB options, the geometry, and the attribute states (materials) and lights the
// geometry refers to. Shaders and lights are kept as RIB names + parameters; shading/ turns
// them into evaluators.
#pragma once

#include "core/math/shutter_opening.h"
#include "core/math/bbox.h"
#include "core/scene/camera.h"
#include "core/geometry/curves/curve_set.h"
#include "core/geometry/points/point_set.h"
#include "core/geometry/surfaces/surface_set.h"
#include "core/accel/accelerator.h"
#include "parser/param_list.h"
#include "parser/source_loc.h"

#include <cstdint>
#include <string>
#include <vector>

namespace darc {

// How a primitive blocks the light of shadow rays (RI `Attribute "visibility"` "transmission",
// BMRT's `Attribute "render" "casts_shadows"`).
enum class Transmission {
  Os,           // by its opacity Os (the default: every object casts shadows)
  Opaque,       // fully, whatever its opacity
  Transparent,  // not at all (invisible to shadow rays)
};

// The attribute state a primitive was created with (one per primitive request).
struct Material {
  std::string surface = "defaultsurface";  // RIB shader name as given
  ParamList surface_params;
  SourceLoc surface_loc;
  Vec3f color{1, 1, 1};    // Cs
  Vec3f opacity{1, 1, 1};  // Os
  int sides = 2;
  // True when the geometric normal must be reversed (Orientation differs from the handedness
  // of the object's coordinate system, RI spec 3.2 §4.2).
  bool flip_normals = false;
  bool matte = false;
  std::vector<uint32_t> lights;  // indices into Scene::lights that illuminate this primitive
  std::string emissive_area_light;  // AreaLightSource shader the geometry belongs to, if any
  ParamList area_light_params;
  // The Scene::lights index of that area light: the geometry is its shape (-1: none).
  int area_light = -1;
  Transmission transmission = Transmission::Os;
  // True when the surface shader reads a texture: only then does a hit compute its (s, t) and
  // their derivatives (Interaction::st), which every other hit would pay for nothing.
  bool reads_textures = false;

  // Sides 1: true when a surface whose own normal (orientation not applied) is `n` is seen
  // from behind along direction d, and so is not drawn. The one place the rule is written.
  bool hides_back_of(const Vec3f& n, const Vec3f& d) const {
    return sides == 1 && dot(flip_normals ? -n : n, d) > 0;
  }
};

struct LightDesc {
  std::string shader;  // "ambientlight", "distantlight", "pointlight", "spotlight", or other
  ParamList params;
  Matrix4 shader_to_world;  // the current transform when LightSource was called
  SourceLoc loc;
  // Ray-traced shadows: a "shadowname" parameter (any name; "raytrace" or a shadow-map file we
  // trace instead), or `Attribute "light" "shadows" "on"` when the light was declared.
  bool casts_shadows = false;
  // An AreaLightSource: its shape is the geometry whose Material::area_light is this light.
  bool geometry = false;
};

// Everything the RIB options say about the image, the sampling and the output.
struct OutputSettings {
  int frame_number = 0;
  bool has_frame_number = false;
  std::string display_name = "ri.tif";
  std::string display_type = "file";
  std::string display_mode = "rgba";
  int xres = 640, yres = 480;
  double pixel_aspect = 1;
  double crop[4] = {0, 1, 0, 1};  // xmin xmax ymin ymax (NDC)
  double pixel_samples[2] = {2, 2};
  std::string filter_name = "gaussian";
  double filter_width[2] = {2, 2};
  double exposure_gain = 1, exposure_gamma = 1;
  // Shutter open close (RIB times). Motion blur when close > open: moving geometry keeps its keys
  // at shutter-normalised times (0 at open, 1 at close) and the hiders sample or sweep them.
  double shutter_open = 0, shutter_close = 0;
  // Camera "shutteropening" [a b]: how much each moment of the shutter counts.
  ShutterOpening shutter_opening;
  std::string hider = "hidden";
  // Option "trace" "int maxdepth": the longest chain of reflection and refraction rays (PRMan's
  // name and default). Shadow rays do not count.
  int trace_max_depth = 10;
  // The RenderMan 21+ Integrator the file asks for ("PxrPathTracer"; empty: none). darc renders
  // with its own integrator whatever it says; --stats reports it.
  std::string integrator;
};

// The BVH: on the benchmark scenes at 160x120 (callgrind, instructions in render_frame) the
// distance hider needs 26 % (hair ball) to 45 % (grass) fewer than with the grid (8 cells per
// primitive), the stochastic hider 18 % to 68 % fewer (docs/performance-640.md has wall times).
inline constexpr AcceleratorKind kDefaultAccelerator = AcceleratorKind::Bvh;

struct Scene {
  Camera camera;
  OutputSettings output;
  CurveSet curves;
  SurfaceSet surfaces;
  PointSet points;  // RI Points: sub-pixel discs facing the ray
  std::vector<Material> materials;
  std::vector<LightDesc> lights;

  // Says the geometry is bitwise that of another scene with the same non-empty key: every
  // geometry request of the frame was replayed from the archive cache, in the same order, with the
  // same transforms (SceneBuilder). Empty: unknown. AccelerationReuse builds on it.
  std::string geometry_key;

  // One acceleration structure over everything: primitive index p < curves.size() is a curve
  // segment, then the surfaces in SurfaceSet's order, then the points (last, so that scenes
  // without points keep their order).
  Accelerator accel;
  BBox bounds;

  // The kinds the tracers tell apart: sub-pixel curve segments, surfaces (every surface
  // request, behind SurfaceSet) and sub-pixel points. `local` is the index among that kind.
  enum class PrimKind { CurveSegment, Surface, Point };
  PrimKind prim_kind(uint32_t p, uint32_t& local) const {
    const uint32_t nc = uint32_t(curves.size()), ns = uint32_t(surfaces.size());
    if (p < nc) { local = p; return PrimKind::CurveSegment; }
    if (p - nc < ns) { local = p - nc; return PrimKind::Surface; }
    local = p - nc - ns;
    return PrimKind::Point;
  }
  size_t primitive_count() const { return curves.size() + surfaces.size() + points.size(); }
  // Motion blur: whether anything moves during the shutter (curves, surfaces lowered to
  // triangles, points); the hiders sample or sweep time only then, so that still scenes keep their images.
  bool has_motion() const { return curves.has_motion() || surfaces.has_motion() || points.has_motion(); }

  // Builds the acceleration structure over the primitives (call once after all geometry is added).
  void build_acceleration(AcceleratorKind kind = kDefaultAccelerator);
};

}  // namespace darc
