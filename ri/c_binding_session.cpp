// The C binding: contexts, declarations, error handlers, blocks and options.
#include "ri/c_binding.h"

#include <cmath>
#include <cstdio>
#include <exception>

using namespace darc;

namespace {

// What a handler function is given for a diagnostic.
void call_handler(RtErrorHandler handler, const Diagnostic& d) {
  const RtInt severity = d.severity == Severity::Error ? RIE_ERROR : RIE_WARNING;
  handler(RIE_CONSISTENCY, severity, d.str().c_str());
}

}  // namespace

extern "C" {

RtVoid RiBegin(RtToken name) {
  try {
    auto context = std::make_unique<CBindingContext>();
    CBindingContext* raw = context.get();
    context->session = std::make_unique<RiSession>(name ? name : "",
                                                   [raw](const Diagnostic& d) { call_handler(raw->handler, d); });
    current_c_context() = context.release();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "darc: error: RiBegin: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "darc: error: RiBegin failed\n");
  }
}

RtVoid RiEnd(void) {
  CBindingContext*& current = current_c_context();
  if (!current) {
    std::fprintf(stderr, "darc: error: RiEnd called outside RiBegin/RiEnd: ignored\n");
    return;
  }
  if (current->calls_in_progress > 0) {
    std::fprintf(stderr, "darc: error: RiEnd called from inside a call of the same context (a procedural or an "
                         "error handler): ignored\n");
    return;
  }
  std::unique_ptr<CBindingContext> ending(current);
  current = nullptr;
  try {
    ending->session->end();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "darc: error: RiEnd: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "darc: error: RiEnd failed\n");
  }
}

RtContextHandle RiGetContext(void) { return current_c_context(); }

RtVoid RiContext(RtContextHandle handle) { current_c_context() = static_cast<CBindingContext*>(handle); }

// The returned token lives until RiEnd (the caller's `name` when there is no context). A null
// declaration declares nothing: the name is returned as a token (RI Spec 3.2).
RtToken RiDeclare(const char* name, const char* declaration) {
  CBindingContext* context = current_c_context();
  if (!name) return RI_NULL;
  RtToken token = name;
  with_session("Declare", [&](RiSession& s, const SourceLoc& loc) {
    token = context->tokens.emplace(name).first->c_str();
    if (declaration) s.declare(name, declaration, loc);
  });
  return token;
}

RtVoid RiErrorHandler(RtErrorHandler handler) {
  CBindingContext* context = current_c_context();
  if (!context) return;
  context->handler = handler ? handler : RiErrorPrint;
  const char* name = handler == RiErrorIgnore ? "ignore" : handler == RiErrorAbort ? "abort" : "print";
  with_session("ErrorHandler", [&](RiSession& s, const SourceLoc& loc) { s.error_handler(name, loc); });
}

RtVoid RiErrorIgnore(RtInt, RtInt, const char*) {}

RtVoid RiErrorPrint(RtInt, RtInt, const char* message) { std::fprintf(stderr, "%s\n", message ? message : ""); }

RtVoid RiErrorAbort(RtInt code, RtInt severity, const char* message) { RiErrorPrint(code, severity, message); }

// --- blocks ---

RtVoid RiFrameBegin(RtInt frame) {
  with_session("FrameBegin", [&](RiSession& s, const SourceLoc& loc) {
    s.frame_begin(frame, loc);
  });
}
RtVoid RiFrameEnd(void) {
  with_session("FrameEnd", [](RiSession& s, const SourceLoc& loc) { s.target().frame_end(loc); });
}
RtVoid RiWorldBegin(void) {
  with_session("WorldBegin", [](RiSession& s, const SourceLoc& loc) { s.target().world_begin(loc); });
}
RtVoid RiWorldEnd(void) {
  with_session("WorldEnd", [](RiSession& s, const SourceLoc& loc) { s.target().world_end(loc); });
}
RtVoid RiAttributeBegin(void) {
  with_session("AttributeBegin", [](RiSession& s, const SourceLoc& loc) { s.target().attribute_begin(loc); });
}
RtVoid RiAttributeEnd(void) {
  with_session("AttributeEnd", [](RiSession& s, const SourceLoc& loc) { s.target().attribute_end(loc); });
}
RtVoid RiTransformBegin(void) {
  with_session("TransformBegin", [](RiSession& s, const SourceLoc& loc) { s.target().transform_begin(loc); });
}
RtVoid RiTransformEnd(void) {
  with_session("TransformEnd", [](RiSession& s, const SourceLoc& loc) { s.target().transform_end(loc); });
}
RtVoid RiMotionBeginV(RtInt n, RtFloat times[]) {
  with_session("MotionBegin", [&](RiSession& s, const SourceLoc& loc) {
    std::vector<double> t;
    for (RtInt i = 0; i < n && times; ++i) t.push_back(decimal_double(times[i]));
    s.target().motion_begin(t, loc);
  });
}
RtVoid RiMotionBegin(RtInt n, ...) {
  std::vector<RtFloat> times;
  va_list args;
  va_start(args, n);
  for (RtInt i = 0; i < n; ++i) times.push_back(RtFloat(va_arg(args, double)));  // floats are promoted
  va_end(args);
  RiMotionBeginV(n, times.data());
}
RtVoid RiMotionEnd(void) {
  with_session("MotionEnd", [](RiSession& s, const SourceLoc& loc) { s.target().motion_end(loc); });
}
RtVoid RiResourceBegin(void) {
  with_session("ResourceBegin", [](RiSession& s, const SourceLoc& loc) { s.target().resource_begin(loc); });
}
RtVoid RiResourceEnd(void) {
  with_session("ResourceEnd", [](RiSession& s, const SourceLoc& loc) { s.target().resource_end(loc); });
}

// --- options ---

RtVoid RiFormat(RtInt xres, RtInt yres, RtFloat pixel_aspect) {
  with_session("Format", [&](RiSession& s, const SourceLoc& loc) {
    s.target().format(xres, yres, decimal_double(pixel_aspect), loc);
  });
}
RtVoid RiFrameAspectRatio(RtFloat ratio) {
  with_session("FrameAspectRatio",
               [&](RiSession& s, const SourceLoc& loc) { s.target().frame_aspect_ratio(decimal_double(ratio), loc); });
}
RtVoid RiScreenWindow(RtFloat left, RtFloat right, RtFloat bottom, RtFloat top) {
  with_session("ScreenWindow", [&](RiSession& s, const SourceLoc& loc) {
    s.target().screen_window(decimal_double(left), decimal_double(right), decimal_double(bottom), decimal_double(top),
                             loc);
  });
}
RtVoid RiCropWindow(RtFloat xmin, RtFloat xmax, RtFloat ymin, RtFloat ymax) {
  with_session("CropWindow", [&](RiSession& s, const SourceLoc& loc) {
    s.target().crop_window(decimal_double(xmin), decimal_double(xmax), decimal_double(ymin), decimal_double(ymax), loc);
  });
}
RtVoid RiProjectionV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]) {
  name_and_params("Projection", name, n, tokens, values, &RiTarget::projection);
}
RtVoid RiProjection(RtToken name, ...) { DARC_RI_WITH_TOKEN_VALUES(name, RiProjectionV(name, tv.size(), tv.tokens.data(), tv.values.data())); }
RtVoid RiClipping(RtFloat near_plane, RtFloat far_plane) {
  with_session("Clipping", [&](RiSession& s, const SourceLoc& loc) {
    s.target().clipping(decimal_double(near_plane), decimal_double(far_plane), loc);
  });
}
RtVoid RiDepthOfField(RtFloat fstop, RtFloat focal_length, RtFloat focal_distance) {
  with_session("DepthOfField", [&](RiSession& s, const SourceLoc& loc) {
    s.target().depth_of_field(decimal_double(fstop), decimal_double(focal_length), decimal_double(focal_distance), loc);
  });
}
RtVoid RiShutter(RtFloat open, RtFloat close) {
  with_session("Shutter", [&](RiSession& s, const SourceLoc& loc) {
    s.target().shutter(decimal_double(open), decimal_double(close), loc);
  });
}
RtVoid RiColorSamples(RtInt n, RtFloat nRGB[], RtFloat RGBn[]) {
  with_session("ColorSamples", [&](RiSession& s, const SourceLoc& loc) {
    std::vector<double> numbers;  // as the parser flattens the request: the two matrices
    for (RtInt i = 0; i < 3 * n && nRGB; ++i) numbers.push_back(decimal_double(nRGB[i]));
    for (RtInt i = 0; i < 3 * n && RGBn; ++i) numbers.push_back(decimal_double(RGBn[i]));
    s.target().ignored_request("ColorSamples", numbers, {}, loc);
  });
}
RtVoid RiPixelVariance(RtFloat variation) {
  with_session("PixelVariance", [&](RiSession& s, const SourceLoc& loc) {
    s.target().ignored_request("PixelVariance", {decimal_double(variation)}, {}, loc);
  });
}
RtVoid RiPixelSamples(RtFloat xsamples, RtFloat ysamples) {
  with_session("PixelSamples", [&](RiSession& s, const SourceLoc& loc) {
    s.target().pixel_samples(decimal_double(xsamples), decimal_double(ysamples), loc);
  });
}
RtVoid RiPixelFilter(RtFilterFunc filter, RtFloat xwidth, RtFloat ywidth) {
  with_session("PixelFilter", [&](RiSession& s, const SourceLoc& loc) {
    const char* name = filter == RiBoxFilter          ? "box"
                       : filter == RiTriangleFilter   ? "triangle"
                       : filter == RiCatmullRomFilter ? "catmull-rom"
                       : filter == RiGaussianFilter   ? "gaussian"
                       : filter == RiSincFilter       ? "sinc"
                                                      : nullptr;
    if (!name) {
      s.diagnostics().warning(loc, "PixelFilter",
                              "a filter function of the program's own is not supported (darc filters with its own "
                              "box, triangle, catmull-rom, gaussian and sinc): the filter is unchanged");
      return;
    }
    s.target().pixel_filter(name, decimal_double(xwidth), decimal_double(ywidth), loc);
  });
}
RtVoid RiExposure(RtFloat gain, RtFloat gamma) {
  with_session("Exposure", [&](RiSession& s, const SourceLoc& loc) {
    s.target().exposure(decimal_double(gain), decimal_double(gamma), loc);
  });
}
RtVoid RiImagerV(RtToken name, RtInt, RtToken[], RtPointer[]) {
  with_session("Imager", [&](RiSession& s, const SourceLoc& loc) {
    s.target().ignored_request("Imager", {}, {name ? name : ""}, loc);
  });
}
RtVoid RiImager(RtToken name, ...) { DARC_RI_WITH_TOKEN_VALUES(name, RiImagerV(name, tv.size(), tv.tokens.data(), tv.values.data())); }
RtVoid RiQuantize(RtToken type, RtInt one, RtInt min, RtInt max, RtFloat dither) {
  with_session("Quantize", [&](RiSession& s, const SourceLoc& loc) {
    s.target().quantize(type ? type : "", one, min, max, decimal_double(dither), loc);
  });
}
RtVoid RiDisplayV(const char* name, RtToken type, RtToken mode, RtInt n, RtToken tokens[], RtPointer values[]) {
  with_session("Display", [&](RiSession& s, const SourceLoc& loc) {
    const ParamList params = c_param_list(s, "Display", single_values(), n, tokens, values, loc);
    s.target().display(name ? name : "", type ? type : "", mode ? mode : "", params, loc);
  });
}
RtVoid RiDisplay(const char* name, RtToken type, RtToken mode, ...) {
  DARC_RI_WITH_TOKEN_VALUES(mode, RiDisplayV(name, type, mode, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiCameraV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]) {
  name_and_params("Camera", name, n, tokens, values, &RiTarget::camera);
}
RtVoid RiCamera(RtToken name, ...) { DARC_RI_WITH_TOKEN_VALUES(name, RiCameraV(name, tv.size(), tv.tokens.data(), tv.values.data())); }
RtVoid RiHiderV(RtToken type, RtInt n, RtToken tokens[], RtPointer values[]) {
  name_and_params("Hider", type, n, tokens, values, &RiTarget::hider);
}
RtVoid RiHider(RtToken type, ...) { DARC_RI_WITH_TOKEN_VALUES(type, RiHiderV(type, tv.size(), tv.tokens.data(), tv.values.data())); }
RtVoid RiOptionV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]) {
  with_session("Option", [&](RiSession& s, const SourceLoc& loc) {
    const ParamList params = c_param_list(s, "Option", single_values(), n, tokens, values, loc);
    s.option(name ? name : "", params, loc);
  });
}
RtVoid RiOption(RtToken name, ...) { DARC_RI_WITH_TOKEN_VALUES(name, RiOptionV(name, tv.size(), tv.tokens.data(), tv.values.data())); }
RtVoid RiIntegratorV(RtToken name, RtToken handle, RtInt n, RtToken tokens[], RtPointer values[]) {
  with_session("Integrator", [&](RiSession& s, const SourceLoc& loc) {
    const ParamList params = c_param_list(s, "Integrator", single_values(), n, tokens, values, loc);
    s.target().integrator(name ? name : "", handle ? handle : "", params, loc);
  });
}
RtVoid RiIntegrator(RtToken name, RtToken handle, ...) {
  DARC_RI_WITH_TOKEN_VALUES(handle, RiIntegratorV(name, handle, tv.size(), tv.tokens.data(), tv.values.data()));
}

