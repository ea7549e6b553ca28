// What a frame's geometry will cost in memory, estimated from its primitive counts before the
// geometry is built, so that a frame larger than the memory darc may use fails with a clear
// error at the request that crosses the limit, instead of meeting the kernel's OOM killer
// halfway through the build (SceneBuilder, FrameOverrides::memory_limit_bytes).
//
// The figures are the peaks measured on a 1M-segment hair scene by bench/memory_per_segment
// (docs/memory.md), rounded up: they include what the arrays' growth and the BVH build hold for
// a moment, not only what stays. tests/core/scene/frame_memory_test.cpp checks that they stay above what
// CurveSet and Accelerator report on real scenes.
#pragma once

#include <cstdint>
#include <string>

namespace darc {

// A curve segment: its CurveSet entry (81 B measured: control points, width, ids, flags, the
// arrays' slack) and the peak of the BVH build over it (218 B: the boxes, the build's references
// and the binary tree the 4-wide BVH is collapsed from; 49 B of it stay), 299 B in all; 336 was
// 324 rounded up when the build's peak was 243 B, and stays as a margin (docs/memory.md).
inline constexpr uint64_t kFrameBytesPerCurveSegment = 336;
// A sphere or a polygon: the shape, its material index, and its share of the BVH and its build.
inline constexpr uint64_t kFrameBytesPerSurface = 512;
// Each point of a polygon's loops (its 2D copy, index and loop bookkeeping).
inline constexpr uint64_t kFrameBytesPerPolygonPoint = 32;

// A pixel of the image: the film's sums (48 B), the resolved image (20 B: R, G, B, A, Z), and
// what writing it holds (the converted buffer, OpenImageIO's own), 122 B measured as the peak
// resident growth of a 4096x4096 frame of one sphere over a 256x256 one (docs/memory.md),
// rounded up. A Format of 16384x16384 is 34 GB: a frame over the limit fails at its first
// geometry request, or at WorldEnd, before the image is allocated.
inline constexpr uint64_t kFrameBytesPerPixel = 128;

inline uint64_t frame_memory_estimate(uint64_t curve_segments, uint64_t surfaces, uint64_t polygon_points) {
  return curve_segments * kFrameBytesPerCurveSegment + surfaces * kFrameBytesPerSurface +
         polygon_points * kFrameBytesPerPolygonPoint;
}

// Bytes, for messages: "1.5 GB", "340 MB", "12 kB" (powers of 1024, as Slurm's --mem counts).
std::string format_bytes(uint64_t bytes);

}  // namespace darc
