// Which hits a secondary ray ignores, and whether it is a shadow ray (which sees each primitive
// through its Transmission attribute instead of its opacity alone).
#pragma once

#include "core/geometry/curves/curve_set.h"
#include "core/scene/interaction.h"
#include "core/scene/scene.h"

#include <cstdint>
#include <limits>

namespace darc {

inline constexpr uint32_t kNoPrimitive = std::numeric_limits<uint32_t>::max();

struct HitFilter {
  // The strand a ray starts on: never hit (by id, not by an offset: an offset as wide as the
  // strand would erase contact shadows between touching strands, curve-ray-tracing.md §6 case 6).
  uint32_t skip_strand = kNoStrand;
  // The surface a ray starts on: its hits nearer than origin_min_t are the start point itself.
  uint32_t origin_primitive = kNoPrimitive;
  float origin_min_t = 0;
  bool shadow = false;
  // The mesh a footprint shadow ray starts on (kNoLayer: none): its pieces nearer than
  // origin_layer_min_t are skipped. The footprint's sub-rays start on the tangent plane of the
  // start point, which cuts into a concave mesh around it: without this, the pieces around the
  // start point shadow it in speckles (self-shadow acne).
  uint32_t origin_layer = kNoLayer;
  float origin_layer_min_t = 0;

  bool skips_primitive(uint32_t primitive, float t) const { return primitive == origin_primitive && t < origin_min_t; }
  bool skips_layer_piece(uint32_t layer, float t_near) const {
    return layer == origin_layer && layer != kNoLayer && t_near < origin_layer_min_t;
  }
};

// The filter of a shadow ray leaving `at`: it never hits the strand it starts on, nor the sphere
// or polygon (convex or flat toward a light the point faces, so never in the way).
inline HitFilter shadow_filter(const Interaction& at) {
  HitFilter f;
  f.shadow = true;
  f.skip_strand = at.strand;
  if (!at.is_curve) {
    f.origin_primitive = at.primitive;
    f.origin_min_t = std::numeric_limits<float>::infinity();
  }
  return f;
}

// The filter of a reflected or refracted ray leaving `at`: its strand is never hit; a planar
// surface (polygon, triangle, point) cannot be hit again; a curved one only beyond `self_distance`
// (a sphere's far side).
inline HitFilter leaving_filter(const Interaction& at, const Scene& scene, float self_distance) {
  HitFilter f;
  f.skip_strand = at.strand;
  if (!at.is_curve) {
    uint32_t local;
    f.origin_primitive = at.primitive;
    // A point's disc is flat too.
    const bool flat = scene.prim_kind(at.primitive, local) != Scene::PrimKind::Surface || scene.surfaces.is_flat(local);
    f.origin_min_t = flat ? std::numeric_limits<float>::infinity() : self_distance;
  }
  return f;
}

// How much of the light a shadow ray's hit of material `m` with opacity `os` blocks.
inline Vec3f shadow_opacity(const Material& m, const Vec3f& os) {
  switch (m.transmission) {
    case Transmission::Opaque: return {1, 1, 1};
    case Transmission::Transparent: return {};
    case Transmission::Os: break;
  }
  return os;
}

}  // namespace darc
