// RenderMan 21+ Pattern nodes as darc sees them: a table of the Pattern requests by handle, and
// the one thing darc takes from a pattern, a constant colour. A Bxdf parameter written
// "reference color diffuseColor" ["handle:output"] is connected to a pattern's output; darc has
// no pattern network, so only patterns whose output is one colour for the whole primitive are
// evaluated: PxrHairColor (its melanin model, below) and a pattern whose only parameter is a
// constant colour. Anything else falls back to the Bxdf's default colour (ris_bxdf_mapping.h).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/math/vec.h"
#include "parser/param_list.h"

namespace darc {

struct RisPattern {
  std::string name;  // the plugin ("PxrHairColor")
  ParamList params;
};

// By handle; a later Pattern with the same handle replaces the earlier one.
using RisPatterns = std::map<std::string, RisPattern>;

// The handle of a reference value "handle:output" (the whole value when it has no ':').
std::string pattern_handle(const std::string& reference);

// The colour of `pattern`'s outputs, or nullopt when darc cannot evaluate the pattern as one
// colour.
std::optional<Vec3f> constant_pattern_color(const RisPattern& pattern);

// A PxrTexture as darc reads it: the file and the (s, t) it is looked up at, from its manifold (a
// PxrManifold2D it references, else the primitive's own s, t): s' = s * scaleS + offsetS, then
// 1 - s' when inverted, the same for t. RenderMan's invertT is 1 by default on both nodes, for DCC
// UVs whose v runs up; whether two set flags cancel was not established (lookdev.md §4.3): t is
// inverted once when either says so. `linearize`: the file holds sRGB-encoded values.
struct RisTexture {
  std::string filename;
  float scale_s = 1, scale_t = 1, offset_s = 0, offset_t = 0;
  bool invert_s = false, invert_t = true;
  bool linearize = false;
  Vec3f missing_color{1, 0, 1};  // what PxrTexture returns when it cannot read its file
  std::vector<std::string> dropped;  // parameters of the two nodes darc does not use
};

// `pattern` as a texture, when it is a PxrTexture with a file name.
std::optional<RisTexture> texture_pattern(const RisPattern& pattern, const RisPatterns& patterns);

// PxrHairColor's physical mode: the colour of hair with `melanin` in [0, 1] (0 white, 1 black) of
// which `redness` in [0, 1] is pheomelanin. The pigment concentrations and their absorption
// coefficients are d'Eon et al. 2011 ("An Energy-Conserving Hair Reflectance Model", §6.1, the
// paper Pixar cites for PxrHairColor) as Blender's Principled Hair BSDF writes them; the colour
// is the inverse of Chiang et al. 2016's colour-to-absorption fit (§4.2), the colour that hair
// of that absorption shows. Pixar's own formula is not published.
Vec3f melanin_hair_color(float melanin, float redness);

}  // namespace darc
