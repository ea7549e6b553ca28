#include "core/geometry/curves/curve_builder.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "parser/diagnostics.h"

namespace darc {

namespace {

// Minimum vertices of one curve: a cubic segment needs 4, a line 2, a closed polyline 3 (RISpec
// gives only the segment formulas; these minimums make every formula yield >= 1 segment).
constexpr int kMinCubicVertices = 4;
constexpr int kMinLinearVertices = 2;
constexpr int kMinLinearPeriodicVertices = 3;
// A segment whose 4 control points lie within this fraction of their largest coordinate of each
// other is a point (float keeps ~7 digits, so this is a few ulps): it is dropped at load.
constexpr double kDegenerateRelativeExtent = 1e-6;


size_t sum_vertices(const CurvesTopology& topology) {
  size_t total = 0;
  for (int nv : topology.nvertices) total += static_cast<size_t>(nv);
  return total;
}

// Where one segment's data lives in the input arrays.
struct SegmentRef {
  size_t curve;                   // index of the curve
  std::array<size_t, 4> vertex;   // vertex indices (global) of the 4 cubic / first 2 linear controls
  std::array<size_t, 2> varying;  // varying indices (global) of the segment's two ends
};

template <typename T>
std::array<T, 4> elevate_linear(const T& a, const T& b) {
  return {a, a + (b - a) * (1.0 / 3.0), a + (b - a) * (2.0 / 3.0), b};
}

// Bézier coefficients of component `comp` of a primvar over one segment: vertex values follow
// the curve's basis (exact), varying values are linear per segment (elevated), uniform and
// constant values are constant.
std::array<double, 4> primvar_bezier(const PrimvarInput& pv, int comp, const SegmentRef& s, bool cubic,
                                     const BezierConversion& conversion) {
  auto value = [&](size_t index) { return static_cast<double>(pv.values[index * pv.components + comp]); };
  switch (pv.storage) {
    case StorageClass::Constant: {
      double c = value(0);
      return {c, c, c, c};
    }
    case StorageClass::Uniform: {
      double c = value(s.curve);
      return {c, c, c, c};
    }
    case StorageClass::Varying:
    case StorageClass::FaceVarying:
      return elevate_linear(value(s.varying[0]), value(s.varying[1]));
    case StorageClass::Vertex:
    case StorageClass::FaceVertex:
      if (!cubic) return elevate_linear(value(s.vertex[0]), value(s.vertex[1]));
      return conversion.apply(
          std::array<double, 4>{value(s.vertex[0]), value(s.vertex[1]), value(s.vertex[2]), value(s.vertex[3])});
  }
  return {0, 0, 0, 0};
}

std::array<Vec3d, 4> primvar_bezier3(const PrimvarInput& pv, const SegmentRef& s, bool cubic,
                                     const BezierConversion& conversion) {
  std::array<Vec3d, 4> out;
  for (int comp = 0; comp < 3; ++comp) {
    std::array<double, 4> b = primvar_bezier(pv, comp, s, cubic, conversion);
    for (int i = 0; i < 4; ++i) out[i][comp] = b[i];
  }
  return out;
}

void check_finite(const std::vector<float>& values, const char* name) {
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i])) throw RibError(fmt::format("\"{}\" value {} is not finite", name, i));
}

void validate_primvar(const std::optional<PrimvarInput>& pv, const char* name, int components,
                      const CurvesTopology& topology) {
  if (!pv) return;
  if (pv->components != components)
    throw RibError(fmt::format("\"{}\" must have {} float(s) per value, found {}", name, components, pv->components));
  size_t count = expected_count(pv->storage, topology);
  size_t floats = count * static_cast<size_t>(components);
  if (pv->values.size() != floats)
    throw RibError(fmt::format("\"{}\" ({}) needs {} floats for {} values, found {}", name, to_string(pv->storage),
                               floats, count, pv->values.size()));
  check_finite(pv->values, name);
}

void validate_input(const CurvesInput& input, const CurvesTopology& topology) {
  if (input.cubic && input.basis.step < 1)
    throw RibError(fmt::format("the basis step must be at least 1, found {}", input.basis.step));
  validate_topology(topology);
  const char* p_name = input.p_components == 4 ? "Pw" : "P";
  if (input.p_components != 3 && input.p_components != 4)
    throw RibError(fmt::format("\"P\" must have 3 (P) or 4 (Pw) floats per vertex, found {}", input.p_components));
  size_t vertices = sum_vertices(topology);
  size_t floats = vertices * static_cast<size_t>(input.p_components);
  if (input.P.size() != floats)
    throw RibError(
        fmt::format("\"{}\" needs {} floats for {} vertices, found {}", p_name, floats, vertices, input.P.size()));
  check_finite(input.P, p_name);
  if (input.p_components == 4)
    for (size_t i = 0; i < vertices; ++i)
      if (input.P[i * 4 + 3] == 0.0f) throw RibError(fmt::format("\"Pw\" vertex {} has w = 0", i));
  validate_primvar(input.width, "width", 1, topology);
  validate_primvar(input.N, "N", 3, topology);
  validate_primvar(input.Cs, "Cs", 3, topology);
  validate_primvar(input.Os, "Os", 3, topology);
  validate_primvar(input.st, "st", 2, topology);
  validate_primvar(input.s, "s", 1, topology);
  validate_primvar(input.t, "t", 1, topology);
  if (input.constantwidth && !std::isfinite(*input.constantwidth)) throw RibError("\"constantwidth\" is not finite");
}

