#include "ri/value_counts.h"

#include "core/geometry/curves/curve_builder.h"
#include "core/geometry/surfaces/patches/patch_tessellation.h"
#include "parser/diagnostics.h"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace darc {

namespace {

size_t sum(std::span<const int> values, const char* what) {
  size_t total = 0;
  for (int v : values) {
    if (v < 0) throw RibError(fmt::format("{} has a negative count {}", what, v));
    total += size_t(v);
  }
  return total;
}

// Points shared by index: one more than the largest index.
size_t indexed_points(std::span<const int> indices) {
  int largest = -1;
  for (int i : indices) {
    if (i < 0) throw RibError(fmt::format("negative vertex index {}", i));
    largest = std::max(largest, i);
  }
  return size_t(largest + 1);
}

// A mesh's counts: facevarying and facevertex both one per face corner.
ValueCounts same_counts(size_t uniform, size_t points, size_t face_points) {
  return ValueCounts{uniform, points, points, face_points, face_points};
}

bool is_quadric(const std::string& name) {
  return name == "Sphere" || name == "Cone" || name == "Cylinder" || name == "Disk" || name == "Hyperboloid" ||
         name == "Paraboloid" || name == "Torus";
}

}  // namespace

size_t ValueCounts::of(StorageClass storage) const {
  switch (storage) {
    case StorageClass::Constant: return 1;
    case StorageClass::Uniform: return uniform;
    case StorageClass::Varying: return varying;
    case StorageClass::Vertex: return vertex;
    case StorageClass::FaceVarying: return facevarying;
    case StorageClass::FaceVertex: return facevertex;
  }
  return 1;
}

ValueCounts single_values() { return {}; }

ValueCounts polygon_counts(int nvertices) {
  if (nvertices < 0) throw RibError(fmt::format("negative vertex count {}", nvertices));
  return same_counts(1, size_t(nvertices), size_t(nvertices));
}

ValueCounts points_counts(int npoints) {
  if (npoints < 0) throw RibError(fmt::format("negative point count {}", npoints));
  return same_counts(1, size_t(npoints), size_t(npoints));
}

ValueCounts general_polygon_counts(std::span<const int> nverts_per_loop) {
  const size_t points = sum(nverts_per_loop, "nverts");
  return same_counts(1, points, points);
}

ValueCounts points_polygons_counts(std::span<const int> nverts_per_face, std::span<const int> indices) {
  const size_t corners = sum(nverts_per_face, "nverts");
  if (corners != indices.size())
    throw RibError(fmt::format("nverts sums to {} but {} vertex indices were given", corners, indices.size()));
  return same_counts(nverts_per_face.size(), indexed_points(indices), corners);
}

ValueCounts points_general_polygons_counts(std::span<const int> nloops_per_face, std::span<const int> nverts_per_loop,
                                           std::span<const int> indices) {
  if (sum(nloops_per_face, "nloops") != nverts_per_loop.size())
    throw RibError(fmt::format("nloops sums to {} but {} loops were given", sum(nloops_per_face, "nloops"),
                               nverts_per_loop.size()));
  const size_t corners = sum(nverts_per_loop, "nverts");
  if (corners != indices.size())
    throw RibError(fmt::format("nverts sums to {} but {} vertex indices were given", corners, indices.size()));
  return same_counts(nloops_per_face.size(), indexed_points(indices), corners);
}

ValueCounts curves_counts(const std::string& type, std::span<const int> nvertices, const std::string& wrap, int vstep) {
  if (type != "linear" && type != "cubic") throw RibError(fmt::format("unknown curve type \"{}\"", type));
  if (wrap != "periodic" && wrap != "nonperiodic") throw RibError(fmt::format("unknown wrap mode \"{}\"", wrap));
  const CurvesTopology topology{type == "cubic", wrap == "periodic", vstep, nvertices};
  validate_topology(topology);
  return ValueCounts{nvertices.size(), expected_count(StorageClass::Varying, topology),
                     expected_count(StorageClass::Vertex, topology), expected_count(StorageClass::FaceVarying, topology),
                     expected_count(StorageClass::FaceVertex, topology)};
}

ValueCounts primitive_counts(const PrimitiveRequest& r, int ustep, int vstep) {
  if (is_quadric(r.name)) return same_counts(1, 4, 4);  // the corners of the (u, v) square
  if (r.name == "Patch") {
    const std::string& type = r.strings.at(0);
    if (type != "bilinear" && type != "bicubic") throw RibError(fmt::format("unknown patch type \"{}\"", type));
    const size_t vertex = type == "bilinear" ? 4 : 16;
    return ValueCounts{1, 4, vertex, 4, vertex};
  }
  if (r.name == "PatchMesh") {
    PatchMeshDescription mesh;
    const std::string& type = r.strings.at(0);
    if (type != "bilinear" && type != "bicubic") throw RibError(fmt::format("unknown patch type \"{}\"", type));
    mesh.type = type == "bilinear" ? PatchType::bilinear : PatchType::bicubic;
    mesh.nu = int(r.numbers.at(0));
    mesh.nv = int(r.numbers.at(1));
    mesh.u_periodic = r.strings.at(1) == "periodic";
    mesh.v_periodic = r.strings.at(2) == "periodic";
    mesh.u_basis.step = ustep;
    mesh.v_basis.step = vstep;
    std::string error;
    const std::optional<PatchCounts> counts = patch_counts(mesh, error);
    if (!counts) throw RibError(error);
    const size_t varying = varying_count(mesh, *counts);
    const size_t vertex = size_t(mesh.nu) * size_t(mesh.nv);
    return ValueCounts{uniform_count(*counts), varying, vertex, varying, vertex};
  }
  if (r.name == "NuPatch") {
    const int nu = int(r.numbers.at(0)), uorder = int(r.numbers.at(1));
    const int nv = int(r.numbers.at(4)), vorder = int(r.numbers.at(5));
    if (nu < uorder || nv < vorder || uorder < 1 || vorder < 1)
      throw RibError(fmt::format("NuPatch needs nu >= uorder and nv >= vorder, found {} {} {} {}", nu, uorder, nv, vorder));
    const size_t varying = size_t(nu - uorder + 2) * size_t(nv - vorder + 2);
    const size_t vertex = size_t(nu) * size_t(nv);
    return ValueCounts{size_t(nu - uorder + 1) * size_t(nv - vorder + 1), varying, vertex, varying, vertex};
  }
  if (r.name == "SubdivisionMesh") {
    const std::vector<int>& nverts = r.integer_arrays.at(0);
    const std::vector<int>& indices = r.integer_arrays.at(1);
    return points_polygons_counts(nverts, indices);
  }
  throw RibError(fmt::format("{} has no known value counts", r.name));
}

}  // namespace darc
