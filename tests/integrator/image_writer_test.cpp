#include "integrator/image_writer.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

namespace darc {
namespace {

namespace fs = std::filesystem;

// A film-like image: channels R, G, B, A, Z over the data window.
Image make_image(int width, int height, PixelRect data_window) {
  Image image;
  image.width = width;
  image.height = height;
  image.data_window = data_window;
  image.channel_names = {"R", "G", "B", "A", "Z"};
  image.pixels.assign(static_cast<std::size_t>(data_window.width()) * data_window.height() * 5, 0.0f);
  return image;
}

void set_pixel(Image& image, int x, int y, std::array<float, 5> v) {
  const PixelRect& dw = image.data_window;
  const std::size_t base = (static_cast<std::size_t>(y - dw.y0) * dw.width() + (x - dw.x0)) * 5;
  for (int c = 0; c < 5; ++c) image.pixels[base + c] = v[c];
}

// Distinct, partly > 1 values for pixel (x, y), channel c.
float pattern(int x, int y, int c) { return 0.05f * static_cast<float>(x + 3 * y) + 0.7f * static_cast<float>(c); }

// Everything read back from a file.
struct ReadBack {
  OIIO::ImageSpec spec;
  std::vector<float> pixels;  // data window, all channels, as float
};

std::optional<ReadBack> read_back(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return std::nullopt;
  ReadBack r;
  r.spec = in->spec();
  r.pixels.resize(static_cast<std::size_t>(r.spec.width) * r.spec.height * r.spec.nchannels);
  if (!in->read_image(0, 0, 0, r.spec.nchannels, OIIO::TypeDesc::FLOAT, r.pixels.data())) return std::nullopt;
  return r;
}

class ImageWriter : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("darc_image_writer_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    return names;
  }

  fs::path dir_;
  ColorConfig config_ = ColorConfig::builtin();
};

TEST_F(ImageWriter, FormatFromExtension) {
  EXPECT_EQ(image_format_for_path("a/b.exr"), ImageFormat::Exr);
  EXPECT_EQ(image_format_for_path("b.EXR"), ImageFormat::Exr);
  EXPECT_EQ(image_format_for_path("frame.0007.tif"), ImageFormat::Tiff);
  EXPECT_EQ(image_format_for_path("x.tiff"), ImageFormat::Tiff);
  EXPECT_EQ(image_format_for_path("x.png"), ImageFormat::Png);
  EXPECT_EQ(image_format_for_path("x.jpg"), ImageFormat::Jpeg);
  EXPECT_FALSE(image_format_for_path("x.bmp"));
  EXPECT_FALSE(image_format_for_path("noextension"));
}

TEST_F(ImageWriter, ExrRoundTripKeepsValuesMetadataAndCropDataWindow) {
  const PixelRect crop{2, 1, 7, 5};
  Image image = make_image(9, 6, crop);
  for (int y = crop.y0; y < crop.y1; ++y) {
    for (int x = crop.x0; x < crop.x1; ++x) {
      set_pixel(image, x, y, {pattern(x, y, 0), pattern(x, y, 1), pattern(x, y, 2), 0.5f, 1234.567f + x});
    }
  }
  ImageMetadata meta;
  meta.software = "darc 0.1.0";
  meta.hider = "distance";
  meta.samples_per_pixel = 16;
  meta.render_seconds = 12.5f;
  meta.extra = {{"darc:scene", std::string("grass.rib")}, {"darc:frame", 7}, {"darc:gain", 1.5f}};

  const std::string out = path("beauty.exr");
  const WriteResult result = write_image(out, image, meta, config_, "rgbaz");
  ASSERT_TRUE(result.ok) << result.error;
  EXPECT_EQ(result.nonfinite_replaced, 0);

  const auto back = read_back(out);
  ASSERT_TRUE(back);
  const OIIO::ImageSpec& spec = back->spec;
  EXPECT_EQ(spec.x, 2);
  EXPECT_EQ(spec.y, 1);
  EXPECT_EQ(spec.width, 5);
  EXPECT_EQ(spec.height, 4);
  EXPECT_EQ(spec.full_x, 0);
  EXPECT_EQ(spec.full_y, 0);
  EXPECT_EQ(spec.full_width, 9);
  EXPECT_EQ(spec.full_height, 6);
  ASSERT_EQ(spec.nchannels, 5);
  EXPECT_EQ(spec.channelnames, (std::vector<std::string>{"R", "G", "B", "A", "Z"}));
  EXPECT_EQ(spec.channelformat(0), OIIO::TypeDesc::HALF);
  EXPECT_EQ(spec.channelformat(4), OIIO::TypeDesc::FLOAT);
  EXPECT_EQ(spec.get_string_attribute("compression"), "zip");
  EXPECT_EQ(spec.get_string_attribute("Software"), "darc 0.1.0");
  EXPECT_EQ(spec.get_string_attribute("darc:hider"), "distance");
  EXPECT_EQ(spec.get_int_attribute("darc:spp"), 16);
  EXPECT_FLOAT_EQ(spec.get_float_attribute("renderTime"), 12.5f);
  EXPECT_EQ(spec.get_string_attribute("darc:scene"), "grass.rib");
  EXPECT_EQ(spec.get_int_attribute("darc:frame"), 7);
  EXPECT_FLOAT_EQ(spec.get_float_attribute("darc:gain"), 1.5f);

  // Half keeps 11 significant bits: relative error <= 2^-11.
  const float half_relative = 1.0f / 2048.0f;
  for (int y = crop.y0; y < crop.y1; ++y) {
    for (int x = crop.x0; x < crop.x1; ++x) {
      const float* p = &back->pixels[((y - crop.y0) * crop.width() + (x - crop.x0)) * 5];
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], pattern(x, y, c), half_relative * pattern(x, y, c) + 1e-7f);
      EXPECT_EQ(p[3], 0.5f);
      EXPECT_EQ(p[4], 1234.567f + x);  // Z is float: exact
    }
  }
}

