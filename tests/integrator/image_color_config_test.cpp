#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include "integrator/color_config.h"

namespace darc {
namespace {

namespace fs = std::filesystem;

// IEC 61966-2-1 sRGB encoding, the analytic reference for the display transform.
float srgb_encode(float linear) {
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

TEST(ColorConfig, BuiltinIsSrgbStandard) {
  const ColorConfig config = ColorConfig::builtin();
  EXPECT_EQ(config.source(), ColorConfig::kBuiltinSource);
  EXPECT_EQ(config.display(), "sRGB");
  EXPECT_EQ(config.view(), "Standard");
  EXPECT_EQ(config.display_colorspace_tag(), "sRGB");
}

TEST(ColorConfig, BuiltinDisplayTransformIsTheSrgbCurveAndLeavesAlpha) {
  const ColorConfig config = ColorConfig::builtin();
  const std::vector<float> linear = {0.0f, 0.0031308f, 0.01f, 0.18f, 0.5f, 1.0f};
  std::vector<float> rgba;
  for (float v : linear) rgba.insert(rgba.end(), {v, v, v, 0.3f});
  config.apply_display_transform(rgba, 4);
  for (std::size_t i = 0; i < linear.size(); ++i) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgba[4 * i + c], srgb_encode(linear[i]), 2e-5f) << linear[i];
    EXPECT_EQ(rgba[4 * i + 3], 0.3f);
  }
  EXPECT_NEAR(srgb_encode(0.18f), 0.461356f, 1e-5f);  // the reference itself, libraries.md §2
}

TEST(ColorConfig, EightBitValuesOfKnownLinearValues) {
  const ColorConfig config = ColorConfig::builtin();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> rgb = {0.18f, 0.18f, 0.18f, 1.0f, 0.0f, 2.0f, -1.0f, nan, 0.0031308f};
  const auto out = config.to_display_8bit(rgb, 3);
  ASSERT_EQ(out.size(), rgb.size());
  EXPECT_EQ(out[0], 118);  // 0.461356 * 255 = 117.6
  EXPECT_EQ(out[3], 255);
  EXPECT_EQ(out[4], 0);
  EXPECT_EQ(out[5], 255);  // above 1 clips
  EXPECT_EQ(out[6], 0);    // negative clips
  EXPECT_EQ(out[7], 0);    // NaN is black
  EXPECT_EQ(out[8], 10);   // 0.04045 * 255 = 10.3
}

TEST(ColorConfig, AlphaIsQuantisedLinearly) {
  const auto out = ColorConfig::builtin().to_display_8bit(std::vector<float>{0.0f, 0.0f, 0.0f, 0.5f}, 4);
  EXPECT_EQ(out[3], 128);  // 127.5 rounds up
}

TEST(ColorConfig, QuantisationRounds) {
  EXPECT_EQ(quantize_unit_to_8bit(0.0f), 0);
  EXPECT_EQ(quantize_unit_to_8bit(1.0f / 255.0f), 1);
  EXPECT_EQ(quantize_unit_to_8bit(0.49f / 255.0f), 0);
  EXPECT_EQ(quantize_unit_to_8bit(0.51f / 255.0f), 1);
  EXPECT_EQ(quantize_unit_to_8bit(254.6f / 255.0f), 255);
  EXPECT_EQ(quantize_unit_to_8bit(std::numeric_limits<float>::infinity()), 255);
  EXPECT_EQ(quantize_unit_to_8bit(-std::numeric_limits<float>::infinity()), 0);
}

class ColorConfigFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("darc_color_config_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A config whose only view is the identity, so 0.18 stays 0.18 (46 in 8 bits), telling it
  // apart from the built-in sRGB one (118).
  std::string write_identity_config() {
    const fs::path path = dir_ / "identity.ocio";
    std::ofstream(path) << "ocio_profile_version: 2\n"
                           "roles:\n"
                           "  default: linear\n"
                           "  scene_linear: linear\n"
                           "file_rules:\n"
                           "  - !<Rule> {name: Default, colorspace: default}\n"
                           "displays:\n"
                           "  Passthrough:\n"
                           "    - !<View> {name: Raw, colorspace: linear}\n"
                           "colorspaces:\n"
                           "  - !<ColorSpace>\n"
                           "    name: linear\n";
    return path.string();
  }

  fs::path dir_;
};

TEST_F(ColorConfigFile, LookupOrderIsExplicitThenEnvThenBuiltin) {
  const std::string identity = write_identity_config();
  const std::string missing = (dir_ / "missing.ocio").string();

  auto builtin = find_color_config("", "");
  ASSERT_TRUE(builtin.config) << builtin.error;
  EXPECT_EQ(builtin.config->source(), ColorConfig::kBuiltinSource);

  auto from_env = find_color_config("", identity);
  ASSERT_TRUE(from_env.config) << from_env.error;
  EXPECT_EQ(from_env.config->source(), identity);
  EXPECT_EQ(from_env.config->display(), "Passthrough");
  EXPECT_EQ(from_env.config->display_colorspace_tag(), "Passthrough");
  EXPECT_EQ(from_env.config->to_display_8bit(std::vector<float>{0.18f, 0.18f, 0.18f}, 3)[0], 46);

  auto explicit_wins = find_color_config(identity, missing);
  ASSERT_TRUE(explicit_wins.config) << explicit_wins.error;
  EXPECT_EQ(explicit_wins.config->source(), identity);
}

TEST_F(ColorConfigFile, UnreadableConfigIsAnErrorNamingThePath) {
  const std::string missing = (dir_ / "missing.ocio").string();
  auto explicit_missing = find_color_config(missing, "");
  EXPECT_FALSE(explicit_missing.config);
  EXPECT_NE(explicit_missing.error.find(missing), std::string::npos);

  auto env_missing = find_color_config("", missing);
  EXPECT_FALSE(env_missing.config);
  EXPECT_NE(env_missing.error.find("$OCIO"), std::string::npos);

  const fs::path garbage = dir_ / "garbage.ocio";
  std::ofstream(garbage) << "this: is: not [ an ocio config\n";
  std::string error;
  EXPECT_FALSE(ColorConfig::from_file(garbage.string(), error));
  EXPECT_FALSE(error.empty());
}

TEST_F(ColorConfigFile, UnknownDisplayIsAnError) {
  std::string error;
  EXPECT_FALSE(ColorConfig::from_file(write_identity_config(), error, "NoSuchDisplay", "Raw"));
  EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace darc
