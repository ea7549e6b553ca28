#include "shading/color_texture.h"

#include <fmt/format.h>

#include <cmath>

#include "core/scene/ris/color_texture_params.h"
#include "shading/shader_params.h"

namespace darc {

namespace {

// The sRGB transfer function's inverse (IEC 61966-2-1).
float srgb_to_linear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

class ColorTexturedSurface : public SurfaceShader {
 public:
  ColorTexturedSurface(std::unique_ptr<SurfaceShader> inner, const Textures& textures, int id,
                       const ColorTextureSettings& settings)
      : inner_(std::move(inner)), textures_(textures), id_(id), settings_(settings) {}

  void apply_patterns(ShadingPoint& sp) const override {
    inner_->apply_patterns(sp);
    if (id_ < 0) {
      sp.Cs = mul(sp.Cs, settings_.missing);
      return;
    }
    // The manifold: scaled and offset, then inverted; the footprint's derivatives scale with it
    // (and change sign with an inversion).
    const ColorTextureSettings& m = settings_;
    TextureCoordinates at = sp.st;
    const float ss = m.invert_s ? -m.scale_s : m.scale_s, st = m.invert_t ? -m.scale_t : m.scale_t;
    at.s = at.s * m.scale_s + m.offset_s;
    at.t = at.t * m.scale_t + m.offset_t;
    if (m.invert_s) at.s = 1 - at.s;
    if (m.invert_t) at.t = 1 - at.t;
    at.dsdx *= ss;
    at.dsdy *= ss;
    at.dtdx *= st;
    at.dtdy *= st;
    Vec3f c;
    if (!textures_.lookup(id_, at, c)) return;
    if (m.linearize) c = {srgb_to_linear(c.x), srgb_to_linear(c.y), srgb_to_linear(c.z)};
    sp.Cs = mul(sp.Cs, c);
  }
  SurfaceLobes lobes(const ShadingPoint& sp) const override { return inner_->lobes(sp); }
  Vec3f response(const ShadingPoint& sp, const SurfaceLobes& l, const LightContribution& lc) const override {
    return inner_->response(sp, l, lc);
  }

 private:
  std::unique_ptr<SurfaceShader> inner_;
  const Textures& textures_;
  int id_;
  ColorTextureSettings settings_;
};

}  // namespace

std::unique_ptr<SurfaceShader> with_color_texture(std::unique_ptr<SurfaceShader> shader, const Textures& textures,
                                                  int id, const ColorTextureSettings& settings) {
  return std::make_unique<ColorTexturedSurface>(std::move(shader), textures, id, settings);
}

std::unique_ptr<SurfaceShader> apply_color_texture(std::unique_ptr<SurfaceShader> shader, const std::string& name,
                                                   const ParamList& params, Textures& textures, const SourceLoc& loc,
                                                   Diagnostics& diag) {
  ColorTextureSettings settings;
  std::string file;
  std::string fallback;
  if (name == "paintedplastic" && params.find("texturename")) {
    file = params.get_string("texturename", "");
    fallback = "paintedplastic shades without it";
  } else if (const Param* p = params.find(kColorTextureParam)) {
    file = p->strings.empty() ? std::string() : p->strings[0];
    if (const Param* m = params.find(kColorTextureManifoldParam); m && m->floats.size() >= 6) {
      settings.scale_s = m->floats[0];
      settings.scale_t = m->floats[1];
      settings.offset_s = m->floats[2];
      settings.offset_t = m->floats[3];
      settings.invert_s = m->floats[4] != 0;
      settings.invert_t = m->floats[5] != 0;
    }
    settings.linearize = params.get_float(kColorTextureLinearizeParam, 0) != 0;
    settings.missing = param_color(params, kColorTextureMissingParam, settings.missing);
    // Found by the scene builder, or not found there (warned, and the name cleared): PxrTexture
    // then gives its missing colour.
    if (file.empty()) return with_color_texture(std::move(shader), textures, -1, settings);
    fallback = name + " shades with the PxrTexture's missingColor";
  } else {
    return shader;
  }
  // The scene builder has found the file (an absolute path) or warned and left the name empty.
  if (file.empty()) return shader;
  std::string reason;
  const int id = textures.open(file, reason);
  if (id < 0)
    diag.warning_once("texture-read:" + file, loc, "Surface",
                      fmt::format("texture \"{}\" cannot be read ({}): {}", file, reason, fallback));
  if (id < 0 && name == "paintedplastic") return shader;
  return with_color_texture(std::move(shader), textures, id, settings);
}

}  // namespace darc
