// SceneBuilder's Patch, PatchMesh and NuPatch: their arguments and control points read into the
// descriptions that core/geometry/surfaces/patches/patch_tessellation.h and core/geometry/surfaces/patches/nurbs_tessellation.h lower to triangles,
// which go to the scene's triangle store with the request's material (as the polygons, the
// colour and opacity are the attributes').

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/surfaces/patches/nurbs_tessellation.h"
#include "core/geometry/surfaces/patches/patch_tessellation.h"
#include "core/scene/builder/scene_builder.h"

namespace darc {

namespace {

PatchType patch_type(const std::string& name) {
  if (name == "bilinear") return PatchType::bilinear;
  if (name == "bicubic") return PatchType::bicubic;
  throw RibError(fmt::format("unknown patch type \"{}\": \"bilinear\" or \"bicubic\"", name));
}

bool periodic(const std::string& wrap, char direction) {
  if (wrap == "periodic") return true;
  if (wrap == "nonperiodic") return false;
  throw RibError(fmt::format("unknown {}wrap \"{}\": \"periodic\" or \"nonperiodic\"", direction, wrap));
}

// The control points from "P" (w = 1), "Pw" (homogeneous, kept so: the surface is rational) or,
// where allowed, "Pz" (heights; x and y come from the surface's parameters).
std::vector<HomogeneousPoint> control_points(const ParamList& params, const char* request, bool allow_heights,
                                             bool& height_field) {
  height_field = false;
  std::vector<HomogeneousPoint> points;
  if (const Param* p = params.find("P")) {
    if (p->decl.components() != 3) throw RibError("\"P\" must be declared with 3 numbers per point");
    for (size_t i = 0; i + 2 < p->floats.size(); i += 3)
      points.push_back({{p->floats[i], p->floats[i + 1], p->floats[i + 2]}, 1});
  } else if (const Param* pw = params.find("Pw")) {
    if (pw->decl.components() != 4) throw RibError("\"Pw\" must be declared with 4 numbers per point");
    for (size_t i = 0; i + 3 < pw->floats.size(); i += 4)
      points.push_back({{pw->floats[i], pw->floats[i + 1], pw->floats[i + 2]}, pw->floats[i + 3]});
  } else if (const Param* pz = allow_heights ? params.find("Pz") : nullptr) {
    if (pz->decl.components() != 1) throw RibError("\"Pz\" must be declared with 1 number per point");
    height_field = true;
    for (float z : pz->floats) points.push_back({{0, 0, z}, 1});
  } else {
    throw RibError(fmt::format("{} needs \"P\"{}", request, allow_heights ? ", \"Pw\" or \"Pz\"" : " or \"Pw\""));
  }
  return points;
}

// Per-vertex colours would need per-vertex shading data the triangle store does not keep.
// A "st" (or "s", "t") primvar on a Patch or PatchMesh: constant, or one value per patch corner
// (varying; vertex too on bilinear meshes, whose corners are their points), bilinear over each
// patch. The vertices' (u, v) become their (s, t), which the default texture coordinates map as
// they are (RI TextureCoordinates is not read). Uniform st (one per patch): an error, as a count
// that does not match.
void map_patch_st(const PatchMeshDescription& mesh, const ParamList& params, TriangleMeshData& triangles) {
  const Param* st = params.find("st");
  const Param* s = st ? nullptr : params.find("s");
  const Param* t = st ? nullptr : params.find("t");
  if (!st && !s && !t) return;
  std::string error;
  const std::optional<PatchCounts> counts = patch_counts(mesh, error);
  if (!counts || triangles.uv.size() != triangles.P.size()) return;
  const int cols = counts->nupatches + (mesh.u_periodic ? 0 : 1), rows = counts->nvpatches + (mesh.v_periodic ? 0 : 1);
  const size_t corners = varying_count(mesh, *counts);
  auto check = [&](const Param* p, const char* name, size_t stride) {
    if (!p) return;
    const StorageClass c = p->decl.storage;
    const bool per_corner = c == StorageClass::Varying || c == StorageClass::FaceVarying ||
                            (mesh.type == PatchType::bilinear && (c == StorageClass::Vertex || c == StorageClass::FaceVertex));
    if (p->decl.is_string() || p->decl.components() != int(stride))
      throw RibError(fmt::format("\"{}\" must have {} number{} per value", name, stride, stride == 1 ? "" : "s"));
    if (c == StorageClass::Constant) {
      if (p->floats.size() != stride) throw RibError(fmt::format("constant \"{}\" needs {} numbers", name, stride));
      return;
    }
    if (!per_corner)
      throw RibError(fmt::format("{} \"{}\" is not supported on patches: give one value per patch corner (varying)", to_string(c), name));
    if (p->floats.size() != corners * stride)
      throw RibError(fmt::format("\"{}\" needs {} values (one per patch corner), found {} numbers", name, corners, p->floats.size()));
  };
  check(st, "st", 2);
  check(s, "s", 1);
  check(t, "t", 1);
  auto value = [&](const Param* p, size_t stride, size_t comp, int i, int j) -> float {
    if (!p) return 0.0f;
    if (p->decl.storage == StorageClass::Constant) return p->floats[comp];
    return p->floats[(size_t(j % rows) * size_t(cols) + size_t(i % cols)) * stride + comp];
  };
  for (Vec2f& uv : triangles.uv) {
    const double fu = std::clamp(double(uv.x), 0.0, 1.0) * counts->nupatches, fv = std::clamp(double(uv.y), 0.0, 1.0) * counts->nvpatches;
    const int i = std::min(int(fu), counts->nupatches - 1), j = std::min(int(fv), counts->nvpatches - 1);
    const float a = float(fu - i), b = float(fv - j);
    auto at = [&](const Param* p, size_t stride, size_t comp) {
      const float v00 = value(p, stride, comp, i, j), v10 = value(p, stride, comp, i + 1, j);
      const float v01 = value(p, stride, comp, i, j + 1), v11 = value(p, stride, comp, i + 1, j + 1);
      return (v00 * (1 - a) + v10 * a) * (1 - b) + (v01 * (1 - a) + v11 * a) * b;
    };
    uv = st ? Vec2f{at(st, 2, 0), at(st, 2, 1)} : Vec2f{at(s, 1, 0), at(t, 1, 0)};
  }
}

// The varying value at parameter x of a NURBS direction: RI gives one per segment boundary,
// knots[order - 1 + i] for i = 0 .. n - order + 1, linear in the parameter between them. A
// zero-length segment (repeated knot) is skipped: the first segment that holds x with a length
// decides.
double nurbs_varying(const NurbsDirection& d, double x, const std::function<double(int)>& value_at) {
  const int segments = d.n - d.order + 1;
  for (int i = 0; i < segments; ++i) {
    const double a = d.knots[size_t(d.order - 1 + i)], b = d.knots[size_t(d.order + i)];
    if (b > a && x <= b) {
      const double f = std::clamp((x - a) / (b - a), 0.0, 1.0);
      return value_at(i) * (1.0 - f) + value_at(i + 1) * f;
    }
  }
  return value_at(segments);
}

// A "st" (or "s", "t") primvar on a NuPatch: constant; varying, one value per segment corner
// ((nu - uorder + 2) x (nv - vorder + 2)), bilinear in the parameters over each segment; or
// vertex, one per control point, interpolated by the surface's own basis and weights (as P).
// Uniform st (one per segment) is an error, as on patches: the tessellation's vertices are
// shared between segments.
void map_nurbs_st(const NurbsSurfaceDescription& surface, const ParamList& params, TriangleMeshData& triangles) {
  const Param* st = params.find("st");
  const Param* s = st ? nullptr : params.find("s");
  const Param* t = st ? nullptr : params.find("t");
  if (!st && !s && !t) return;
  if (triangles.uv.size() != triangles.P.size()) return;
  const int ucorners = surface.u.n - surface.u.order + 2, vcorners = surface.v.n - surface.v.order + 2;
  auto check = [&](const Param* p, const char* name, size_t stride) {
    if (!p) return;
    if (p->decl.is_string() || p->decl.components() != int(stride))
      throw RibError(fmt::format("\"{}\" must have {} number{} per value", name, stride, stride == 1 ? "" : "s"));
    size_t expected = 0;
    switch (p->decl.storage) {
      case StorageClass::Constant: expected = 1; break;
      case StorageClass::Varying:
      case StorageClass::FaceVarying: expected = size_t(ucorners) * size_t(vcorners); break;
      case StorageClass::Vertex:
      case StorageClass::FaceVertex: expected = size_t(surface.u.n) * size_t(surface.v.n); break;
      case StorageClass::Uniform:
        throw RibError(fmt::format("uniform \"{}\" is not supported on NuPatch: give one value per segment corner "
                                   "(varying) or per control point (vertex)", name));
    }
    if (p->floats.size() != expected * stride)
      throw RibError(fmt::format("{} \"{}\" needs {} values, found {} numbers", to_string(p->decl.storage), name,
                                 expected, p->floats.size()));
  };
  check(st, "st", 2);
  check(s, "s", 1);
  check(t, "t", 1);
  // Vertex values as a scalar NURBS of the surface's basis and weights, (value, 0, 0) per
  // control point: rational like P. Built once per component.
  auto scalar_surface = [&](const Param* p, size_t stride, size_t comp) {
    NurbsSurfaceDescription scalar{surface.u, surface.v, {}};
    if (!p || (p->decl.storage != StorageClass::Vertex && p->decl.storage != StorageClass::FaceVertex)) return scalar;
    scalar.points.reserve(surface.points.size());
    for (size_t k = 0; k < surface.points.size(); ++k) {
      const double w = surface.points[k].w;
      scalar.points.push_back({{double(p->floats[k * stride + comp]) * w, 0.0, 0.0}, w});
    }
    return scalar;
  };
  const NurbsSurfaceDescription first = st ? scalar_surface(st, 2, 0) : scalar_surface(s, 1, 0);
  const NurbsSurfaceDescription second = st ? scalar_surface(st, 2, 1) : scalar_surface(t, 1, 0);
  // Component `comp` of p at parameters (u, v); `vertex_values` its scalar surface.
  auto value = [&](const Param* p, size_t stride, size_t comp, const NurbsSurfaceDescription& vertex_values, double u,
                   double v) -> double {
    if (!p) return 0.0;
    switch (p->decl.storage) {
      case StorageClass::Constant:
      case StorageClass::Uniform: return p->floats[comp];
      case StorageClass::Varying:
      case StorageClass::FaceVarying: {
        auto at = [&](int i, int j) { return double(p->floats[(size_t(j) * size_t(ucorners) + size_t(i)) * stride + comp]); };
        return nurbs_varying(surface.v, v, [&](int j) {
          return nurbs_varying(surface.u, u, [&](int i) { return at(i, j); });
        });
      }
      case StorageClass::Vertex:
      case StorageClass::FaceVertex: break;
    }
    return evaluate_nurbs(vertex_values, u, v).P.x;
  };
  for (Vec2f& uv : triangles.uv) {
    const double u = uv.x, v = uv.y;
    uv = st ? Vec2f{float(value(st, 2, 0, first, u, v)), float(value(st, 2, 1, second, u, v))}
            : Vec2f{float(value(s, 1, 0, first, u, v)), float(value(t, 1, 0, second, u, v))};
  }
}

void warn_of_interpolated_colours(const ParamList& params, Diagnostics& diag, const char* request,
                                  const SourceLoc& loc) {
  for (const char* name : {"Cs", "Os"}) {
    const Param* p = params.find(name);
    if (!p || p->decl.storage == StorageClass::Constant || p->decl.storage == StorageClass::Uniform) continue;
    diag.warning_once(std::string("interpolated colours on ") + request, loc, request,
                      fmt::format("vertex and varying \"Cs\" and \"Os\" are not supported on {}: the Color and "
                                  "Opacity attributes are used",
                                  request));
    return;
  }
}

}  // namespace

void SceneBuilder::add_patch(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc) {
  PatchMeshDescription mesh;
  mesh.type = patch_type(r.strings.at(0));
  mesh.nu = mesh.nv = mesh.type == PatchType::bilinear ? 2 : 4;
  // 4 x 4 points make one nonperiodic patch in any basis step: (4 - 4) / step + 1.
  mesh.u_basis = attributes_.ubasis;
  mesh.v_basis = attributes_.vbasis;
  add_patch_surface(mesh, params, "Patch", loc);
}

void SceneBuilder::add_patch_mesh(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc) {
  PatchMeshDescription mesh;
  mesh.type = patch_type(r.strings.at(0));
  mesh.nu = int(r.numbers.at(0));
  mesh.nv = int(r.numbers.at(1));
  mesh.u_periodic = periodic(r.strings.at(1), 'u');
  mesh.v_periodic = periodic(r.strings.at(2), 'v');
  mesh.u_basis = attributes_.ubasis;
  mesh.v_basis = attributes_.vbasis;
  add_patch_surface(mesh, params, "PatchMesh", loc);
}

void SceneBuilder::add_patch_surface(PatchMeshDescription& mesh, const ParamList& params, const char* request,
                                     const SourceLoc& loc) {
  mesh.points = control_points(params, request, true, mesh.height_field);
  warn_of_interpolated_colours(params, diag_, request, loc);
  std::string error;
  const std::optional<DicingView> view = dicing_view();
  TriangleMeshData triangles = tessellate_patch_mesh(mesh, error, view ? &*view : nullptr);
  if (!error.empty()) throw RibError(error);
  map_patch_st(mesh, params, triangles);
  add_triangle_mesh(triangles, make_material(loc));
}

std::optional<DicingView> SceneBuilder::dicing_view() const {
  if (!in_world_ || !scene_) return std::nullopt;
  const Camera& c = scene_->camera;
  return make_dicing_view(ctm_, c.world_to_camera, c.projection == Camera::Projection::Perspective, c.fov_degrees,
                          c.screen.right - c.screen.left, c.screen.top - c.screen.bottom, c.xres, c.yres);
}

void SceneBuilder::add_nu_patch(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc) {
  // numbers: nu uorder umin umax nv vorder vmin vmax; number_arrays: uknot vknot.
  NurbsSurfaceDescription s;
  const std::vector<double>& n = r.numbers;
  s.u = {int(n.at(0)), int(n.at(1)), r.number_arrays.at(0), n.at(2), n.at(3)};
  s.v = {int(n.at(4)), int(n.at(5)), r.number_arrays.at(1), n.at(6), n.at(7)};
  bool height_field = false;
  s.points = control_points(params, "NuPatch", false, height_field);
  warn_of_interpolated_colours(params, diag_, "NuPatch", loc);
  std::string error;
  const std::optional<DicingView> view = dicing_view();
  TriangleMeshData triangles = tessellate_nurbs(s, error, view ? &*view : nullptr);
  if (!error.empty()) throw RibError(error);
  map_nurbs_st(s, params, triangles);
  add_triangle_mesh(triangles, make_material(loc));
}

}  // namespace darc
