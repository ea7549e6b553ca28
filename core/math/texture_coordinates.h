// Texture coordinates at a hit and the footprint they stand for: RI s, t (s runs left to right
// across an image, t down it) and their changes along the two directions of the hit's footprint
// (Interaction::dPdx, dPdy), which is all a filtered texture lookup needs (lookdev.md §4.2).
// Zero derivatives: a point (an exact ray of the stochastic hider).
#pragma once

namespace darc {

struct TextureCoordinates {
  float s = 0, t = 0;
  float dsdx = 0, dtdx = 0, dsdy = 0, dtdy = 0;
};

}  // namespace darc
