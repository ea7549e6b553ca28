// Colour management: which OpenColorIO config is in force, and the display transform that turns
// scene-linear pixels into display-referred 8-bit values.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace darc {

// An OCIO config plus the processor for its display/view transform, from the scene_linear role to
// the chosen display and view. A cheap-to-copy value (shared immutable state); safe to use from
// several threads at once.
class ColorConfig {
 public:
  // Source name reported for the config built in code.
  static constexpr const char* kBuiltinSource = "built-in";

  // The in-code config: scene-linear Rec.709 ("lin_rec709", aliases "linear"/"Linear"), the
  // piecewise sRGB curve as display "sRGB" view "Standard" (and view "Raw"). It is always valid.
  static ColorConfig builtin();
  // Loads an .ocio file. An empty display/view means the config's defaults. On failure returns
  // nullopt and sets error (OCIO's message, with the path).
  static std::optional<ColorConfig> from_file(const std::string& path, std::string& error,
                                              const std::string& display = {}, const std::string& view = {});

  // "built-in" or the path the config was read from.
  const std::string& source() const;
  const std::string& display() const;
  const std::string& view() const;
  // The colour-space tag to store in display-referred files ("oiio:ColorSpace"): "sRGB" for an
  // sRGB display, else the display's name.
  std::string display_colorspace_tag() const;

  // Applies the display/view transform in place to interleaved pixels with 3 (RGB) or 4 (RGBA)
  // channels; alpha is left untouched. Pixels stay premultiplied, as RenderMan outputs are: the
  // transform is applied to premultiplied RGB, like PRMan and OIIO do by default.
  void apply_display_transform(std::span<float> pixels, int channels) const;
  // Display-referred 8-bit values of linear interleaved pixels (3 or 4 channels): the display
  // transform on RGB, alpha as is, then each value clamped to [0, 1] and rounded to 0..255.
  // Non-finite values become 0.
  std::vector<std::uint8_t> to_display_8bit(std::span<const float> pixels, int channels) const;

  // Opaque: keeps OpenColorIO's headers out of this one.
  struct State;

 private:
  explicit ColorConfig(std::shared_ptr<const State> state);
  std::shared_ptr<const State> state_;
};

// A value in [0, 1] (clamped; NaN counts as 0) rounded to the nearest of 0..255.
std::uint8_t quantize_unit_to_8bit(float v);

// Result of looking up the colour config to use.
struct ColorConfigLookup {
  std::optional<ColorConfig> config;  // set on success
  std::string error;                  // why it failed otherwise
};

// The config to use: explicit_path if non-empty (e.g. --ocio-config), else the file named by
// ocio_env (the value of $OCIO) if non-empty, else the built-in one. A named file that cannot be
// read is an error, not a silent fallback: colours would differ from what the user asked for.
ColorConfigLookup find_color_config(const std::string& explicit_path, const std::string& ocio_env);
// The same with ocio_env read from the environment variable OCIO.
ColorConfigLookup find_color_config(const std::string& explicit_path);

}  // namespace darc
