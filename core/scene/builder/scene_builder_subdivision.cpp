// SceneBuilder's SubdivisionMesh: the request's arrays are checked and tessellated once, here,
// as the scene is built (core/geometry/surfaces/subdivision/subdivision_surface.h), and the limit triangles join the scene's
// triangle store. Constant and uniform "Cs" / "Os" give the faces their colour and opacity (one
// material per distinct pair); "st" (or "s", "t") of any class gives the texture coordinates;
// other primitive variables are not used, with one warning each.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <map>
#include <optional>

#include "core/scene/builder/scene_builder.h"
#include "core/geometry/surfaces/subdivision/subdivision_surface.h"

namespace darc {

namespace {

constexpr const char* kRequest = "SubdivisionMesh";

template <typename T>
std::vector<T> argument_or_empty(const std::vector<std::vector<T>>& arrays, size_t i) {
  return i < arrays.size() ? arrays[i] : std::vector<T>{};
}

// The request's fixed arguments (parser/primitive_signatures.cpp: strings {scheme},
// integer_arrays {nvertices, vertices, nargs, intargs}, string_arrays {tags, stringargs},
// number_arrays {floatargs}) and "P".
SubdivisionMeshRequest mesh_request(const PrimitiveRequest& r, const ParamList& params) {
  SubdivisionMeshRequest m;
  m.scheme = r.strings.empty() ? std::string() : r.strings[0];
  m.nvertices = argument_or_empty(r.integer_arrays, 0);
  m.vertices = argument_or_empty(r.integer_arrays, 1);
  m.nargs = argument_or_empty(r.integer_arrays, 2);
  m.intargs = argument_or_empty(r.integer_arrays, 3);
  m.tags = argument_or_empty(r.string_arrays, 0);
  m.stringargs = argument_or_empty(r.string_arrays, 1);
  for (double f : argument_or_empty(r.number_arrays, 0)) m.floatargs.push_back(float(f));
  const Param* p = params.find("P");
  if (p == nullptr) throw RibError("SubdivisionMesh needs \"P\" (one point per vertex)");
  if (p->decl.is_string() || p->decl.components() != 3)
    throw RibError("\"P\" must be declared with 3 numbers per point, declared as " + to_string(p->decl));
  for (size_t i = 0; i + 2 < p->floats.size(); i += 3)
    m.P.push_back({p->floats[i], p->floats[i + 1], p->floats[i + 2]});
  return m;
}

// One colour per face from "Cs" or "Os" when it is constant or uniform; nullopt when it is
// absent or of a class the triangles cannot carry (then the attribute's value is used).
std::optional<std::vector<Vec3f>> face_values(const ParamList& params, const char* name, size_t face_count,
                                              Diagnostics& diag, const SourceLoc& loc) {
  const Param* p = params.find(name);
  if (p == nullptr) return std::nullopt;
  if (p->decl.is_string() || p->decl.components() != 3)
    throw RibError(fmt::format("\"{}\" must have 3 numbers per value, declared as {}", name, to_string(p->decl)));
  const size_t values = p->floats.size() / 3;
  auto value = [&](size_t i) { return Vec3f{p->floats[3 * i], p->floats[3 * i + 1], p->floats[3 * i + 2]}; };
  if (p->decl.storage == StorageClass::Constant) {
    if (values < 1) throw RibError(fmt::format("\"{}\" (constant) has no value", name));
    return std::vector<Vec3f>(face_count, value(0));
  }
  if (p->decl.storage == StorageClass::Uniform) {
    if (values != face_count)
      throw RibError(fmt::format("\"{}\" (uniform) has {} values, the mesh has {} faces", name, values, face_count));
    std::vector<Vec3f> out(face_count);
    for (size_t f = 0; f < face_count; ++f) out[f] = value(f);
    return out;
  }
  diag.warning_once(fmt::format("SubdivisionMesh {} {}", name, to_string(p->decl.storage)), loc, kRequest,
                    fmt::format("\"{}\" ({}) is not interpolated across a subdivision surface: the attribute's "
                                "value is used",
                                name, to_string(p->decl.storage)));
  return std::nullopt;
}

// "st" (or "s" and "t") into the request: vertex class (every given one) subdivided like P, any
// other class written per face corner and subdivided linearly inside each face (constant: one
// value; uniform: one per face; varying: one per vertex; facevarying / facevertex: one per
// corner). A missing "s" or "t" is 0. Counts that do not match the mesh are errors.
void read_texture_coordinates(const ParamList& params, SubdivisionMeshRequest& m) {
  const Param* st = params.find("st");
  const Param* s = st ? nullptr : params.find("s");
  const Param* t = st ? nullptr : params.find("t");
  if (!st && !s && !t) return;
  const size_t faces = m.nvertices.size(), vertices = m.P.size(), corners = m.vertices.size();
  auto check = [&](const Param* p, const char* name, size_t stride) {
    if (!p) return;
    if (p->decl.is_string() || p->decl.components() != int(stride))
      throw RibError(fmt::format("\"{}\" must have {} number{} per value, declared as {}", name, stride,
                                 stride == 1 ? "" : "s", to_string(p->decl)));
    size_t expected = 0;
    const char* per = "";
    switch (p->decl.storage) {
      case StorageClass::Constant: expected = 1, per = "constant"; break;
      case StorageClass::Uniform: expected = faces, per = "one per face"; break;
      case StorageClass::Vertex:
      case StorageClass::Varying: expected = vertices, per = "one per vertex"; break;
      case StorageClass::FaceVarying:
      case StorageClass::FaceVertex: expected = corners, per = "one per face corner"; break;
    }
    if (p->floats.size() != expected * stride)
      throw RibError(fmt::format("\"{}\" ({}) needs {} value{} ({}), found {} numbers", name, to_string(p->decl.storage),
                                 expected, expected == 1 ? "" : "s", per, p->floats.size()));
  };
  check(st, "st", 2);
  check(s, "s", 1);
  check(t, "t", 1);
  // The value of component `comp` of p at corner c of face f, on vertex v.
  auto value = [](const Param* p, size_t stride, size_t comp, size_t f, size_t c, size_t v) -> float {
    if (!p) return 0.0f;
    switch (p->decl.storage) {
      case StorageClass::Constant: return p->floats[comp];
      case StorageClass::Uniform: return p->floats[f * stride + comp];
      case StorageClass::Vertex:
      case StorageClass::Varying: return p->floats[v * stride + comp];
      case StorageClass::FaceVarying:
      case StorageClass::FaceVertex: break;
    }
    return p->floats[c * stride + comp];
  };
  auto at = [&](size_t f, size_t c, size_t v) {
    return st ? Vec2f{value(st, 2, 0, f, c, v), value(st, 2, 1, f, c, v)}
              : Vec2f{value(s, 1, 0, f, c, v), value(t, 1, 0, f, c, v)};
  };
  auto is_vertex = [](const Param* p) { return !p || p->decl.storage == StorageClass::Vertex; };
  if (is_vertex(st) && is_vertex(s) && is_vertex(t)) {
    for (size_t v = 0; v < vertices; ++v) m.vertex_st.push_back(at(0, 0, v));
    return;
  }
  // Face sizes and indices are checked when the mesh is tessellated; reading stops short of them.
  size_t c = 0;
  for (size_t f = 0; f < faces; ++f) {
    for (int k = 0; k < m.nvertices[f] && c < corners; ++k, ++c) {
      const int v = m.vertices[c];
      m.corner_st.push_back(at(f, c, v >= 0 && size_t(v) < vertices ? size_t(v) : 0));
    }
  }
}

void warn_unused_parameters(const ParamList& params, Diagnostics& diag, const SourceLoc& loc) {
  for (const Param& p : params.params) {
    if (p.name == "P" || p.name == "Cs" || p.name == "Os" || p.name == "st" || p.name == "s" || p.name == "t")
      continue;
    diag.warning_once("SubdivisionMesh parameter " + p.name, loc, kRequest,
                      fmt::format("\"{}\" is not used on a subdivision surface: ignored", p.name));
  }
}

// The triangles of `mesh` whose index is listed, with only the vertices they use.
TriangleMeshData select_triangles(const TriangleMeshData& mesh, const std::vector<uint32_t>& triangles) {
  TriangleMeshData out;
  std::vector<uint32_t> remap(mesh.P.size(), UINT32_MAX);
  for (uint32_t t : triangles) {
    for (int c = 0; c < 3; ++c) {
      uint32_t v = mesh.indices[3 * size_t(t) + c];
      if (remap[v] == UINT32_MAX) {
        remap[v] = uint32_t(out.P.size());
        out.P.push_back(mesh.P[v]);
        if (!mesh.N.empty()) out.N.push_back(mesh.N[v]);
        if (!mesh.uv.empty()) out.uv.push_back(mesh.uv[v]);
      }
      out.indices.push_back(remap[v]);
    }
  }
  return out;
}

}  // namespace

void SceneBuilder::add_subdivision_mesh(const PrimitiveRequest& r, const ParamList& params, const SourceLoc& loc) {
  SubdivisionMeshRequest request = mesh_request(r, params);
  read_texture_coordinates(params, request);
  const size_t face_count = request.nvertices.size();
  // Read before tessellating, so that a bad primitive variable fails the request cheaply.
  std::optional<std::vector<Vec3f>> colours = face_values(params, "Cs", face_count, diag_, loc);
  std::optional<std::vector<Vec3f>> opacities = face_values(params, "Os", face_count, diag_, loc);
  warn_unused_parameters(params, diag_, loc);
  const std::optional<DicingView> view = dicing_view();
  SubdivisionTessellation t = tessellate_subdivision_mesh(request, view ? &*view : nullptr);
  if (!t.ok()) throw RibError(t.error);
  for (const std::string& w : t.warnings) diag_.warning(loc, kRequest, w);
  if (t.mesh.triangle_count() == 0) return;
  if (!colours && !opacities) {
    add_triangle_mesh(t.mesh, make_material(loc));
    return;
  }
  // One piece per distinct (colour, opacity), in the order of the values (deterministic).
  std::map<std::array<float, 6>, std::vector<uint32_t>> pieces;
  for (uint32_t k = 0; k < t.triangle_control_face.size(); ++k) {
    const uint32_t f = t.triangle_control_face[k];
    const Vec3f c = colours ? (*colours)[f] : attributes_.color;
    const Vec3f o = opacities ? (*opacities)[f] : attributes_.opacity;
    pieces[{c.x, c.y, c.z, o.x, o.y, o.z}].push_back(k);
  }
  const Vec3f attribute_color = attributes_.color, attribute_opacity = attributes_.opacity;
  for (const auto& [value, triangles] : pieces) {
    attributes_.color = {value[0], value[1], value[2]};
    attributes_.opacity = {value[3], value[4], value[5]};
    const uint32_t material = make_material(loc);
    attributes_.color = attribute_color;
    attributes_.opacity = attribute_opacity;
    add_triangle_mesh(pieces.size() == 1 ? t.mesh : select_triangles(t.mesh, triangles), material);
  }
}

}  // namespace darc