TEST_F(ImageWriter, ExrModeSelectsChannels) {
  Image image = make_image(2, 2, PixelRect{0, 0, 2, 2});
  set_pixel(image, 1, 1, {0.25f, 0.5f, 0.75f, 1.0f, 3.0f});
  ASSERT_TRUE(write_image(path("rgb.exr"), image, {}, config_, "rgb").ok);
  ASSERT_TRUE(write_image(path("z.exr"), image, {}, config_, "z").ok);
  const auto rgb = read_back(path("rgb.exr"));
  const auto z = read_back(path("z.exr"));
  ASSERT_TRUE(rgb && z);
  EXPECT_EQ(rgb->spec.channelnames, (std::vector<std::string>{"R", "G", "B"}));
  EXPECT_EQ(rgb->pixels[9 + 2], 0.75f);
  EXPECT_EQ(z->spec.channelnames, (std::vector<std::string>{"Z"}));
  EXPECT_EQ(z->pixels[3], 3.0f);
}

TEST_F(ImageWriter, PngOfLinearValuesReadsBackSrgbCodes) {
  Image image = make_image(4, 1, PixelRect{0, 0, 4, 1});
  set_pixel(image, 0, 0, {0.18f, 0.18f, 0.18f, 1.0f, 0.0f});
  set_pixel(image, 1, 0, {1.0f, 1.0f, 1.0f, 1.0f, 0.0f});
  set_pixel(image, 2, 0, {0.0f, 0.0f, 0.0f, 0.0f, 0.0f});
  set_pixel(image, 3, 0, {0.0f, 0.09f, 0.0f, 0.5f, 0.0f});
  const std::string out = path("grey.png");
  const WriteResult result = write_image(out, image, {}, config_, "rgba");
  ASSERT_TRUE(result.ok) << result.error;

  auto in = OIIO::ImageInput::open(out);
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::UINT8);
  EXPECT_EQ(in->spec().nchannels, 4);
  EXPECT_EQ(in->spec().get_string_attribute("oiio:ColorSpace"), "sRGB");
  std::vector<std::uint8_t> px(4 * 4);
  ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, px.data()));
  EXPECT_EQ(px[0], 118);
  EXPECT_EQ(px[1], 118);
  EXPECT_EQ(px[3], 255);
  EXPECT_EQ(px[4], 255);
  EXPECT_EQ(px[8], 0);
  EXPECT_EQ(px[11], 0);
  EXPECT_NEAR(px[13], 118 / 2, 1);  // OIIO re-premultiplies the stored straight 118 on read
  EXPECT_EQ(px[15], 128);           // alpha passes through linearly: 0.5 -> 128
}

