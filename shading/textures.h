// Image textures read through OpenImageIO's TextureSystem: MIP-mapped .tx files from maketx and
// plain images, filtered over the footprint a lookup is given (its s, t derivatives along two
// directions of the hit's footprint: lookdev.md §4.2), so that the distance hider's one ray per
// pixel reads a texture antialiased. The cache behind it is one private TextureSystem for the
// process (textures.cpp says why it is never destroyed); ids and handles belong to the instance.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/math/texture_coordinates.h"
#include "core/math/vec.h"


namespace darc {

class Textures {
 public:
  Textures();  // opens OpenImageIO's cache with the first texture
  ~Textures();
  Textures(const Textures&) = delete;
  Textures& operator=(const Textures&) = delete;

  // An id for the texture at `path` (a resolved file name: the scene builder finds it along
  // Option "searchpath" "texture"), or -1 when the file cannot be opened as a texture; `reason`
  // then says why. Opening one file twice gives the same id.
  int open(const std::string& path, std::string& reason);

  // The texture's first three channels (a one-channel texture as grey) filtered over `at`,
  // wrapping as the file says (periodic when it does not say). Thread safe. False (and black)
  // when the lookup fails.
  bool lookup(int id, const TextureCoordinates& at, Vec3f& rgb) const;

 private:
  struct System;
  std::unique_ptr<System> system_;
};

}  // namespace darc
