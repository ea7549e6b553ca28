#include "bench/reference_cache.h"

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <filesystem>
#include <system_error>
#include <vector>

namespace darc::bench {

namespace {

// Bumped when the reference's meaning changes in a way the key would not see (e.g. what is
// stored), so that old cache entries are not reused.
constexpr const char* kReferenceFormat = "darc speed-vs-error reference v1";
constexpr const char* kKeyAttribute = "darc:reference_key";
constexpr int kRgbaChannels = 4;

}  // namespace

uint64_t fnv1a64(std::string_view bytes) {
  constexpr uint64_t kOffsetBasis = 0xcbf29ce484222325ull;
  constexpr uint64_t kPrime = 0x100000001b3ull;
  uint64_t h = kOffsetBasis;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= kPrime;
  }
  return h;
}

std::string reference_cache_key(std::string_view scene_text, int xres, int yres, const ReferenceSettings& settings) {
  char header[160];
  std::snprintf(header, sizeof header, "%s\nstochastic %dx%d seed %u\nresolution %dx%d\n", kReferenceFormat,
                settings.samples_per_axis, settings.samples_per_axis, unsigned(settings.seed), xres, yres);
  std::string text = header;
  if (settings.contribution_threshold != kDefaultContributionThreshold) {
    std::snprintf(header, sizeof header, "contribution threshold %.9g\n", double(settings.contribution_threshold));
    text += header;
  }
  text += scene_text;
  char key[17];
  std::snprintf(key, sizeof key, "%016llx", static_cast<unsigned long long>(fnv1a64(text)));
  return key;
}

std::string reference_cache_path(const std::string& dir, const std::string& scene_name, const std::string& key) {
  return (std::filesystem::path(dir) / (scene_name + "-" + key + ".exr")).string();
}

std::optional<Image> load_cached_reference(const std::string& path, const std::string& key, int xres, int yres) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return std::nullopt;
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    (void)OIIO::geterror();  // clear the message: a broken cache file is only a miss
    return std::nullopt;
  }
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width != xres || spec.height != yres || spec.x != 0 || spec.y != 0 || spec.nchannels != kRgbaChannels ||
      spec.get_string_attribute(kKeyAttribute) != key)
    return std::nullopt;
  Image image;
  image.width = xres;
  image.height = yres;
  image.data_window = {0, 0, xres, yres};
  image.channel_names = {"R", "G", "B", "A"};
  image.pixels.resize(size_t(xres) * size_t(yres) * kRgbaChannels);
  if (!in->read_image(0, 0, 0, kRgbaChannels, OIIO::TypeDesc::FLOAT, image.pixels.data())) return std::nullopt;
  return image;
}

std::string store_cached_reference(const std::string& path, const Image& image, const std::string& key) {
  std::vector<float> rgba(size_t(image.width) * size_t(image.height) * kRgbaChannels);
  const char* names[kRgbaChannels] = {"R", "G", "B", "A"};
  for (int c = 0; c < kRgbaChannels; ++c) {
    int ic = image.channel_index(names[c]);
    if (ic < 0) return std::string("the reference has no channel ") + names[c];
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        rgba[(size_t(y) * size_t(image.width) + size_t(x)) * kRgbaChannels + size_t(c)] = image.at(x, y, ic);
  }
  std::filesystem::path target(path);
  std::error_code ec;
  std::filesystem::create_directories(target.parent_path(), ec);
  std::filesystem::path temp = target;
  temp.replace_filename(target.stem().string() + ".tmp.exr");
  OIIO::ImageSpec spec(image.width, image.height, kRgbaChannels, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"R", "G", "B", "A"};
  spec.alpha_channel = 3;
  spec.attribute(kKeyAttribute, key);
  spec.attribute("compression", "zip");
  auto out = OIIO::ImageOutput::create(temp.string());
  if (!out) return "cannot create " + temp.string() + ": " + OIIO::geterror();
  if (!out->open(temp.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, rgba.data()) || !out->close())
    return "cannot write " + temp.string() + ": " + out->geterror();
  std::filesystem::rename(temp, target, ec);
  if (ec) return "cannot rename " + temp.string() + ": " + ec.message();
  return "";
}

}  // namespace darc::bench