TEST_F(ImageWriter, PngStoresStraightAlphaUnpremultipliedInLinear) {
  Image image = make_image(1, 1, PixelRect{0, 0, 1, 1});
  set_pixel(image, 0, 0, {0.09f, 0.0f, 0.5f, 0.5f, 0.0f});  // premultiplied: straight (0.18, 0, 1)
  const std::string out = path("edge.png");
  ASSERT_TRUE(write_image(out, image, {}, config_, "rgba").ok);
  OIIO::ImageSpec hint;
  hint.attribute("oiio:UnassociatedAlpha", 1);  // read the stored values, not re-premultiplied
  auto in = OIIO::ImageInput::open(out, &hint);
  ASSERT_TRUE(in);
  std::vector<std::uint8_t> px(4);
  ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, px.data()));
  EXPECT_EQ(px[0], 118);  // sRGB of linear 0.18
  EXPECT_EQ(px[1], 0);
  EXPECT_EQ(px[2], 255);
  EXPECT_EQ(px[3], 128);
}

TEST_F(ImageWriter, TiffKeepsPremultipliedRgb) {
  Image image = make_image(1, 1, PixelRect{0, 0, 1, 1});
  set_pixel(image, 0, 0, {0.18f, 0.18f, 0.18f, 0.5f, 0.0f});
  const std::string out = path("edge.tif");
  ASSERT_TRUE(write_image(out, image, {}, config_, "rgba").ok);
  auto in = OIIO::ImageInput::open(out);
  ASSERT_TRUE(in);
  std::vector<std::uint8_t> px(4);
  ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, px.data()));
  EXPECT_EQ(px[0], 118);
  EXPECT_EQ(px[3], 128);
}

TEST_F(ImageWriter, EightBitFormatsWriteTheFullImageZeroOutsideTheCrop) {
  Image image = make_image(5, 4, PixelRect{1, 1, 3, 2});
  set_pixel(image, 1, 1, {1, 1, 1, 1, 0});
  set_pixel(image, 2, 1, {1, 1, 1, 1, 0});
  const std::string out = path("crop.tif");
  ASSERT_TRUE(write_image(out, image, {}, config_, "rgb").ok);
  const auto back = read_back(out);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->spec.width, 5);
  EXPECT_EQ(back->spec.height, 4);
  EXPECT_EQ(back->spec.nchannels, 3);
  EXPECT_EQ(back->spec.get_string_attribute("compression"), "lzw");
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 5; ++x) {
      const bool inside = y == 1 && (x == 1 || x == 2);
      EXPECT_EQ(back->pixels[(y * 5 + x) * 3], inside ? 1.0f : 0.0f) << x << "," << y;
    }
  }
}