// The standard filters, as RI defines them (darc's renders use its own implementations: these
// exist so that a program can name them).
RtFloat RiBoxFilter(RtFloat, RtFloat, RtFloat, RtFloat) { return 1; }
RtFloat RiTriangleFilter(RtFloat x, RtFloat y, RtFloat xwidth, RtFloat ywidth) {
  const RtFloat fx = 1 - 2 * std::abs(x) / xwidth, fy = 1 - 2 * std::abs(y) / ywidth;
  return fx > 0 && fy > 0 ? fx * fy : 0;
}
RtFloat RiCatmullRomFilter(RtFloat x, RtFloat y, RtFloat, RtFloat) {
  auto one = [](RtFloat t) {
    t = std::abs(t);
    if (t < 1) return 1.5f * t * t * t - 2.5f * t * t + 1;
    if (t < 2) return -0.5f * t * t * t + 2.5f * t * t - 4 * t + 2;
    return 0.0f;
  };
  return one(x) * one(y);
}
RtFloat RiGaussianFilter(RtFloat x, RtFloat y, RtFloat xwidth, RtFloat ywidth) {
  const RtFloat u = 2 * x / xwidth, v = 2 * y / ywidth;
  return std::exp(-2 * (u * u + v * v));
}
RtFloat RiSincFilter(RtFloat x, RtFloat y, RtFloat, RtFloat) {
  auto one = [](RtFloat t) { return t == 0 ? 1.0f : std::sin(3.14159265f * t) / (3.14159265f * t); };
  return one(x) * one(y);
}

}  // extern "C"
