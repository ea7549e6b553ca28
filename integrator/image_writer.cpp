#include "integrator/image_writer.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <filesystem>
#include <string_view>
#include <system_error>

namespace darc {

namespace fs = std::filesystem;

namespace {

// Default compression per format: zip is lossless and the usual EXR choice for renders; lzw is
// what RIB files ask for TIFF ("string compression" "lzw").
constexpr const char* kExrDefaultCompression = "zip";
constexpr const char* kTiffDefaultCompression = "lzw";
// How many temporary names to try before giving up (another process may hold the first ones).
constexpr int kMaxTemporaryNameAttempts = 1000;

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool is_8bit(ImageFormat f) { return f != ImageFormat::Exr; }

bool has_channel(const std::vector<std::string>& names, const char* name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// Pixels ready for OIIO: float values of the chosen channels, non-finite values replaced.
struct PixelBuffer {
  std::vector<float> values;
  std::int64_t nonfinite = 0;
};

// The chosen channels over `rect` (raster pixels), zero outside the image's data window.
PixelBuffer gather(const Image& image, const std::vector<int>& channel_indices, const PixelRect& rect) {
  PixelBuffer buf;
  const std::size_t nc = channel_indices.size();
  buf.values.assign(static_cast<std::size_t>(rect.width()) * rect.height() * nc, 0.0f);
  std::size_t i = 0;
  for (int y = rect.y0; y < rect.y1; ++y) {
    for (int x = rect.x0; x < rect.x1; ++x) {
      for (int c : channel_indices) {
        const float v = image.at(x, y, c);
        if (std::isfinite(v)) {
          buf.values[i] = v;
        } else {
          ++buf.nonfinite;
        }
        ++i;
      }
    }
  }
  return buf;
}

// PNG stores straight (unassociated) alpha. Dividing by alpha must happen on linear values,
// before the display curve: OIIO would otherwise divide the display-encoded 8-bit values, which
// brightens soft edges (encode(c a) / a > encode(c)) - visible on every hair strand.
// Pixels with alpha 0 keep their RGB (additive, e.g. glows).
void unpremultiply(std::vector<float>& rgba) {
  for (std::size_t i = 0; i + 3 < rgba.size(); i += 4) {
    const float a = rgba[i + 3];
    if (a > 0.0f) {
      for (int c = 0; c < 3; ++c) rgba[i + c] /= a;
    }
  }
}

// The ImageDescription line that carries the error count in formats without custom attributes.
const std::string kErrorCountDescriptionKey = std::string(kErrorCountAttribute) + "=";

// The frame's errors, in the form each format can hold (ImageMetadata::error_count).
void add_error_record(OIIO::ImageSpec& spec, const ImageMetadata& m, ImageFormat format) {
  if (m.error_count <= 0) return;
  switch (format) {
    case ImageFormat::Exr:  // typed attributes; EXR's int is 32-bit
      spec.attribute(kErrorCountAttribute, static_cast<int>(std::min<std::int64_t>(m.error_count, INT_MAX)));
      spec.attribute(kFirstErrorAttribute, m.first_error);
      break;
    case ImageFormat::Png:  // OIIO writes string attributes as text chunks and drops the others
      spec.attribute(kErrorCountAttribute, std::to_string(m.error_count));
      spec.attribute(kFirstErrorAttribute, m.first_error);
      break;
    case ImageFormat::Tiff:
    case ImageFormat::Jpeg:  // OIIO writes only standard tags for these
      spec.attribute("ImageDescription", kErrorCountDescriptionKey + std::to_string(m.error_count) + "\n" +
                                             kFirstErrorAttribute + "=" + m.first_error);
      break;
  }
}

void add_metadata(OIIO::ImageSpec& spec, const ImageMetadata& m, ImageFormat format) {
  if (!m.software.empty()) spec.attribute("Software", m.software);
  if (!m.hider.empty()) spec.attribute("darc:hider", m.hider);
  if (m.samples_per_pixel > 0) spec.attribute("darc:spp", m.samples_per_pixel);
  if (m.render_seconds >= 0.0f) spec.attribute("renderTime", m.render_seconds);
  add_error_record(spec, m, format);
  for (const auto& a : m.extra) {
    std::visit([&](const auto& v) { spec.attribute(a.name, v); }, a.value);
  }
}

// A whole decimal integer, or nullopt.
std::optional<std::int64_t> parse_count(std::string_view text) {
  std::int64_t value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::string temporary_path(const fs::path& target, int attempt) {
  const std::string name = target.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                           std::to_string(attempt) + target.extension().string();
  return (target.parent_path() / name).string();
}

// A temporary file name that does not exist yet, or "" if none was found.
std::string free_temporary_path(const fs::path& target) {
  for (int n = 0; n < kMaxTemporaryNameAttempts; ++n) {
    std::string candidate = temporary_path(target, n);
    std::error_code ec;
    if (!fs::exists(candidate, ec) && !ec) return candidate;
  }
  return {};
}

void remove_quietly(const std::string& path) {
  std::error_code ec;
  fs::remove(path, ec);  // best effort: the file may never have been created
}

// Writes spec + pixels to `temp` with OIIO; returns an error message or "".
std::string write_with_oiio(const std::string& temp, const OIIO::ImageSpec& spec, OIIO::TypeDesc buffer_type,
                            const void* pixels) {
  auto out = OIIO::ImageOutput::create(temp);
  if (!out) return "no writer for this format: " + OIIO::geterror();
  if (!out->open(temp, spec)) return out->geterror();
  const bool wrote = out->write_image(buffer_type, pixels);
  std::string error = wrote ? std::string() : out->geterror();
  if (!out->close() && error.empty()) error = out->geterror();
  if (error.empty() && !wrote) error = "write failed";
  return error;
}

}  // namespace

std::optional<ImageFormat> image_format_for_path(const std::string& path) {
  const std::string ext = lowercase(fs::path(path).extension().string());
  if (ext == ".exr") return ImageFormat::Exr;
  if (ext == ".tif" || ext == ".tiff") return ImageFormat::Tiff;
  if (ext == ".png") return ImageFormat::Png;
  if (ext == ".jpg" || ext == ".jpeg") return ImageFormat::Jpeg;
  return std::nullopt;
}

std::optional<std::vector<std::string>> channels_for_display_mode(const std::string& mode) {
  if (mode == "rgb") return std::vector<std::string>{"R", "G", "B"};
  if (mode == "rgba") return std::vector<std::string>{"R", "G", "B", "A"};
  if (mode == "z") return std::vector<std::string>{"Z"};
  if (mode == "rgbz") return std::vector<std::string>{"R", "G", "B", "Z"};
  if (mode == "rgbaz") return std::vector<std::string>{"R", "G", "B", "A", "Z"};
  return std::nullopt;
}

WriteResult write_image(const std::string& path, const Image& image, const ImageMetadata& metadata,
                        const ColorConfig& config, const std::string& mode) {
  WriteResult result;
  auto fail = [&](const std::string& why) {
    result.ok = false;
    result.error = path + ": " + why;
    return result;
  };

  const auto format = image_format_for_path(path);
  if (!format) return fail("unknown image format (use .exr, .tif, .tiff, .png or .jpg)");
  auto channels = channels_for_display_mode(mode);
  if (!channels) return fail("unsupported display mode \"" + mode + "\" (use rgb, rgba, z, rgbz or rgbaz)");
  const bool wants_z = has_channel(*channels, "Z");
  if (is_8bit(*format) && wants_z && !(mode == "z" && *format == ImageFormat::Tiff)) {
    return fail("display mode \"" + mode + "\" needs depth, which this 8-bit format cannot hold (use .exr)");
  }
  if (*format == ImageFormat::Jpeg && has_channel(*channels, "A")) {
    channels->pop_back();  // "A" is last in "rgba"
    result.warnings.push_back(path + ": JPEG has no alpha channel; alpha dropped");
  }

  const PixelRect& dw = image.data_window;
  const std::size_t expected = static_cast<std::size_t>(dw.width()) * dw.height() * image.channels();
  if (image.width <= 0 || image.height <= 0 || dw.empty() || image.pixels.size() != expected ||
      intersect(dw, PixelRect{0, 0, image.width, image.height}) != dw) {
    return fail("empty or inconsistent image (size, data window and pixel count disagree)");
  }
  std::vector<int> indices;
  for (const auto& name : *channels) {
    const int c = image.channel_index(name);
    if (c < 0) return fail("the image has no " + name + " channel for display mode \"" + mode + "\"");
    indices.push_back(c);
  }
  const int nc = static_cast<int>(indices.size());

  OIIO::ImageSpec spec;
  PixelBuffer buffer;
  std::vector<std::uint8_t> display_pixels;
  OIIO::TypeDesc buffer_type = OIIO::TypeDesc::FLOAT;
  const void* data = nullptr;
  if (*format == ImageFormat::Exr) {
    buffer = gather(image, indices, dw);
    spec = OIIO::ImageSpec(dw.width(), dw.height(), nc, OIIO::TypeDesc::HALF);
    spec.x = dw.x0;
    spec.y = dw.y0;
    spec.full_x = 0;
    spec.full_y = 0;
    spec.full_width = image.width;
    spec.full_height = image.height;
    spec.channelnames = *channels;
    spec.alpha_channel = -1;
    for (int i = 0; i < nc; ++i) {
      if ((*channels)[i] == "A") spec.alpha_channel = i;
      if ((*channels)[i] == "Z") spec.z_channel = i;
    }
    if (wants_z) {
      spec.channelformats.assign(nc, OIIO::TypeDesc::HALF);
      spec.channelformats[spec.z_channel] = OIIO::TypeDesc::FLOAT;
    }
    spec.attribute("compression", metadata.compression.empty() ? kExrDefaultCompression : metadata.compression);
    spec.attribute("oiio:ColorSpace", "Linear");
    data = buffer.values.data();
  } else {
    const PixelRect full{0, 0, image.width, image.height};
    buffer = gather(image, indices, full);
    if (wants_z) {  // a linear float depth TIFF
      spec = OIIO::ImageSpec(image.width, image.height, 1, OIIO::TypeDesc::FLOAT);
      spec.channelnames = {"Z"};
      spec.alpha_channel = -1;
      spec.z_channel = 0;
      data = buffer.values.data();
    } else {
      const bool straight_alpha = *format == ImageFormat::Png && nc == 4;
      if (straight_alpha) unpremultiply(buffer.values);
      display_pixels = config.to_display_8bit(buffer.values, nc);
      // Tells OIIO the values are already unassociated, so it writes them untouched.
      spec = OIIO::ImageSpec(image.width, image.height, nc, OIIO::TypeDesc::UINT8);
      if (straight_alpha) spec.attribute("oiio:UnassociatedAlpha", 1);
      spec.channelnames = *channels;
      spec.alpha_channel = nc == 4 ? 3 : -1;
      spec.attribute("oiio:ColorSpace", config.display_colorspace_tag());
      buffer_type = OIIO::TypeDesc::UINT8;
      data = display_pixels.data();
    }
    if (*format == ImageFormat::Tiff) {
      spec.attribute("compression", metadata.compression.empty() ? kTiffDefaultCompression : metadata.compression);
    }
  }
  add_metadata(spec, metadata, *format);
  result.nonfinite_replaced = buffer.nonfinite;

  const std::string temp = free_temporary_path(fs::path(path));
  if (temp.empty()) return fail("no free temporary file name next to it");
  const std::string error = write_with_oiio(temp, spec, buffer_type, data);
  if (!error.empty()) {
    remove_quietly(temp);
    return fail(error);
  }
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) {
    remove_quietly(temp);
    return fail("cannot rename the temporary file into place: " + ec.message());
  }
  result.ok = true;
  return result;
}

std::optional<std::int64_t> read_recorded_error_count(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return std::nullopt;
  const OIIO::ImageSpec& spec = in->spec();
  if (const OIIO::ParamValue* p = spec.find_attribute(kErrorCountAttribute)) {
    if (p->type() == OIIO::TypeInt) return p->get_int();
    if (p->type() == OIIO::TypeString) return parse_count(p->get_string()).value_or(0);
  }
  const std::string description = spec.get_string_attribute("ImageDescription");
  if (description.rfind(kErrorCountDescriptionKey, 0) == 0) {
    const size_t begin = kErrorCountDescriptionKey.size();
    const size_t end = std::min(description.find('\n', begin), description.size());
    return parse_count(std::string_view(description).substr(begin, end - begin)).value_or(0);
  }
  return 0;
}

}  // namespace darc
