// A colour texture on any surface shader: before the shader's lobes, Cs is multiplied by a texture
// looked up at the point's (s, t), moved by a 2-D manifold, filtered over the point's footprint
// (shading/textures.h). paintedplastic's "texturename" is one (RI Spec 3.2 Appendix A: plastic with
// Cs times the texture); a RIS Bxdf colour fed by a PxrTexture is another (the manifold of its
// PxrManifold2D, sRGB decoding when "linearize", and its missingColor when the file cannot be read:
// core/scene/ris/color_texture_params.h).
#pragma once

#include <memory>

#include "core/math/vec.h"
#include "parser/diagnostics.h"
#include "parser/param_list.h"
#include "shading/surface_shader.h"
#include "shading/textures.h"

namespace darc {

struct ColorTextureSettings {
  float scale_s = 1, scale_t = 1, offset_s = 0, offset_t = 0;
  bool invert_s = false, invert_t = false;
  bool linearize = false;     // decode sRGB-encoded values to linear
  Vec3f missing{1, 1, 1};     // the factor when the texture cannot be read
};

// `shader` with Cs multiplied by texture `id` of `textures` (-1: by settings.missing).
std::unique_ptr<SurfaceShader> with_color_texture(std::unique_ptr<SurfaceShader> shader, const Textures& textures,
                                                  int id, const ColorTextureSettings& settings);

// `shader` wrapped as `params` ask: paintedplastic's "texturename", or the PxrTexture parameters
// of color_texture_params.h (a file that cannot be read: one warning at `loc`, then the missing
// colour). `shader` unchanged when they name no texture.
std::unique_ptr<SurfaceShader> apply_color_texture(std::unique_ptr<SurfaceShader> shader, const std::string& name,
                                                   const ParamList& params, Textures& textures, const SourceLoc& loc,
                                                   Diagnostics& diag);

}  // namespace darc
