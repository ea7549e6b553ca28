// Writes a resolved film Image to disk through OpenImageIO, atomically.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "integrator/color_config.h"
#include "integrator/film.h"

namespace darc {

// The header attributes that record a frame's scene errors. --skip-existing and the regression
// runner (scripts/darc-regress) read them back: keep the names.
inline constexpr const char* kErrorCountAttribute = "darc:errors";       // int: how many
inline constexpr const char* kFirstErrorAttribute = "darc:first_error";  // "file:line:col: error: ..."

// What is recorded in the file header, and how the file is stored.
struct ImageMetadata {
  // One extra header attribute; ints and floats keep their type in EXR.
  struct Attribute {
    std::string name;
    std::variant<std::string, int, float> value;
  };

  std::string software = "darc";  // "Software"; the caller appends the version, e.g. "darc 0.1.0"
  std::string hider;              // "darc:hider"; empty = not written
  int samples_per_pixel = 0;      // "darc:spp"; <= 0 = not written
  float render_seconds = -1.0f;   // "renderTime" in seconds; < 0 = not written
  // The errors attributed to the frame (kErrorCountAttribute, kFirstErrorAttribute), written
  // only when error_count > 0: a frame without errors has neither attribute. EXR keeps them
  // typed (int, string); PNG as text (its text chunks hold nothing else); TIFF and JPEG, for
  // which OIIO writes only standard tags, as the ImageDescription "darc:errors=N\n
  // darc:first_error=MESSAGE". read_recorded_error_count reads any of them back.
  std::int64_t error_count = 0;
  std::string first_error;
  // The Display request's "compression" parameter; empty = the format's default (zip for EXR,
  // lzw for TIFF). PNG and JPEG ignore it.
  std::string compression;
  std::vector<Attribute> extra;  // anything else, written as is
};

// The file formats darc writes, chosen by the file extension (case-insensitive).
enum class ImageFormat {
  Exr,   // .exr: scene-linear half float (Z as float), zip, no view transform, data window kept
  Tiff,  // .tif, .tiff: 8-bit display-referred (mode "z": one float channel, linear)
  Png,   // .png: 8-bit display-referred, straight alpha (the PNG spec's)
  Jpeg,  // .jpg, .jpeg: 8-bit display-referred, RGB only
};

std::optional<ImageFormat> image_format_for_path(const std::string& path);

// Channel names for a RI display mode: "rgb", "rgba", "z", "rgbz", "rgbaz"; nullopt otherwise.
std::optional<std::vector<std::string>> channels_for_display_mode(const std::string& mode);

struct WriteResult {
  bool ok = false;
  std::string error;                    // set when !ok; names the file
  std::vector<std::string> warnings;    // e.g. alpha dropped for JPEG
  std::int64_t nonfinite_replaced = 0;  // NaN/inf channel values written as 0
};

// Writes image to path in the format its extension names, with the channels of the RI display
// mode:
// - EXR: RGBA as half, Z as float (depth needs more than half's 11 bits), the display window is
//   the full image and the data window is image.data_window (CropWindow).
// - TIFF/PNG/JPEG: 8 bits through config's display/view transform, tagged oiio:ColorSpace =
//   config.display_colorspace_tag(). TIFF and JPEG keep premultiplied RGB (RenderMan's output
//   convention; TIFF marks its alpha as associated). PNG's alpha is straight by definition, so
//   RGB is divided by alpha in linear space before the display transform. The full image is
//   written, zero outside the data window. Depth ("z") goes to TIFF only, as one linear float
//   channel; PNG and JPEG refuse it, and every 8-bit format refuses "rgbz"/"rgbaz" (use EXR).
// Non-finite values are written as 0 and counted. The file appears atomically: it is written to
// "<stem>.tmp-<pid>-<n><ext>" in the same directory and renamed; on any failure the temporary is
// removed and nothing is left behind (an existing file at path is left untouched).
WriteResult write_image(const std::string& path, const Image& image, const ImageMetadata& metadata,
                        const ColorConfig& config, const std::string& mode);

// The error count that write_image recorded in the file at `path` (0 when it records none);
// nullopt when the file does not open as an image.
std::optional<std::int64_t> read_recorded_error_count(const std::string& path);

}  // namespace darc