Vec3d vertex_position(const CurvesInput& input, size_t index) {
  const float* p = input.P.data() + index * static_cast<size_t>(input.p_components);
  Vec3d pos{p[0], p[1], p[2]};
  if (input.p_components == 4) pos = pos / static_cast<double>(p[3]);
  return pos;
}

bool is_degenerate(const std::array<Vec3f, 4>& cp) {
  float extent = 0.0f, scale = 0.0f;
  for (const Vec3f& p : cp) {
    extent = std::max(extent, max_component(abs(p - cp[0])));
    scale = std::max(scale, max_component(abs(p)));
  }
  return extent <= kDegenerateRelativeExtent * scale;
}

bool all_finite(const std::array<Vec3f, 4>& cp) {
  for (const Vec3f& p : cp)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
  return true;
}

// Per-call state of the conversion to world space.
struct WorldTransform {
  Matrix4 object_to_world;
  Matrix4 world_to_object;  // for normals (inverse transpose)
  // Widths are object-space lengths measured across the strand; we scale them by the cube root
  // of the volume scale. Exact for uniform scale; under non-uniform scale it is the geometric
  // mean of the axis scales (RenderMan does not define the direction of the width).
  double width_scale;
};

WorldTransform make_world_transform(const Matrix4& object_to_world) {
  const auto& m = object_to_world.m;
  double det3 = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return {object_to_world, object_to_world.inverse(), std::cbrt(std::abs(det3))};
}

enum class SegmentOutcome { Added, Degenerate, BeyondFloatRange };

// Appends one segment, unless it is degenerate or beyond the float range in world space.
SegmentOutcome append_segment(CurveSet& set, const CurvesInput& input, const SegmentRef& s,
                              const BezierConversion& conversion, const WorldTransform& xf, uint32_t strand,
                              uint32_t attribute_id) {
  // Convert in object space first: Hermite tangents and power coefficients are not points, so
  // only the resulting Bézier control points may be transformed as points.
  std::array<Vec3d, 4> object_cp;
  if (input.cubic) {
    object_cp = conversion.apply(
        std::array<Vec3d, 4>{vertex_position(input, s.vertex[0]), vertex_position(input, s.vertex[1]),
                             vertex_position(input, s.vertex[2]), vertex_position(input, s.vertex[3])});
  } else {
    object_cp = elevate_linear(vertex_position(input, s.vertex[0]), vertex_position(input, s.vertex[1]));
  }
  std::array<Vec3f, 4> cp;
  for (int i = 0; i < 4; ++i) cp[i] = Vec3f(xf.object_to_world.transform_point(object_cp[i]));
  if (!all_finite(cp)) return SegmentOutcome::BeyondFloatRange;
  if (is_degenerate(cp)) return SegmentOutcome::Degenerate;

  std::array<double, 4> width{1, 1, 1, 1};
  if (input.width) {
    width = primvar_bezier(*input.width, 0, s, input.cubic, conversion);
  } else if (input.constantwidth) {
    width.fill(*input.constantwidth);
  }
  std::array<float, 4> world_width;
  for (int i = 0; i < 4; ++i) world_width[i] = static_cast<float>(width[i] * xf.width_scale);
  for (float w : world_width)
    if (!std::isfinite(w)) return SegmentOutcome::BeyondFloatRange;

  auto colour = [&](const std::optional<PrimvarInput>& pv, const Vec3f& fallback, std::array<Vec3f, 4>& out) {
    if (!pv) {
      out.fill(fallback);
      return;
    }
    std::array<Vec3d, 4> c = primvar_bezier3(*pv, s, input.cubic, conversion);
    for (int i = 0; i < 4; ++i) out[i] = Vec3f(c[i]);
  };

  // Normals at the segment ends: the Bézier form's end coefficients are the end values.
  Vec3f n0, n1;
  if (input.N) {
    std::array<Vec3d, 4> n = primvar_bezier3(*input.N, s, input.cubic, conversion);
    n0 = Vec3f(normalize(xf.world_to_object.transform_normal_by_inverse(n[0])));
    n1 = Vec3f(normalize(xf.world_to_object.transform_normal_by_inverse(n[3])));
    // A zero normal at one end borrows the other; with none, the ribbon faces the ray.
    if (length_squared(n0) == 0.0f) n0 = n1;
    if (length_squared(n1) == 0.0f) n1 = n0;
  }
  bool oriented = length_squared(n0) > 0.0f;

  SegmentShading colours;
  colour(input.Cs, input.default_cs, colours.cs);
  colour(input.Os, input.default_os, colours.os);
  auto coordinate = [&](const std::optional<PrimvarInput>& pv, int comp, std::array<float, 4>& out) {
    if (!pv) return;
    const std::array<double, 4> c = primvar_bezier(*pv, comp, s, input.cubic, conversion);
    for (int i = 0; i < 4; ++i) out[size_t(i)] = static_cast<float>(c[size_t(i)]);
  };
  if (input.st) {
    coordinate(input.st, 0, colours.s);
    coordinate(input.st, 1, colours.t);
  } else {
    coordinate(input.s, 0, colours.s);
    coordinate(input.t, 0, colours.t);
  }
  const Vec3f normals[2] = {n0, n1};
  set.add_segment(cp, world_width, strand, attribute_id, colours, oriented ? normals : nullptr);
  return SegmentOutcome::Added;
}

}  // namespace

