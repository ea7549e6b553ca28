// What a surface shader sees at one hit: the RI shading globals we support.
#pragma once

#include "core/math/texture_coordinates.h"
#include "core/math/vec.h"

namespace darc {

struct ShadingPoint {
  Vec3f P;    // world-space position
  Vec3f N;    // shading normal (unit), as the surface defines it (may face away from the viewer)
  Vec3f I;    // incident direction (unit), from the eye towards P
  Vec3f Cs;   // surface colour
  Vec3f Os;   // surface opacity
  TextureCoordinates st;  // RI s, t and their changes across the footprint
  Vec3f dPdv;  // unit tangent along a curve (RIB v); zero on surfaces
};

// faceforward(N, I): N flipped to face against I.
inline Vec3f faceforward(const Vec3f& n, const Vec3f& i) { return dot(n, i) < 0 ? n : -n; }

}  // namespace darc
