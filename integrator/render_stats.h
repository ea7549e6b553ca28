// Counters and timings of one frame, reported by --stats.
#pragma once

#include <cstdint>

namespace darc {

// The secondary rays, by what they are traced for.
enum class SecondaryKind { Shadow = 0, Reflection = 1, Refraction = 2 };
inline constexpr int kSecondaryKinds = 3;
inline const char* to_string(SecondaryKind k) {
  return k == SecondaryKind::Shadow ? "shadow" : k == SecondaryKind::Reflection ? "reflection" : "refraction";
}

// Per-thread counters, summed at the end of a frame.
struct RayCounters {
  uint64_t primary_rays = 0;
  uint64_t secondary_rays = 0;
  uint64_t segment_tests = 0;   // ray-curve segment intersection tests
  uint64_t surface_tests = 0;   // ray-surface intersection tests (exact rays, and sub-rays of a footprint)
  uint64_t surface_pieces = 0;  // surfaces covered analytically by a footprint (no sub-ray tests)
  uint64_t shadow_segment_tests = 0;  // the segment tests made by shadow rays (part of segment_tests)
  uint64_t shadow_surface_pieces = 0;  // the surface pieces shadow rays covered (part of surface_pieces)
  uint64_t fragment_merges = 0;  // A-buffer fragments merged because the list was full
  uint64_t point_tests = 0;     // ray-point (RI Points) tests
  uint64_t cells_visited = 0;   // grid cells visited
  uint64_t rays_terminated_early = 0;  // stopped because the remaining transmittance was negligible
  uint64_t fragments = 0;       // A-buffer fragments (distance hider)
  uint64_t peak_fragments = 0;  // longest A-buffer seen
  uint64_t pruned_rays = 0;     // secondary rays not traced because of a negligible contribution weight
  // Per SecondaryKind: traced (their sum is secondary_rays) and pruned (their sum is pruned_rays).
  uint64_t traced_by_kind[kSecondaryKinds] = {};
  uint64_t pruned_by_kind[kSecondaryKinds] = {};

  void count_traced(SecondaryKind k) {
    ++secondary_rays;
    ++traced_by_kind[int(k)];
  }
  void count_pruned(SecondaryKind k) {
    ++pruned_rays;
    ++pruned_by_kind[int(k)];
  }

  RayCounters& operator+=(const RayCounters& o) {
    primary_rays += o.primary_rays;
    secondary_rays += o.secondary_rays;
    segment_tests += o.segment_tests;
    surface_tests += o.surface_tests;
    surface_pieces += o.surface_pieces;
    shadow_segment_tests += o.shadow_segment_tests;
    shadow_surface_pieces += o.shadow_surface_pieces;
    fragment_merges += o.fragment_merges;
    point_tests += o.point_tests;
    cells_visited += o.cells_visited;
    rays_terminated_early += o.rays_terminated_early;
    fragments += o.fragments;
    peak_fragments = peak_fragments > o.peak_fragments ? peak_fragments : o.peak_fragments;
    pruned_rays += o.pruned_rays;
    for (int k = 0; k < kSecondaryKinds; ++k) {
      traced_by_kind[k] += o.traced_by_kind[k];
      pruned_by_kind[k] += o.pruned_by_kind[k];
    }
    return *this;
  }
};

struct FrameStats {
  double parse_seconds = 0;  // time spent reading RIB up to this frame's WorldEnd
  double build_seconds = 0;  // acceleration structure
  double render_seconds = 0;
  RayCounters counters;
};

}  // namespace darc