void validate_topology(const CurvesTopology& topology) {
  for (size_t c = 0; c < topology.nvertices.size(); ++c) {
    int nv = topology.nvertices[c];
    if (nv <= 0) throw RibError(fmt::format("curve {} has {} vertices; nvertices must be positive", c, nv));
    if (topology.cubic && topology.periodic) {
      if (nv % topology.step != 0)
        throw RibError(fmt::format("periodic cubic curve {} has {} vertices, not a multiple of the basis step {}", c,
                                   nv, topology.step));
    } else if (topology.cubic) {
      if (nv < kMinCubicVertices || (nv - kMinCubicVertices) % topology.step != 0)
        throw RibError(fmt::format("nonperiodic cubic curve {} has {} vertices; with basis step {} it needs 4 + {}k", c,
                                   nv, topology.step, topology.step));
    } else {
      int min_vertices = topology.periodic ? kMinLinearPeriodicVertices : kMinLinearVertices;
      if (nv < min_vertices)
        throw RibError(fmt::format("{} linear curve {} has {} vertices, needs at least {}",
                                   topology.periodic ? "periodic" : "nonperiodic", c, nv, min_vertices));
    }
  }
}

size_t segments_in_curve(const CurvesTopology& topology, int nv) {
  size_t n = static_cast<size_t>(nv);
  if (!topology.cubic) return topology.periodic ? n : n - 1;
  size_t step = static_cast<size_t>(topology.step);
  return topology.periodic ? n / step : (n - kMinCubicVertices) / step + 1;
}

size_t expected_count(StorageClass storage, const CurvesTopology& topology) {
  switch (storage) {
    case StorageClass::Constant:
      return 1;
    case StorageClass::Uniform:
      return topology.nvertices.size();
    case StorageClass::Varying:
    case StorageClass::FaceVarying: {
      size_t total = 0;
      for (int nv : topology.nvertices) total += segments_in_curve(topology, nv) + (topology.periodic ? 0 : 1);
      return total;
    }
    case StorageClass::Vertex:
    case StorageClass::FaceVertex:
      return sum_vertices(topology);
  }
  return 0;
}

CurvesAppended append_curves(CurveSet& set, const CurvesInput& input, uint32_t attribute_id, uint32_t& next_strand_id) {
  CurvesAppended appended;
  CurvesTopology topology{input.cubic, input.periodic, input.cubic ? input.basis.step : 1, input.nvertices};
  validate_input(input, topology);

  BezierConversion conversion = bezier_conversion(input.basis);
  WorldTransform xf = make_world_transform(input.object_to_world);
  size_t vertex_base = 0, varying_base = 0;
  const size_t first_segment = set.size();
  for (size_t c = 0; c < input.nvertices.size(); ++c) {
    int nv = input.nvertices[c];
    size_t nsegs = segments_in_curve(topology, nv);
    uint32_t strand = next_strand_id++;
    for (size_t k = 0; k < nsegs; ++k) {
      SegmentRef s{c, {}, {varying_base + k, varying_base + (input.periodic ? (k + 1) % nsegs : k + 1)}};
      size_t first = input.cubic ? k * static_cast<size_t>(topology.step) : k;
      size_t controls = input.cubic ? 4 : 2;
      for (size_t j = 0; j < controls; ++j) s.vertex[j] = vertex_base + (first + j) % static_cast<size_t>(nv);
      if (append_segment(set, input, s, conversion, xf, strand, attribute_id) == SegmentOutcome::BeyondFloatRange &&
          appended.segments_beyond_float_range++ == 0)
        appended.first_curve_beyond = c;
    }
    vertex_base += static_cast<size_t>(nv);
    varying_base += nsegs + (input.periodic ? 0 : 1);
  }
  set.mark_strand_ends(first_segment);
  return appended;
}

}  // namespace darc
