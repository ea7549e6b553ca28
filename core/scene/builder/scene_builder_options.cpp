// SceneBuilder's option requests (Option, Format, the camera and image settings, Display,
// Hider and the requests without effect on darc's images): they set the options a frame starts
// from (the graphics state and the frame's blocks live in scene_builder.cpp).
#include "core/scene/builder/scene_builder.h"
#include "core/scene/builder/texture_paths.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/scene/builder/display_confinement.h"
#include "core/scene/builder/shader_parameter_checks.h"
#include "core/scene/builder/unused_request_checks.h"

namespace darc {

namespace {

// Largest image side we accept from Format or --res: a typo like "Format 32000 24000" would
// otherwise allocate gigabytes.
constexpr int kMaxResolution = 16384;
// Largest N for N x N pixel samples.
constexpr double kMaxPixelSamples = 64;
// Widest pixel filter (pixels): 16 is 8 pixels each side, eight times the RI default of 2.
constexpr double kMaxFilterWidth = 16;
// RI_INFINITY as RIB files write it (ri.h: 1.0e38): an f-stop this large is a pinhole.
constexpr double kRiInfinity = 1e38;

}  // namespace

// ---------------------------------------------------------------- options

bool SceneBuilder::option_allowed(const char* request, const SourceLoc& loc) {
  if (!in_world_) return true;
  diag_.warning(loc, request, "options cannot change inside WorldBegin/WorldEnd: ignored");
  return false;
}

void SceneBuilder::option(const std::string& category, const ParamList& params, const SourceLoc& loc) {
  if (category == "searchpath") {
    for (const Param& p : params.params) {
      if (p.name == "texture" && p.decl.is_string()) {
        options_.texture_search_path = texture_search_path(p.strings, options_.texture_search_path, loc.file_name());
      } else if (p.name != "archive" && p.name != "procedural") {  // the parser uses both
        diag_.warning_once("searchpath:" + p.name, loc, "Option",
                           "searchpath \"" + p.name +
                               "\" ignored (only \"archive\", \"procedural\" and \"texture\" are used)");
      }
    }
    return;
  }
  if (category == "trace") return trace_option(params, loc);
  diag_.warning_once("option:" + category, loc, "Option", "Option \"" + category + "\" has no effect in darc: ignored");
}

void SceneBuilder::format(int xres, int yres, double pixel_aspect, const SourceLoc& loc) {
  if (!option_allowed("Format", loc)) return;
  if (xres > kMaxResolution || yres > kMaxResolution)
    throw RibError("resolution " + std::to_string(xres) + "x" + std::to_string(yres) + " exceeds the limit of " +
                   std::to_string(kMaxResolution));
  // RI: values <= 0 keep the current setting.
  if (xres > 0) options_.output.xres = xres;
  if (yres > 0) options_.output.yres = yres;
  if (pixel_aspect > 0) options_.output.pixel_aspect = pixel_aspect;
}

void SceneBuilder::frame_aspect_ratio(double ratio, const SourceLoc& loc) {
  if (!option_allowed("FrameAspectRatio", loc)) return;
  if (!(ratio > 0)) throw RibError(fmt::format("frame aspect ratio {} must be positive", ratio));
  options_.frame_aspect = ratio;
}

void SceneBuilder::screen_window(double l, double r, double b, double t, const SourceLoc& loc) {
  if (!option_allowed("ScreenWindow", loc)) return;
  if (l == r || b == t) throw RibError(fmt::format("[{} {} {} {}] has zero width or height", l, r, b, t));
  options_.screen_window = ScreenWindow{l, r, b, t};
}

void SceneBuilder::crop_window(double x0, double x1, double y0, double y1, const SourceLoc& loc) {
  if (!option_allowed("CropWindow", loc)) return;
  auto in01 = [](double v) { return v >= 0 && v <= 1; };
  if (!in01(x0) || !in01(x1) || !in01(y0) || !in01(y1) || x0 >= x1 || y0 >= y1)
    throw RibError(fmt::format("[{} {} {} {}]: needs 0 <= xmin < xmax <= 1 and 0 <= ymin < ymax <= 1", x0, x1, y0, y1));
  double* c = options_.output.crop;
  c[0] = x0, c[1] = x1, c[2] = y0, c[3] = y1;
  options_.crop_loc = loc;
}

void SceneBuilder::projection(const std::string& name, const ParamList& params, const SourceLoc& loc) {
  if (!option_allowed("Projection", loc)) return;
  if (name == "perspective") {
    // Checked before anything changes: a request with an error is skipped as a whole.
    const Param* given = params.find("fov");
    if (given && (given->decl.is_string() || given->floats.size() != 1))
      throw RibError(
          fmt::format("fov must be one number, found {}",
                      given->decl.is_string() ? "a string" : std::to_string(given->floats.size()) + " numbers"));
    const double fov = given ? given->floats[0] : 90.0;
    if (!(fov > 0 && fov < 180)) throw RibError(fmt::format("fov must be in (0, 180) degrees, found {}", fov));
    options_.projection = Camera::Projection::Perspective;
    options_.fov_degrees = fov;
  } else if (name == "orthographic") {
    options_.projection = Camera::Projection::Orthographic;
  } else {
    diag_.warning(loc, "Projection", "unknown projection \"" + name + "\": using orthographic");
    options_.projection = Camera::Projection::Orthographic;
  }
  // RI: the current transform becomes the screen transform and is reset (camera space starts here).
  set_ctm(Matrix4{});
}

void SceneBuilder::clipping(double n, double f, const SourceLoc& loc) {
  if (!option_allowed("Clipping", loc)) return;
  if (!(n > 0) || !(f > n)) throw RibError(fmt::format("near {} and far {}: needs 0 < near < far", n, f));
  options_.near_clip = n;
  options_.far_clip = f;
}

void SceneBuilder::depth_of_field(double fstop, double focal_length, double focal_distance, const SourceLoc& loc) {
  if (!option_allowed("DepthOfField", loc)) return;
  // RI_INFINITY (1e38 in RIB files) or more: a pinhole, as by default.
  if (fstop >= kRiInfinity) {
    options_.lens_radius = 0;
    return;
  }
  if (!(fstop > 0) || !(focal_length > 0) || !(focal_distance > 0) || !std::isfinite(focal_length) ||
      !std::isfinite(focal_distance))
    throw RibError(fmt::format("fstop {}, focal length {} and focal distance {} must be positive", fstop,
                               focal_length, focal_distance));
  // A lens of diameter focallength / fstop, in camera-space units (pbrt-v4's thin lens).
  options_.lens_radius = focal_length / (2 * fstop);
  options_.focal_distance = focal_distance;
}

void SceneBuilder::pixel_samples(double xs, double ys, const SourceLoc& loc) {
  if (!option_allowed("PixelSamples", loc)) return;
  if (!(xs >= 1) || !(ys >= 1) || xs > kMaxPixelSamples || ys > kMaxPixelSamples)
    throw RibError(fmt::format("{} {} must be between 1 and {}", xs, ys, kMaxPixelSamples));
  // The hiders sample an N x N grid: fractional counts are rounded, and the image says so.
  const double x = std::round(xs), y = std::round(ys);
  if (x != xs || y != ys)
    diag_.warning(loc, "PixelSamples", fmt::format("{} {} are not whole numbers: rounded to {} {}", xs, ys, x, y));
  options_.output.pixel_samples[0] = x;
  options_.output.pixel_samples[1] = y;
}

void SceneBuilder::pixel_filter(const std::string& name, double xw, double yw, const SourceLoc& loc) {
  if (!option_allowed("PixelFilter", loc)) return;
  static const char* known[] = {"box", "triangle", "gaussian", "catmull-rom", "sinc"};
  if (std::find(std::begin(known), std::end(known), name) == std::end(known)) {
    diag_.warning(loc, "PixelFilter", "unknown filter \"" + name + "\": using gaussian 2 2");
    options_.output.filter_name = "gaussian";
    options_.output.filter_width[0] = options_.output.filter_width[1] = 2;
    return;
  }
  if (!(xw > 0) || !(yw > 0) || xw > kMaxFilterWidth || yw > kMaxFilterWidth)
    throw RibError(fmt::format("filter widths {} {} must be in (0, {}]", xw, yw, kMaxFilterWidth));
  options_.output.filter_name = name;
  options_.output.filter_width[0] = xw;
  options_.output.filter_width[1] = yw;
}

void SceneBuilder::exposure(double gain, double gamma, const SourceLoc& loc) {
  if (!option_allowed("Exposure", loc)) return;
  // A negative gain would make every pixel negative; gain 0 (a black frame) is a fade.
  if (!(gain >= 0)) throw RibError(fmt::format("gain {} must not be negative", gain));
  if (!(gamma > 0)) throw RibError(fmt::format("gamma {} must be positive", gamma));
  options_.output.exposure_gain = gain;
  options_.output.exposure_gamma = gamma;
}

void SceneBuilder::quantize(const std::string& type, int one, int, int, double, const SourceLoc& loc) {
  if (!option_allowed("Quantize", loc)) return;
  diag_.warning_once("quantize", loc, "Quantize",
                     "Quantize \"" + type + "\" " + std::to_string(one) +
                         " ignored: EXR is written as half float, 8-bit formats through the OCIO display transform");
}

void SceneBuilder::display(const std::string& name, const std::string& type, const std::string& mode,
                           const ParamList&, const SourceLoc& loc) {
  if (!option_allowed("Display", loc)) return;
  if (!name.empty() && name[0] == '+') {
    diag_.warning_once("display+", loc, "Display", "additional displays (\"+name\") are not supported: ignored");
    return;
  }
  static const char* file_types[] = {"file", "tiff", "openexr", "exr", "png", "framebuffer", "it"};
  if (std::find(std::begin(file_types), std::end(file_types), type) == std::end(file_types))
    diag_.warning_once("displaytype:" + type, loc, "Display",
                       "display type \"" + type + "\" unknown: writing a file chosen by the name's extension");
  else if (type == "framebuffer" || type == "it")
    diag_.warning_once("displaytype:" + type, loc, "Display",
                       "display type \"" + type + "\" has no window in darc: writing the file instead");
  static const char* modes[] = {"rgb", "rgba", "z", "rgbz", "rgbaz"};
  std::string m = mode;
  if (std::find(std::begin(modes), std::end(modes), m) == std::end(modes)) {
    diag_.warning(loc, "Display", "display mode \"" + mode + "\" not supported: using rgba");
    m = "rgba";
  }
  options_.output.display_name = confined_display_name(name, loc);
  options_.output.display_type = type;
  options_.output.display_mode = m;
}

std::string SceneBuilder::confined_display_name(const std::string& name, const SourceLoc& loc) {
  if (overrides_.display_folder.empty()) return name;
  const DisplayNameCheck check = check_display_name(name, overrides_.display_folder);
  if (check.allowed) return name;
  // The frame is still written (the rest of the request holds), where it cannot harm: under the
  // name's last component in the working folder, or the name in effect when there is none.
  const std::string written = check.fallback.empty() ? options_.output.display_name : check.fallback;
  diag_.error(loc, "Display",
              fmt::format("Display name \"{}\" refused: {}; a RIB's Display name must stay inside the working "
                          "folder ({}): the frame is written to \"{}\" there instead (-o names any file; "
                          "--trust-rib lifts this rule)",
                          name, check.reason, overrides_.display_folder, written));
  return written;
}

void SceneBuilder::hider(const std::string& type, const ParamList&, const SourceLoc& loc) {
  if (!option_allowed("Hider", loc)) return;
  options_.output.hider = type;
}

void SceneBuilder::camera(const std::string& name, const ParamList& params, const SourceLoc& loc) {
  if (!option_allowed("Camera", loc)) return;
  options_.named_cameras.emplace_back(name, ctm_);
  for (const Param& p : params.params) {
    if (p.name == "shutteropening") {
      camera_shutter_opening(p, loc);
      continue;
    }
    diag_.warning_once("camera parameters", loc, "Camera",
                       "camera parameters (\"" + p.name +
                           "\", lens and projection settings) are not supported: ignored; the image is rendered "
                           "from the camera in effect at WorldBegin");
  }
}

// PRMan's shutter opening: [a b], the times (fractions of the shutter) at which the shutter has
// opened fully and begins to close; RenderMan 21+ writes 8 numbers, a and b then the control
// points of its opening and closing curves, which darc takes as straight ramps.
void SceneBuilder::camera_shutter_opening(const Param& p, const SourceLoc& loc) {
  const std::vector<float>& v = p.floats;
  if (p.decl.is_string() || (v.size() != 2 && v.size() != 8))
    throw RibError(fmt::format("\"shutteropening\" takes 2 numbers (or RenderMan's 8), found {}: ignored",
                               p.decl.is_string() ? std::string("a string") : std::to_string(v.size())));
  if (!(v[0] >= 0 && v[0] <= v[1] && v[1] <= 1))
    throw RibError(fmt::format("\"shutteropening\" [{} {}] must be times 0 <= a <= b <= 1: ignored", v[0], v[1]));
  options_.output.shutter_opening = {v[0], v[1]};
  if (v.size() == 8)
    diag_.warning_once("shutteropening curve", loc, "Camera",
                       "the shutter curve's control points (numbers 3 to 8 of \"shutteropening\") are not "
                       "supported: the shutter opens and closes linearly");
}

void SceneBuilder::ignored_request(const std::string& request, const std::vector<double>& numbers,
                                   const std::vector<std::string>&, const SourceLoc& loc) {
  // ErrorHandler: the parser has applied it to the Diagnostics.
  static const char* silent[] = {"ShadingRate", "ShadingInterpolation", "Bound", "ErrorHandler",
                                 "ArchiveRecord", "Displacement", "RelativeDetail", "Detail", "DetailRange",
                                 "ColorSamples", "PixelVariance", "GeometricApproximation"};
  if (request == "Matte") {
    if (!numbers.empty() && numbers[0] != 0)
      diag_.warning_once("matte", loc, "Matte", "holdout objects (Matte 1) are not supported: drawn as ordinary objects");
    return;
  }
  if (std::find(std::begin(silent), std::end(silent), request) != std::end(silent))
    return check_unused_request_values(request, numbers, diag_, loc);
  diag_.warning_once("ignored:" + request, loc, request, "not supported by darc: ignored");
}

}  // namespace darc
