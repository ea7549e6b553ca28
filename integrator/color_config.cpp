#include "integrator/color_config.h"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace darc {

namespace OCIO = OCIO_NAMESPACE;

namespace {

// Largest 8-bit code value.
constexpr float kMax8bit = 255.0f;
// IEC 61966-2-1 sRGB: exponent 2.4 and offset 0.055 of the piecewise curve (OCIO's
// ExponentWithLinearTransform derives the linear segment, 12.92 below 0.0031308, from them).
constexpr double kSrgbGamma = 2.4;
constexpr double kSrgbOffset = 0.055;

constexpr const char* kLinearName = "lin_rec709";
constexpr const char* kDisplayName = "sRGB";
constexpr const char* kSrgbSpaceName = "sRGB - Display";

// The in-code config of libraries.md §2 (tested there against known sRGB values).
OCIO::ConstConfigRcPtr make_builtin_config() {
  auto cfg = OCIO::Config::CreateRaw()->createEditableCopy();  // brings the "raw" space
  auto lin = OCIO::ColorSpace::Create(OCIO::REFERENCE_SPACE_SCENE);
  lin->setName(kLinearName);
  lin->setEncoding("scene-linear");
  // OIIO names scene-linear "linear"/"Linear" in oiio:ColorSpace; the aliases let it find ours.
  lin->addAlias("linear");
  lin->addAlias("Linear");
  cfg->addColorSpace(lin);

  auto srgb = OCIO::ColorSpace::Create(OCIO::REFERENCE_SPACE_SCENE);
  srgb->setName(kSrgbSpaceName);
  auto curve = OCIO::ExponentWithLinearTransform::Create();
  const double gamma[4] = {kSrgbGamma, kSrgbGamma, kSrgbGamma, 1.0};
  const double offset[4] = {kSrgbOffset, kSrgbOffset, kSrgbOffset, 0.0};
  curve->setGamma(gamma);
  curve->setOffset(offset);
  curve->setDirection(OCIO::TRANSFORM_DIR_INVERSE);  // the transform decodes; we encode
  srgb->setTransform(curve, OCIO::COLORSPACE_DIR_FROM_REFERENCE);
  cfg->addColorSpace(srgb);

  cfg->setRole(OCIO::ROLE_SCENE_LINEAR, kLinearName);
  cfg->setRole(OCIO::ROLE_DEFAULT, kLinearName);
  cfg->setRole(OCIO::ROLE_RENDERING, kLinearName);
  cfg->addDisplayView(kDisplayName, "Standard", kSrgbSpaceName, "");
  cfg->addDisplayView(kDisplayName, "Raw", "raw", "");
  cfg->validate();
  return cfg;
}

}  // namespace

struct ColorConfig::State {
  OCIO::ConstConfigRcPtr config;
  OCIO::ConstCPUProcessorRcPtr processor;
  std::string source, display, view;
};

namespace {

// Builds the state for a config and a display/view (empty = defaults); throws OCIO::Exception.
std::shared_ptr<const ColorConfig::State> make_state(OCIO::ConstConfigRcPtr config, std::string source,
                                                     std::string display, std::string view) {
  // OCIO returns "" (not null) when there is no default; guard anyway: std::string(nullptr) is UB.
  auto text = [](const char* s) { return std::string(s != nullptr ? s : ""); };
  if (display.empty()) display = text(config->getDefaultDisplay());
  if (view.empty()) view = text(config->getDefaultView(display.c_str()));
  auto processor =
      config->getProcessor(OCIO::ROLE_SCENE_LINEAR, display.c_str(), view.c_str(), OCIO::TRANSFORM_DIR_FORWARD);
  auto state = std::make_shared<ColorConfig::State>();
  state->config = std::move(config);
  state->processor = processor->getDefaultCPUProcessor();
  state->source = std::move(source);
  state->display = std::move(display);
  state->view = std::move(view);
  return state;
}

}  // namespace

ColorConfig::ColorConfig(std::shared_ptr<const State> state) : state_(std::move(state)) {}

ColorConfig ColorConfig::builtin() {
  // The built-in config is validated by tests; an exception here would be a programming error.
  return ColorConfig(make_state(make_builtin_config(), kBuiltinSource, kDisplayName, "Standard"));
}

std::optional<ColorConfig> ColorConfig::from_file(const std::string& path, std::string& error,
                                                  const std::string& display, const std::string& view) {
  try {
    return ColorConfig(make_state(OCIO::Config::CreateFromFile(path.c_str()), path, display, view));
  } catch (const std::exception& e) {
    error = "OCIO config '" + path + "': " + e.what();
    return std::nullopt;
  }
}

const std::string& ColorConfig::source() const { return state_->source; }
const std::string& ColorConfig::display() const { return state_->display; }
const std::string& ColorConfig::view() const { return state_->view; }

std::string ColorConfig::display_colorspace_tag() const {
  return state_->display == kDisplayName ? std::string("sRGB") : state_->display;
}

void ColorConfig::apply_display_transform(std::span<float> pixels, int channels) const {
  if (channels != 3 && channels != 4) return;
  const long count = static_cast<long>(pixels.size() / static_cast<std::size_t>(channels));
  if (count == 0) return;
  OCIO::PackedImageDesc desc(pixels.data(), count, 1, channels);
  state_->processor->apply(desc);
}

std::uint8_t quantize_unit_to_8bit(float v) {
  if (!(v > 0.0f)) return 0;  // also NaN
  if (v >= 1.0f) return 255;
  return static_cast<std::uint8_t>(std::lround(v * kMax8bit));
}

std::vector<std::uint8_t> ColorConfig::to_display_8bit(std::span<const float> pixels, int channels) const {
  std::vector<float> work(pixels.begin(), pixels.end());
  // Non-finite input would poison OCIO's arithmetic; it is black by contract.
  for (float& v : work) {
    if (!std::isfinite(v)) v = 0.0f;
  }
  apply_display_transform(work, channels);
  std::vector<std::uint8_t> out(work.size());
  std::transform(work.begin(), work.end(), out.begin(), quantize_unit_to_8bit);
  return out;
}

ColorConfigLookup find_color_config(const std::string& explicit_path, const std::string& ocio_env) {
  ColorConfigLookup result;
  const std::string& path = !explicit_path.empty() ? explicit_path : ocio_env;
  if (path.empty()) {
    result.config = ColorConfig::builtin();
    return result;
  }
  result.config = ColorConfig::from_file(path, result.error);
  if (!result.config && explicit_path.empty()) result.error += " (from $OCIO)";
  return result;
}

ColorConfigLookup find_color_config(const std::string& explicit_path) {
  const char* env = std::getenv("OCIO");
  return find_color_config(explicit_path, env != nullptr ? std::string(env) : std::string());
}

}  // namespace darc
