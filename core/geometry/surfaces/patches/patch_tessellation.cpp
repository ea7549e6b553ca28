#include "core/geometry/surfaces/patches/patch_tessellation.h"

#include <fmt/format.h>

#include <array>
#include <cmath>

namespace darc {

namespace {

// One direction of a mesh: its control point count, wrap, and (bicubic) basis.
struct MeshDirection {
  char name;  // 'u' or 'v'
  int n;
  bool periodic;
  const CurveBasis* basis;  // nullptr: bilinear
};

std::optional<int> direction_patches(const MeshDirection& d, std::string& error) {
  const char* wrap = d.periodic ? "periodic" : "nonperiodic";
  if (!d.basis) {
    if (d.n < 2) {
      error = fmt::format("a {} bilinear patch mesh needs n{} >= 2 points, found n{} = {}", wrap, d.name, d.name, d.n);
      return std::nullopt;
    }
    return d.periodic ? d.n : d.n - 1;
  }
  const int step = d.basis->step;
  if (step < 1) {
    error = fmt::format("the {} basis step must be at least 1, found {}", d.name, step);
    return std::nullopt;
  }
  if (d.periodic) {
    if (d.n < 1 || d.n % step != 0) {
      error =
          fmt::format("a periodic bicubic patch mesh with {} step {} needs n{} = {} k points (k >= 1), found n{} = {}",
                      d.name, step, d.name, step, d.name, d.n);
      return std::nullopt;
    }
    return d.n / step;
  }
  if (d.n < 4 || (d.n - 4) % step != 0) {
    error = fmt::format(
        "a nonperiodic bicubic patch mesh with {} step {} needs n{} = 4 + {} k points (k >= 0), found n{} = {}", d.name,
        step, d.name, step, d.name, d.n);
    return std::nullopt;
  }
  return (d.n - 4) / step + 1;
}

std::array<MeshDirection, 2> directions(const PatchMeshDescription& m) {
  const bool cubic = m.type == PatchType::bicubic;
  return {MeshDirection{'u', m.nu, m.u_periodic, cubic ? &m.u_basis : nullptr},
          MeshDirection{'v', m.nv, m.v_periodic, cubic ? &m.v_basis : nullptr}};
}

bool valid_points(const PatchMeshDescription& m, std::string& error) {
  const size_t expected = size_t(m.nu) * size_t(m.nv);
  if (m.points.size() != expected) {
    error = fmt::format("nu x nv = {} x {} needs {} points, found {}", m.nu, m.nv, expected, m.points.size());
    return false;
  }
  if (!valid_control_points(m.points, error)) return false;
  if (m.height_field && (m.u_periodic || m.v_periodic)) {
    error = "a height field (\"Pz\") cannot be periodic";
    return false;
  }
  return true;
}

// The weights of one patch's control points at local parameter s in [0, 1], and their
// derivatives: bilinear (1 - s, s); bicubic [s^3 s^2 s 1] * M.
struct PatchWeights {
  std::array<double, 4> w{}, dw{};
  int count = 2;
};

PatchWeights patch_weights(const CurveBasis* basis, double s) {
  PatchWeights r;
  if (!basis) {
    r.w = {1 - s, s, 0, 0};
    r.dw = {-1, 1, 0, 0};
    return r;
  }
  r.count = 4;
  const double powers[4] = {s * s * s, s * s, s, 1}, dpowers[4] = {3 * s * s, 2 * s, 1, 0};
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row) {
      r.w[size_t(col)] += powers[row] * basis->m[size_t(row * 4 + col)];
      r.dw[size_t(col)] += dpowers[row] * basis->m[size_t(row * 4 + col)];
    }
  return r;
}

// The index of the k-th control point of patch i in one direction (wrapping when periodic).
int control_index(const MeshDirection& d, int patch, int k) {
  const int step = d.basis ? d.basis->step : 1;
  const int index = patch * step + k;
  return d.periodic ? index % d.n : index;
}

// Evaluates patch (i, j) at the mesh's parameters (u, v): the local parameter is u * nupatches - i.
SurfaceSample evaluate_patch(const PatchMeshDescription& m, const std::array<MeshDirection, 2>& dirs,
                             const PatchCounts& counts, int i, int j, double u, double v) {
  const double su = std::clamp(u * counts.nupatches - i, 0.0, 1.0);
  const double sv = std::clamp(v * counts.nvpatches - j, 0.0, 1.0);
  const PatchWeights wu = patch_weights(dirs[0].basis, su), wv = patch_weights(dirs[1].basis, sv);
  HomogeneousPoint H{{}, 0}, Hu{{}, 0}, Hv{{}, 0};
  for (int b = 0; b < wv.count; ++b)
    for (int a = 0; a < wu.count; ++a) {
      const HomogeneousPoint& p =
          m.points[size_t(control_index(dirs[0], i, a)) + size_t(control_index(dirs[1], j, b)) * size_t(m.nu)];
      const double w = wu.w[size_t(a)] * wv.w[size_t(b)];
      // Mesh parameters run nupatches times slower than a patch's own.
      const double du = wu.dw[size_t(a)] * wv.w[size_t(b)] * counts.nupatches;
      const double dv = wu.w[size_t(a)] * wv.dw[size_t(b)] * counts.nvpatches;
      H.xyz += p.xyz * w, H.w += p.w * w;
      Hu.xyz += p.xyz * du, Hu.w += p.w * du;
      Hv.xyz += p.xyz * dv, Hv.w += p.w * dv;
    }
  SurfaceSample s = rational_sample(H, Hu, Hv);
  if (m.height_field) {
    s.P.x = u, s.P.y = v;
    s.dPdu.x = 1, s.dPdu.y = 0;
    s.dPdv.x = 0, s.dPdv.y = 1;
  }
  return s;
}

std::vector<double> uniform_edges(int spans) {
  std::vector<double> edges(size_t(spans) + 1);
  for (int i = 0; i <= spans; ++i) edges[size_t(i)] = double(i) / spans;
  edges.back() = 1;
  return edges;
}

}  // namespace

std::optional<PatchCounts> patch_counts(const PatchMeshDescription& mesh, std::string& error) {
  const auto dirs = directions(mesh);
  const std::optional<int> u = direction_patches(dirs[0], error);
  if (!u) return std::nullopt;
  const std::optional<int> v = direction_patches(dirs[1], error);
  if (!v) return std::nullopt;
  return PatchCounts{*u, *v};
}

size_t uniform_count(const PatchCounts& c) { return size_t(c.nupatches) * size_t(c.nvpatches); }

size_t varying_count(const PatchMeshDescription& mesh, const PatchCounts& c) {
  return size_t(c.nupatches + (mesh.u_periodic ? 0 : 1)) * size_t(c.nvpatches + (mesh.v_periodic ? 0 : 1));
}

TriangleMeshData tessellate_patch_mesh(const PatchMeshDescription& mesh, std::string& error, const DicingView* view) {
  const std::optional<PatchCounts> counts = patch_counts(mesh, error);
  if (!counts || !valid_points(mesh, error)) return {};
  const auto dirs = directions(mesh);
  SpanLayout layout{uniform_edges(counts->nupatches), uniform_edges(counts->nvpatches), mesh.u_periodic,
                    mesh.v_periodic};
  return tessellate_spans(
      layout, [&](int i, int j, double u, double v) { return evaluate_patch(mesh, dirs, *counts, i, j, u, v); },
      view);
}

}  // namespace darc
