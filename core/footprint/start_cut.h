// Which sub-rays of a footprint start before a strand, when they start on a patch that leans
// along the ray (DistanceRay::start: a shadow ray's receiving patch, a strand's band running
// along the strand). Sub-ray (u, v) of the footprint square [-1/2, 1/2]^2 starts at depth
// u du + v dv; a strand whose depth along the footprint is z0' + u su + v sv is met by the
// sub-rays that start before it: the half-plane u cu + v cv < z0 of the square, with
// cu = du - su, cv = dv - sv. To first order a half-plane, since both depths are affine in (u, v).
#pragma once

#include "core/footprint/coverage.h"
#include "core/footprint/coverage_mask.h"

#include <cmath>

namespace darc {

struct StartCut {
  float cu = 0, cv = 0, z0 = 1;

  // The share of the footprint's sub-rays that start before the strand (the half-plane's area
  // in the square: u cu + v cv is the sum of two centred uniforms of widths |cu| and |cv|).
  float share() const { return trapezoid_cdf(z0, std::abs(cu), std::abs(cv)); }

  // The mask points that start before the strand. The test value is affine in the point's grid
  // coordinates, so it is stepped, not recomputed.
  CoverageMask mask() const {
    const float step = 1.0f / kMaskSide;
    const float si = cu * step, sj = cv * step;
    const float s0 = -0.5f * (kMaskSide - 1) * (si + sj);
    CoverageMask m = 0;
    for (int j = 0; j < kMaskSide; ++j) {
      float s = s0 + float(j) * sj;
      for (int i = 0; i < kMaskSide; ++i, s += si)
        if (s < z0) m |= CoverageMask{1} << (j * kMaskSide + i);
    }
    return m;
  }
};

}  // namespace darc
