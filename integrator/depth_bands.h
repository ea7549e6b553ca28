// Depth bands: a surface that covers a whole lens footprint, split into parts of about equal
// depth (the distance hider's collect_fragments puts each in the A-buffer as its own fragment).
#pragma once

#include "integrator/distance_hider.h"

#include <array>
#include <limits>

namespace darc {

// A surface that covers the whole footprint is one fragment at the depth of its centre, unless
// its depth changes across the footprint by more than kDepthBandFraction of that depth: then
// whatever stands on it (grass on the ground seen through a lens, where the footprint is the
// circle of confusion) is in front of it in part of the footprint and behind it in the rest.
// One depth would hide such a strand wholly or not at all (strands behind the centre's depth were
// also culled: the defocused grass lost 0.3 % of its coverage to the ground); bands of mask
// points of about equal depth, each its own fragment, let the A-buffer composite the strand in
// front of the farther bands and behind the nearer ones.
// Depths over the footprint are bilinear through the four corner mask points' hits (a plane's
// depth along the sub-rays is a ratio of linear functions: near enough over one footprint).
inline constexpr float kDepthBandFraction = 0.01f;
inline constexpr int kMaxDepthBands = 4;  // 2 did as well as 8 on the defocused grass

struct DepthBand {
  float t = 0, coverage = 0;
  CoverageMask mask = 0;
  int point = -1;  // the mask point nearest the band's centroid, shaded for it
};
struct DepthBands {
  int count = 0;
  float nearest = std::numeric_limits<float>::infinity();
  std::array<DepthBand, kMaxDepthBands> band{};
};

// The bands of sf (count 0: its depth changes too little across the footprint, one fragment).
DepthBands depth_bands(const SurfaceFragment& sf);

// The farthest depth of a surface that covers the whole footprint: its corner mask points'
// depths carried out to the footprint's corners (half a cell farther from the centre).
float farthest_depth(const SurfaceFragment& sf);

}  // namespace darc