TEST_F(ImageWriter, DepthGoesToFloatTiffButNotToPng) {
  Image image = make_image(2, 1, PixelRect{0, 0, 2, 1});
  set_pixel(image, 0, 0, {0, 0, 0, 0, 42.25f});
  set_pixel(image, 1, 0, {0, 0, 0, 0, kNoHitDepth});
  ASSERT_TRUE(write_image(path("depth.tif"), image, {}, config_, "z").ok);
  const auto back = read_back(path("depth.tif"));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->spec.format, OIIO::TypeDesc::FLOAT);
  EXPECT_EQ(back->pixels[0], 42.25f);
  EXPECT_EQ(back->pixels[1], kNoHitDepth);

  const WriteResult png = write_image(path("depth.png"), image, {}, config_, "z");
  EXPECT_FALSE(png.ok);
  EXPECT_NE(png.error.find("depth.png"), std::string::npos);
  const WriteResult rgbz = write_image(path("beauty.tif"), image, {}, config_, "rgbz");
  EXPECT_FALSE(rgbz.ok);
  EXPECT_EQ(files(), std::vector<std::string>{"depth.tif"});
}

TEST_F(ImageWriter, JpegDropsAlphaWithAWarning) {
  Image image = make_image(2, 2, PixelRect{0, 0, 2, 2});
  const WriteResult result = write_image(path("x.jpg"), image, {}, config_, "rgba");
  ASSERT_TRUE(result.ok) << result.error;
  EXPECT_EQ(result.warnings.size(), 1u);
  const auto back = read_back(path("x.jpg"));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->spec.nchannels, 3);
}

TEST_F(ImageWriter, MissingDirectoryIsAnErrorAndLeavesNoFile) {
  Image image = make_image(2, 2, PixelRect{0, 0, 2, 2});
  for (const char* name : {"nodir/out.exr", "nodir/out.png"}) {
    const WriteResult result = write_image(path(name), image, {}, config_, "rgba");
    EXPECT_FALSE(result.ok);
    EXPECT_FALSE(result.error.empty());
  }
  EXPECT_TRUE(files().empty());
}

TEST_F(ImageWriter, BadNameOrModeIsAnErrorAndLeavesNoFile) {
  Image image = make_image(2, 2, PixelRect{0, 0, 2, 2});
  EXPECT_FALSE(write_image(path("out.bmp"), image, {}, config_, "rgb").ok);
  EXPECT_FALSE(write_image(path("out"), image, {}, config_, "rgb").ok);
  EXPECT_FALSE(write_image(path("out.exr"), image, {}, config_, "cmyk").ok);
  Image no_z = image;
  no_z.channel_names = {"R", "G", "B", "A", "Y"};
  EXPECT_FALSE(write_image(path("out.exr"), no_z, {}, config_, "rgbaz").ok);
  Image inconsistent = image;
  inconsistent.pixels.pop_back();
  EXPECT_FALSE(write_image(path("out.exr"), inconsistent, {}, config_, "rgb").ok);
  EXPECT_TRUE(files().empty());
}

TEST_F(ImageWriter, SuccessLeavesOnlyTheFinalFileAndReplacesAnOldOne) {
  Image image = make_image(3, 3, PixelRect{0, 0, 3, 3});
  std::ofstream(path("frame.0007.exr")) << "stale";
  for (const char* name : {"frame.0007.exr", "frame.0007.png", "frame.0007.tif"}) {
    const WriteResult result = write_image(path(name), image, {}, config_, "rgba");
    ASSERT_TRUE(result.ok) << result.error;
  }
  auto names = files();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"frame.0007.exr", "frame.0007.png", "frame.0007.tif"}));
  EXPECT_TRUE(read_back(path("frame.0007.exr")));
}

