#include "core/scene/ris/ris_light_mapping.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <numbers>

#include "core/scene/ris/ris_param_reader.h"

namespace darc {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
// PxrSphereLight's radius before its transform: the unit-diameter sphere.
constexpr double kSphereLightRadius = 0.5;

Param number_param(const std::string& name, float v) {
  Param p;
  p.name = name;
  p.decl.type = ParamType::Float;
  p.floats = {v};
  return p;
}

Param triple_param(const std::string& name, ParamType type, Vec3f v) {
  Param p;
  p.name = name;
  p.decl.type = type;
  p.floats = {v.x, v.y, v.z};
  return p;
}

// The area, in world units, of the unit square in the light's xy plane.
double rect_area(const Matrix4& m) {
  return length(cross(m.transform_vector({1, 0, 0}), m.transform_vector({0, 1, 0})));
}

// The sphere's radius in world units; a non-uniform scale takes the radius of the sphere of the
// same volume (RenderMan draws a sphere whatever the scale).
double sphere_radius(const Matrix4& m) { return kSphereLightRadius * std::cbrt(std::fabs(m.determinant())); }

}  // namespace

RisLightMapping map_ris_light(const std::string& name, const ParamList& params, const Matrix4& light_to_world) {
  RisParamReader r(params, nullptr);
  RisLightMapping m;
  const bool known = name == "PxrDistantLight" || name == "PxrSphereLight" || name == "PxrRectLight" ||
                     name == "PxrDiskLight" || name == "PxrDomeLight";
  if (!known) return m;
  // RenderMan's defaults: intensity 1, exposure 0, white, shadows on.
  const float scale = r.number("intensity", 1) * std::exp2(r.number("exposure", 0));
  const Vec3f color = r.color("lightColor", {1, 1, 1});
  m.casts_shadows = r.number("enableShadows", 1) != 0;
  float intensity = scale;
  std::vector<Param> extra;
  if (name == "PxrDistantLight") {
    // Along the light's +z, as RenderMan's own bridges place it (lookdev.md §2.2).
    m.shader = "distantlight";
    extra = {triple_param("from", ParamType::Point, {0, 0, 0}), triple_param("to", ParamType::Point, {0, 0, 1})};
    // Its angular diameter in degrees (RenderMan's default, 0.53, is the sun's): soft shadows.
    extra.push_back(number_param("angle", r.number("angleExtent", kDefaultSunAngleDegrees)));
  } else if (name == "PxrDomeLight") {
    // Its radiance from every direction (times its lat-long lightColorMap), sampled with shadows.
    m.shader = "domelight";
    if (const std::string map = r.text("lightColorMap"); !map.empty()) {
      Param p;
      p.name = "mapname";
      p.decl.type = ParamType::String;
      p.strings = {map};
      extra.push_back(std::move(p));
    }
  } else {
    // Shapes of radiance L (shading/area_lights.h). With areaNormalize the light's power does
    // not change with its size: the radiance is divided by the area.
    const bool normalize = r.number("areaNormalize", 0) != 0;
    double area = 0;
    if (name == "PxrRectLight") {
      m.shader = "rectlight";
      area = rect_area(light_to_world);
    } else if (name == "PxrDiskLight") {
      m.shader = "disklight";
      area = rect_area(light_to_world) * std::numbers::pi / 4;
    } else {
      m.shader = "spherelight";
      const double radius = sphere_radius(light_to_world);
      area = 4 * std::numbers::pi * radius * radius;
    }
    if (normalize && area > 0) intensity = float(scale / area);
  }
  m.params.params = {number_param("intensity", intensity), triple_param("lightcolor", ParamType::Color, color)};
  // RenderMan's per-light sample count; 0 (its default) leaves the count to the renderer.
  if (const float fixed = r.number("fixedSampleCount", 0); fixed > 0)
    m.params.params.push_back(number_param("nsamples", fixed));
  m.params.params.insert(m.params.params.end(), extra.begin(), extra.end());
  m.dropped = r.unread();
  return m;
}

void warn_ris_light(const std::string& name, const RisLightMapping& m, Diagnostics& diag, const SourceLoc& loc) {
  if (m.shader.empty()) {
    diag.warning_once("ris-light:" + name, loc, "Light", fmt::format("unknown Light \"{}\": no light", name));
    return;
  }
  if (!m.approximation.empty())
    diag.warning_once("ris-light-approx:" + name, loc, "Light",
                      fmt::format("{} is mapped to {}", name, m.approximation));
  if (!m.dropped.empty()) {
    const std::string list = fmt::format("{}", fmt::join(m.dropped, ", "));
    diag.warning_once("ris-light-dropped:" + name + ":" + list, loc, "Light",
                      fmt::format("{} is mapped to darc's {}: dropped {}", name, m.shader, list));
  }
}

}  // namespace darc
