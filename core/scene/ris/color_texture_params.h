// The surface-shader parameters by which a RIS Bxdf whose colour is fed by a PxrTexture hands
// that texture to darc's shader (core/scene/ris/ris_bxdf_mapping.cpp writes them, the scene builder finds
// the file, shading/color_texture.h reads them). Names no RIB shader uses: darc's own.
#pragma once

namespace darc {

// string: the texture file (a full path once the scene builder has found it; empty: not found).
inline constexpr const char* kColorTextureParam = "__colortexture";
// float[6]: scale s, scale t, offset s, offset t, invert s, invert t (RisTexture).
inline constexpr const char* kColorTextureManifoldParam = "__colortexture_manifold";
// float: 1 when the file's values are sRGB-encoded (PxrTexture "linearize").
inline constexpr const char* kColorTextureLinearizeParam = "__colortexture_linearize";
// color: the colour used when the file cannot be found or read (PxrTexture "missingColor").
inline constexpr const char* kColorTextureMissingParam = "__colortexture_missing";

}  // namespace darc