TEST_F(ImageWriter, NonFiniteValuesAreWrittenAsZeroAndCounted) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  Image image = make_image(2, 1, PixelRect{0, 0, 2, 1});
  set_pixel(image, 0, 0, {nan, 0.5f, inf, 1.0f, -inf});
  set_pixel(image, 1, 0, {0.25f, 0.25f, 0.25f, nan, 1.0f});
  const WriteResult exr = write_image(path("nan.exr"), image, {}, config_, "rgbaz");
  ASSERT_TRUE(exr.ok) << exr.error;
  EXPECT_EQ(exr.nonfinite_replaced, 4);
  const auto back = read_back(path("nan.exr"));
  ASSERT_TRUE(back);
  for (float v : back->pixels) EXPECT_TRUE(std::isfinite(v));
  EXPECT_EQ(back->pixels[0], 0.0f);
  EXPECT_EQ(back->pixels[1], 0.5f);
  EXPECT_EQ(back->pixels[2], 0.0f);
  EXPECT_EQ(back->pixels[4], 0.0f);
  EXPECT_EQ(back->pixels[8], 0.0f);

  const WriteResult png = write_image(path("nan.png"), image, {}, config_, "rgba");
  ASSERT_TRUE(png.ok) << png.error;
  EXPECT_EQ(png.nonfinite_replaced, 3);
  const auto png_back = read_back(path("nan.png"));
  ASSERT_TRUE(png_back);
  EXPECT_EQ(png_back->pixels[0], 0.0f);
  EXPECT_EQ(png_back->pixels[2], 0.0f);
  EXPECT_EQ(png_back->pixels[7], 0.0f);
}

// A frame's errors are recorded in every format: typed in EXR, as text in PNG, in the
// ImageDescription of TIFF and JPEG (OIIO writes no custom attributes there); all read back.
TEST_F(ImageWriter, ErrorsAreRecordedInEveryFormatAndReadBack) {
  Image image = make_image(2, 2, PixelRect{0, 0, 2, 2});
  ImageMetadata meta;
  meta.error_count = 3;
  meta.first_error = "scene.rib:12:3: error: Basis: unknown basis \"bsline\"";
  for (const char* name : {"e.exr", "e.png", "e.tif", "e.jpg"}) {
    SCOPED_TRACE(name);
    const WriteResult result = write_image(path(name), image, meta, config_, "rgba");
    ASSERT_TRUE(result.ok) << result.error;
    EXPECT_EQ(read_recorded_error_count(path(name)), 3);
  }
  const OIIO::ImageSpec exr = read_back(path("e.exr"))->spec;
  const OIIO::ParamValue* count = exr.find_attribute(kErrorCountAttribute);
  ASSERT_NE(count, nullptr);
  EXPECT_EQ(count->type(), OIIO::TypeInt);
  EXPECT_EQ(exr.get_int_attribute(kErrorCountAttribute), 3);
  EXPECT_EQ(exr.get_string_attribute(kFirstErrorAttribute), meta.first_error);
  const OIIO::ImageSpec png = read_back(path("e.png"))->spec;
  EXPECT_EQ(png.get_string_attribute(kErrorCountAttribute), "3");
  EXPECT_EQ(png.get_string_attribute(kFirstErrorAttribute), meta.first_error);
  for (const char* name : {"e.tif", "e.jpg"}) {
    EXPECT_EQ(read_back(path(name))->spec.get_string_attribute("ImageDescription"),
              "darc:errors=3\ndarc:first_error=" + meta.first_error)
        << name;
  }
}

TEST_F(ImageWriter, FramesWithoutErrorsRecordNone) {
  Image image = make_image(2, 2, PixelRect{0, 0, 2, 2});
  for (const char* name : {"c.exr", "c.png", "c.tif", "c.jpg"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(write_image(path(name), image, {}, config_, "rgba").ok);
    const OIIO::ImageSpec spec = read_back(path(name))->spec;
    EXPECT_EQ(spec.find_attribute(kErrorCountAttribute), nullptr);
    EXPECT_EQ(spec.find_attribute(kFirstErrorAttribute), nullptr);
    EXPECT_EQ(spec.get_string_attribute("ImageDescription"), "");
    EXPECT_EQ(read_recorded_error_count(path(name)), 0);
  }
  EXPECT_EQ(read_recorded_error_count(path("missing.exr")), std::nullopt);
}

}  // namespace
}  // namespace darc
