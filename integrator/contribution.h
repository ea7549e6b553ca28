// Contribution weights (the seed paper: "we also avoid tracing reflection/refraction/shadow rays
// if the final contribution is sufficiently small"). Every ray carries how much its result can
// still change the pixel: the camera footprint's coverage of the fragment x the transmittance in
// front of it x its opacity x the shader's factor for that ray (Kr*F, Kt*(1-F), the light's
// unoccluded contribution for a shadow ray), multiplied along the path. A secondary ray whose
// weight is below the threshold is not traced; what replaces its result is said where it is cast.
#pragma once

namespace darc {

// The default --contribution-threshold (docs/performance-secondary.md measures 0 to 1e-1).
inline constexpr float kDefaultContributionThreshold = 1e-3f;

}  // namespace darc
