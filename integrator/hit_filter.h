// Which hits a secondary ray ignores, and whether it is a shadow ray (which sees each primitive
// through its Transmission attribute instead of its opacity alone).
#pragma once

#include "core/curve_set.h"
#include "core/scene.h"

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

  bool skips_primitive(uint32_t primitive, float t) const { return primitive == origin_primitive && t < origin_min_t; }
};

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
