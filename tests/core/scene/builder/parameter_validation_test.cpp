// The numeric parameter audit (docs/parameters.md), one test per row of its table: the RIB the
// row is about, the one diagnostic it must give (severity, position, request, message; none for
// a valid value) and what the scene holds afterwards (the request skipped, the clamped value
// used, or the value kept). A last test checks that every row of the table has its test here.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include "core/scene/builder/parameter_validation_rows.h"
#include "support/scenes_from_rib.h"

namespace darc::test {
namespace {

float param(const ParamList& params, const char* name) {
  const Param* p = params.find(name);
  EXPECT_TRUE(p) << name;
  return p ? p->floats.at(0) : std::nanf("");
}

constexpr float kFloatMax = std::numeric_limits<float>::max();

std::vector<Row> option_rows() {
  return {
      {"format-res-limit", before_world("Format 20000 100 1"),
       error(1, "Format", "resolution 20000x100 exceeds the limit of 16384"),
       [](const Scene& s) { EXPECT_EQ(s.output.xres, 640); }},
      {"format-res-nonpositive", before_world("Format 320 240 1\nFormat -1 0 1"), std::nullopt,
       [](const Scene& s) {
         EXPECT_EQ(s.output.xres, 320);
         EXPECT_EQ(s.output.yres, 240);
       }},
      {"format-aspect-nonpositive", before_world("Format 320 240 2\nFormat 320 240 0"), std::nullopt,
       [](const Scene& s) { EXPECT_EQ(s.output.pixel_aspect, 2); }},
      {"format-aspect-float-range", before_world("Format 4 1 3e38"),
       warning(2, "WorldBegin",
               "the frame aspect ratio 1.2e+39 (Format pixel aspect ratio 3e+38) puts the screen window beyond the "
               "float range: clamped to 3.4028234663852886e+38"),
       [](const Scene& s) { EXPECT_EQ(s.camera.screen.right, double(kFloatMax)); }},
      {"frameaspect-nonpositive", before_world("FrameAspectRatio 0"),
       error(1, "FrameAspectRatio", "frame aspect ratio 0 must be positive"),
       [](const Scene& s) { EXPECT_NEAR(s.camera.screen.right, 640.0 / 480.0, 1e-12); }},
      {"screenwindow-empty", before_world("ScreenWindow -1 -1 -1 1"),
       error(1, "ScreenWindow", "[-1 -1 -1 1] has zero width or height"),
       [](const Scene& s) { EXPECT_NEAR(s.camera.screen.left, -640.0 / 480.0, 1e-12) << "the default window"; }},
      {"screenwindow-flipped", before_world("ScreenWindow 1 -1 -1 1"), std::nullopt,
       [](const Scene& s) { EXPECT_EQ(s.camera.screen.left, 1); }},
      {"cropwindow-range", before_world("CropWindow 0.5 0.25 0 1"),
       error(1, "CropWindow", "[0.5 0.25 0 1]: needs 0 <= xmin < xmax <= 1 and 0 <= ymin < ymax <= 1"),
       [](const Scene& s) { EXPECT_EQ(s.output.crop[1], 1); }},
      {"cropwindow-no-pixel", before_world("Format 10 10 1\nCropWindow 0.01 0.02 0 1"),
       error(2, "CropWindow", "[0.01 0.02 0 1] keeps no pixel of the 10x10 image: the whole image is rendered"),
       [](const Scene& s) {
         EXPECT_EQ(s.output.crop[0], 0);
         EXPECT_EQ(s.output.crop[1], 1);
       }},
      {"projection-fov-range", before_world("Projection \"perspective\" \"fov\" [180]"),
       error(1, "Projection", "fov must be in (0, 180) degrees, found 180"),
       [](const Scene& s) { EXPECT_EQ(s.camera.projection, Camera::Projection::Orthographic); }},
      {"projection-fov-count", before_world("Projection \"perspective\" \"fov\" [30 40]"),
       error(1, "Projection", "fov must be one number, found 2 numbers"),
       [](const Scene& s) { EXPECT_EQ(s.camera.projection, Camera::Projection::Orthographic); }},
      {"clipping-near", before_world("Clipping 0 10"), error(1, "Clipping", "near 0 and far 10: needs 0 < near < far"),
       [](const Scene& s) { EXPECT_EQ(s.camera.near_clip, 1e-10); }},
      {"clipping-far", before_world("Clipping 5 5"), error(1, "Clipping", "near 5 and far 5: needs 0 < near < far"),
       [](const Scene& s) { EXPECT_EQ(s.camera.far_clip, 1e38); }},
      {"shutter", before_world("Shutter 1 0"),
       error(1, "Shutter", "close time 0 is before the open time 1: the shutter is left as it was"),
       [](const Scene& s) { EXPECT_EQ(s.output.shutter_close, 0.0); }},
      {"dof-fstop", before_world("DepthOfField 0 0.5 4"),
       error(1, "DepthOfField", "fstop 0, focal length 0.5 and focal distance 4 must be positive"),
       [](const Scene& s) { EXPECT_FALSE(s.camera.has_lens()) << "the request is skipped: a pinhole"; }},
      {"dof-focal-distance", before_world("DepthOfField 2 0.5 -1"),
       error(1, "DepthOfField", "fstop 2, focal length 0.5 and focal distance -1 must be positive"),
       [](const Scene& s) { EXPECT_FALSE(s.camera.has_lens()); }},
      {"dof-infinite-fstop", before_world("DepthOfField 2 0.5 4\nDepthOfField 1e38 0 0"), std::nullopt,
       [](const Scene& s) { EXPECT_FALSE(s.camera.has_lens()) << "RI_INFINITY: back to a pinhole"; }},
      {"dof-lens", before_world("DepthOfField 2 0.5 4"), std::nullopt,
       [](const Scene& s) {
         EXPECT_DOUBLE_EQ(s.camera.lens_radius, 0.125) << "focallength / (2 fstop)";
         EXPECT_DOUBLE_EQ(s.camera.focal_distance, 4);
       }},
      {"clipping-tiny-near", before_world("Clipping 1e-20 10"), std::nullopt,
       [](const Scene& s) { EXPECT_EQ(s.camera.near_clip, 1e-20); }},
      {"pixelsamples-range", before_world("PixelSamples 0.5 2"),
       error(1, "PixelSamples", "0.5 2 must be between 1 and 64"),
       [](const Scene& s) { EXPECT_EQ(s.output.pixel_samples[1], 2); }},
      {"pixelsamples-fraction", before_world("PixelSamples 2.5 3"),
       warning(1, "PixelSamples", "2.5 3 are not whole numbers: rounded to 3 3"),
       [](const Scene& s) { EXPECT_EQ(s.output.pixel_samples[0], 3); }},
      {"pixelfilter-width", before_world("PixelFilter \"box\" 0 1"),
       error(1, "PixelFilter", "filter widths 0 1 must be in (0, 16]"),
       [](const Scene& s) { EXPECT_EQ(s.output.filter_name, "gaussian"); }},
      {"exposure-gain", before_world("Exposure -1 1"), error(1, "Exposure", "gain -1 must not be negative"),
       [](const Scene& s) { EXPECT_EQ(s.output.exposure_gain, 1); }},
      {"exposure-gain-zero", before_world("Exposure 0 1"), std::nullopt,
       [](const Scene& s) { EXPECT_EQ(s.output.exposure_gain, 0); }},
      {"exposure-gamma", before_world("Exposure 2 0"), error(1, "Exposure", "gamma 0 must be positive"),
       [](const Scene& s) { EXPECT_EQ(s.output.exposure_gain, 1) << "the whole request is skipped"; }},
      {"quantize", before_world("Quantize \"rgba\" -5 300 2 -1"),
       warning(1, "Quantize",
               "Quantize \"rgba\" -5 ignored: EXR is written as half float, 8-bit formats through the OCIO display "
               "transform"),
       [](const Scene&) {}},
      {"display-hider-params", before_world("Hider \"hidden\" \"jitter\" [-3]"), std::nullopt,
       [](const Scene& s) { EXPECT_EQ(s.output.hider, "hidden"); }},
      {"trace-maxdepth-negative", before_world("Option \"trace\" \"int maxdepth\" [-1]"),
       error(1, "Option", "Option \"trace\" \"maxdepth\" must be an integer >= 0, found -1"),
       [](const Scene& s) { EXPECT_EQ(s.output.trace_max_depth, 10); }},
      {"trace-maxdepth-deep", before_world("Option \"trace\" \"int maxdepth\" [1000000]"),
       warning(1, "Option", "Option \"trace\" \"maxdepth\" 1000000 is deeper than darc traces: clamped to 100"),
       [](const Scene& s) { EXPECT_EQ(s.output.trace_max_depth, 100); }},
      {"framebegin-number", "FrameBegin -2147483648\nWorldBegin\nWorldEnd\nFrameEnd\n", std::nullopt,
       [](const Scene& s) { EXPECT_EQ(s.output.frame_number, std::numeric_limits<int>::min()); }},
      {"procedural-bound", in_world("Procedural \"DelayedReadArchive\" [\"absent.rib\"] [1 0 0 1 0 1]"),
       error(2, "Procedural", "the bound's xmin (1) is greater than its xmax (0)"), [](const Scene&) {}},
      {"version", before_world("version 9.5"), std::nullopt, [](const Scene&) {}},
  };
}

// Requests darc accepts without effect: their RI ranges give warnings only.
std::vector<Row> unused_request_rows() {
  const auto nothing = [](const Scene&) {};
  const std::string unused = " (RI Spec 3.2); darc does not use it";
  return {
      {"shadingrate", in_world("ShadingRate 0"), warning(2, "ShadingRate", "size 0 must be positive" + unused),
       nothing},
      {"relativedetail", before_world("RelativeDetail -1"),
       warning(1, "RelativeDetail", "value -1 must not be negative" + unused), nothing},
      {"pixelvariance", before_world("PixelVariance -0.5"),
       warning(1, "PixelVariance", "value -0.5 must not be negative" + unused), nothing},
      {"geometricapproximation", in_world("GeometricApproximation \"flatness\" -1"),
       warning(2, "GeometricApproximation", "value -1 must not be negative" + unused), nothing},
      {"detailrange", in_world("DetailRange 0 2 1 3"),
       warning(2, "DetailRange", "[0 2 1 3] must not decrease" + unused), nothing},
      {"bound", in_world("Bound [1 0 0 1 0 1]"), warning(2, "Bound", "the bound's xmin 1 is above its xmax 0" + unused),
       nothing},
      {"detail", in_world("Detail [0 1 0 1 1 0]"),
       warning(2, "Detail", "the bound's zmin 1 is above its zmax 0" + unused), nothing},
      {"unused-count", in_world("ShadingRate"), warning(2, "ShadingRate", "takes 1 number, found 0" + unused), nothing},
      {"colorsamples", before_world("ColorSamples [0.3 0.3 0.3] [1 1 1]"),
       warning(1, "ColorSamples", "N = 1 samples per colour is not supported: colours stay RGB"), nothing},
      {"matte", in_world("Matte 5"),
       warning(2, "Matte", "holdout objects (Matte 1) are not supported: drawn as ordinary objects"), nothing},
      {"unsupported-numbers", in_world("TextureCoordinates -1 0 0 0 0 1 1 1"),
       warning(2, "TextureCoordinates", "not supported by darc: ignored"), nothing},
  };
}

std::vector<Row> transform_rows() {
  std::string nine_scales;
  for (int i = 0; i < 9; ++i) nine_scales += i < 8 ? "Scale 1e38 1 1\n" : "Scale 1e38 1 1";
  return {
      {"transform-overflow", before_world(nine_scales),
       error(9, "Scale", "the current transform would overflow (an entry beyond the double range)"),
       [](const Scene& s) {
         EXPECT_DOUBLE_EQ(s.camera.world_to_camera.m[0][0], 1e304) << "the current transform before the overflow";
       }},
      {"transform-values", in_world("Translate 1e38 0 0\nRotate 1e30 0 0 1\nSphere 1 -1 1 360"), std::nullopt,
       [](const Scene& s) { ASSERT_EQ(s.surfaces.spheres.size(), 1u); }},
      {"rotate-axis", in_world("Rotate 30 0 0 0"), error(2, "Rotate", "Rotate axis is the zero vector"),
       [](const Scene&) {}},
      {"transform-singular", in_world("ConcatTransform [0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0]\nSphere 1 -1 1 360"),
       std::nullopt,
       [](const Scene& s) {
         ASSERT_EQ(s.surfaces.spheres.size(), 1u);
         EXPECT_TRUE(s.surfaces.spheres[0].degenerate) << "flattened to nothing";
       }},
      {"perspective-fov", in_world("Perspective 0"), error(2, "Perspective", "Perspective fov must be in (0, 180)"),
       [](const Scene&) {}},
      {"camera-singular", before_world("Scale 0 0 0"),
       warning(2, "WorldBegin", "the camera transform is singular: the identity is used instead"),
       [](const Scene& s) { EXPECT_EQ(s.camera.world_to_camera, Matrix4{}); }},
  };
}

std::vector<Row> attribute_rows() {
  const auto material = [](const Scene& s) -> const Material& { return s.materials.at(s.surfaces.sphere_material.at(0)); };
  return {
      {"sides", in_world("Sides 3\nSphere 1 -1 1 360"), error(2, "Sides", "Sides must be 1 or 2, found 3"),
       [material](const Scene& s) { EXPECT_EQ(material(s).sides, 2); }},
      {"color", in_world("Color [-0.1 2 0.5]\nSphere 1 -1 1 360"), std::nullopt,
       [material](const Scene& s) {
         EXPECT_EQ(material(s).color, (Vec3f{-0.1f, 2, 0.5f}));
       }},
      {"opacity", in_world("Opacity [1.5 -0.5 0.5]\nSphere 1 -1 1 360"),
       warning(2, "Opacity", "[1.5 -0.5 0.5] is outside [0, 1]: clamped to [1 0 0.5]"),
       [material](const Scene& s) {
         EXPECT_EQ(material(s).opacity, (Vec3f{1, 0, 0.5f}));
       }},
      {"basis-step", in_world("Basis \"bezier\" 0 \"bezier\" 3"),
       error(2, "Basis", "basis step must be at least 1, found 0"), [](const Scene&) {}},
      {"ri-basisstep", in_world("Attribute \"Ri\" \"int[2] BasisStep\" [0 1]"),
       error(2, "Attribute", "basis step must be at least 1, found 0"), [](const Scene&) {}},
      {"basis-matrix",
       in_world("Basis [0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0] 1 [0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0] 1\n"
                "Curves \"cubic\" [4] \"nonperiodic\" \"P\" [0 0 0  1 0 0  2 0 0  3 0 0]"),
       std::nullopt, [](const Scene& s) { EXPECT_EQ(s.curves.size(), 0u) << "every segment collapses to a point"; }},
      {"illuminate", in_world("LightSource \"pointlight\" 1\nIlluminate 1 7\nSphere 1 -1 1 360"), std::nullopt,
       [material](const Scene& s) { EXPECT_EQ(material(s).lights.size(), 1u); }},
      {"transmission", in_world("Attribute \"visibility\" \"int transmission\" [2]"),
       error(2, "Attribute",
             "Attribute \"visibility\" \"transmission\" must be 0 or 1 (or one of \"opaque\", \"transparent\", "
             "\"Os\", \"shader\"), found 2"),
       [](const Scene&) {}},
  };
}

std::vector<Row> shader_rows() {
  const auto surface = [](const Scene& s) -> const ParamList& {
    return s.materials.at(s.surfaces.sphere_material.at(0)).surface_params;
  };
  const auto light = [](const Scene& s) -> const ParamList& { return s.lights.at(0).params; };
  const std::string sphere = "\nSphere 1 -1 1 360";
  return {
      {"surface-coefficient", in_world("Surface \"plastic\" \"Kd\" [-0.5]" + sphere),
       warning(2, "Surface", "\"plastic\" \"Kd\" -0.5 is negative: clamped to 0"),
       [surface](const Scene& s) { EXPECT_EQ(param(surface(s), "Kd"), 0); }},
      {"surface-coefficient-large", in_world("Surface \"plastic\" \"Ks\" [4]" + sphere), std::nullopt,
       [surface](const Scene& s) { EXPECT_EQ(param(surface(s), "Ks"), 4); }},
      {"surface-roughness", in_world("Surface \"metal\" \"roughness\" [0]" + sphere),
       warning(2, "Surface", "\"metal\" \"roughness\" 0 is not positive: clamped to 0.0001"),
       [surface](const Scene& s) { EXPECT_EQ(param(surface(s), "roughness"), 1e-4f); }},
      {"surface-eta", in_world("Surface \"glass\" \"eta\" [-1.5]" + sphere),
       warning(2, "Surface", "\"glass\" \"eta\" -1.5 is not positive: clamped to 1 (no refraction)"),
       [surface](const Scene& s) { EXPECT_EQ(param(surface(s), "eta"), 1); }},
      {"surface-count", in_world("Surface \"matte\" \"Kd\" [0.5 0.5]" + sphere),
       error(2, "Surface", "\"Kd\" must be one number, found 2 numbers"),
       [](const Scene& s) { EXPECT_EQ(s.materials.at(0).surface, "defaultsurface") << "the request is skipped"; }},
      {"surface-unknown", in_world("Surface \"velvet\" \"Kd\" [-1]" + sphere), std::nullopt,
       [surface](const Scene& s) { EXPECT_EQ(param(surface(s), "Kd"), -1); }},
      {"light-intensity", in_world("LightSource \"pointlight\" 1 \"intensity\" [-2]"), std::nullopt,
       [light](const Scene& s) { EXPECT_EQ(param(light(s), "intensity"), -2); }},
      {"light-cone-negative", in_world("LightSource \"spotlight\" 1 \"coneangle\" [-0.1]"),
       warning(2, "LightSource",
               "\"spotlight\" \"coneangle\" -0.1 is negative: clamped to 0 (the light sends nothing)"),
       [light](const Scene& s) { EXPECT_EQ(param(light(s), "coneangle"), 0); }},
      {"light-cone-wide", in_world("LightSource \"shadowspot\" 1 \"coneangle\" [30]"),
       warning(2, "LightSource",
               "\"shadowspot\" \"coneangle\" 30 is more than pi: clamped to 3.1415927 (RI angles are radians: 30 "
               "radians is 1719 degrees)"),
       [light](const Scene& s) { EXPECT_EQ(param(light(s), "coneangle"), std::numbers::pi_v<float>); }},
      {"light-delta", in_world("LightSource \"spotlight\" 1 \"coneangle\" [0.5] \"conedeltaangle\" [0.6]"),
       warning(2, "LightSource", "\"spotlight\" \"conedeltaangle\" 0.6 is wider than the cone angle: clamped to 0.5"),
       [light](const Scene& s) { EXPECT_EQ(param(light(s), "conedeltaangle"), 0.5f); }},
      {"light-delta-negative", in_world("LightSource \"spotlight\" 1 \"conedeltaangle\" [-0.2]"),
       warning(2, "LightSource", "\"spotlight\" \"conedeltaangle\" -0.2 is negative: clamped to 0 (a hard cone edge)"),
       [light](const Scene& s) { EXPECT_EQ(param(light(s), "conedeltaangle"), 0); }},
      {"light-beam", in_world("LightSource \"spotlight\" 1 \"beamdistribution\" [-1]"),
       warning(2, "LightSource", "\"spotlight\" \"beamdistribution\" -1 is negative: clamped to 0"),
       [light](const Scene& s) { EXPECT_EQ(param(light(s), "beamdistribution"), 0); }},
      {"light-angle-negative", in_world("LightSource \"distantlight\" 1 \"float angle\" [-2]"),
       warning(2, "LightSource", "\"distantlight\" \"angle\" -2 is negative: clamped to 0 (hard shadows)"),
       [light](const Scene& s) { EXPECT_EQ(param(light(s), "angle"), 0); }},
      {"light-angle-wide", in_world("LightSource \"shadowdistant\" 1 \"float angle\" [120]"),
       warning(2, "LightSource", "\"shadowdistant\" \"angle\" 120 is more than 90 degrees: clamped to 90"),
       [light](const Scene& s) { EXPECT_EQ(param(light(s), "angle"), 90); }},
      {"light-direction", in_world("LightSource \"distantlight\" 1 \"from\" [1 2 3] \"to\" [1 2 3]"),
       warning(
           2, "LightSource",
           "\"distantlight\" \"from\" and \"to\" are both (1, 2, 3): the light has no direction and sends no light"),
       [](const Scene& s) { EXPECT_EQ(s.lights.size(), 1u) << "the light is kept"; }},
      {"light-position-range", in_world("Translate 3e38 0 0\nLightSource \"pointlight\" 1 \"from\" [3e38 0 0]"),
       error(3, "LightSource", "\"from\" (3e+38 0 0) lies beyond the float range in world space"),
       [](const Scene& s) { EXPECT_TRUE(s.lights.empty()); }},
      {"light-count", in_world("LightSource \"pointlight\" 1 \"intensity\" [1 2]"),
       error(2, "LightSource", "\"intensity\" must be one number, found 2 numbers"),
       [](const Scene& s) { EXPECT_TRUE(s.lights.empty()); }},
      {"light-map-missing", in_world("LightSource \"domelight\" 1 \"string mapname\" [\"no-such-sky.exr\"]"),
       warning(2, "LightSource",
               "texture \"no-such-sky.exr\" not found (searched beside the RIB file): domelight lights with its colour "
               "alone"),
       [light](const Scene& s) {
         const Param* map = light(s).find("mapname");
         ASSERT_TRUE(map);
         EXPECT_EQ(map->strings.at(0), "") << "cleared: the dome keeps its colour";
       }},
      {"pxrtexture-missing",
       in_world("Pattern \"PxrTexture\" \"t\" \"string filename\" [\"no-such-wood.tex\"]\n"
                "Bxdf \"PxrSurface\" \"s\" \"reference color diffuseColor\" [\"t:resultRGB\"]"),
       warning(3, "Bxdf",
               "texture \"no-such-wood.tex\" not found (searched beside the RIB file): plastic shades with the "
               "PxrTexture's missingColor"),
       [](const Scene&) {}},
      {"arealight-count", in_world("AreaLightSource \"arealight\" 1 \"intensity\" [1 2]"),
       error(2, "AreaLightSource", "\"intensity\" must be one number, found 2 numbers"), [](const Scene&) {}},
  };
}

std::vector<Row> geometry_rows() {
  const auto no_curves = [](const Scene& s) { EXPECT_EQ(s.curves.size(), 0u); };
  const auto widths_not_negative = [](const Scene& s) {
    ASSERT_EQ(s.curves.size(), 2u);
    for (float w : s.curves.width) EXPECT_GE(w, 0.0f);
    EXPECT_FLOAT_EQ(s.curves.width[0], 0.1f);
    EXPECT_EQ(s.curves.width[3], 0.0f) << "the clamped end value";
  };
  return {
      {"curves-nvertices", in_world("Curves \"linear\" [1] \"nonperiodic\" \"P\" [0 0 0]"),
       error(2, "Curves", "nonperiodic linear curve 0 has 1 vertices, needs at least 2"), no_curves},
      {"curves-width-negative", in_world(kLine3 + " \"width\" [0.1 -0.01 -0.02]"),
       warning(2, "Curves", "\"width\" (varying) value 1 is -0.01, negative: clamped to 0 (2 numbers clamped)"),
       widths_not_negative},
      {"curves-width-zero", in_world(kLine3 + " \"width\" [0 0.1 0]"), std::nullopt,
       [](const Scene& s) { EXPECT_EQ(s.curves.size(), 2u); }},
      {"curves-constantwidth-negative", in_world(kLine3 + " \"constantwidth\" [-0.1]"),
       warning(2, "Curves", "\"constantwidth\" -0.1 is negative: clamped to 0"),
       [](const Scene& s) {
         ASSERT_EQ(s.curves.size(), 2u);
         for (float w : s.curves.width) EXPECT_EQ(w, 0.0f);
       }},
      {"curves-constantwidth-count", in_world(kLine3 + " \"constantwidth\" [0.1 0.2]"),
       error(2, "Curves", "\"constantwidth\" must be one number, found 2 numbers"), no_curves},
      {"curves-os", in_world(kLine3 + " \"Os\" [1.5 1 1  0.5 0.5 0.5  -1 0 0]"),
       warning(2, "Curves",
               "\"Os\" (varying) value 0 component 0 is 1.5, outside [0, 1]: clamped to 1 (2 numbers clamped)"),
       [](const Scene& s) {
         ASSERT_EQ(s.curves.size(), 2u);
         EXPECT_EQ(s.curves.opacities(0)[0], (Vec3f{1, 1, 1}));
         EXPECT_EQ(s.curves.opacities(1)[3], (Vec3f{0, 0, 0}));
       }},
      {"curves-cs", in_world(kLine3 + " \"Cs\" [-1 0 0  2 2 2  0 0 0]"), std::nullopt,
       [](const Scene& s) {
         EXPECT_EQ(s.curves.colors(0)[0], (Vec3f{-1, 0, 0}));
       }},
      {"curves-width-count", in_world(kLine3 + " \"width\" [0.1]"),
       error(2, "Curves", "\"width\" (varying) needs 3 floats for 3 values, found 1"), no_curves},
      {"pw-w-zero", in_world("Curves \"linear\" [2] \"nonperiodic\" \"Pw\" [0 0 0 0  1 0 0 1]"),
       error(2, "Curves", "\"Pw\" has a point with w = 0"), no_curves},
      {"curves-world-range",
       in_world("Scale 1e10 1e10 1e10\nCurves \"linear\" [2 2] \"nonperiodic\" \"P\" [0 0 0 1 0 0  0 0 0 1e30 0 0]"),
       warning(3, "Curves", "1 segment (in curve 1) lies beyond the float range in world space: dropped"),
       [](const Scene& s) { EXPECT_EQ(s.curves.size(), 1u) << "the other curve is kept"; }},
      {"sphere-degenerate", in_world("Sphere 0 -1 1 360\nSphere 1 0.5 0.5 360\nSphere 1 -1 1 0"), std::nullopt,
       [](const Scene& s) {
         for (const Sphere& sp : s.surfaces.spheres) EXPECT_TRUE(sp.degenerate);
       }},
      {"sphere-flipped", in_world("Sphere -1 1 -1 -360"), std::nullopt,
       [](const Scene& s) {
         ASSERT_EQ(s.surfaces.spheres.size(), 1u);
         EXPECT_EQ(s.surfaces.spheres[0].radius, 1);
         EXPECT_TRUE(s.surfaces.spheres[0].flip_normal) << "three flips";
       }},
      {"sphere-clip-beyond", in_world("Sphere 1 -5 5 720"), std::nullopt,
       [](const Scene& s) {
         ASSERT_EQ(s.surfaces.spheres.size(), 1u);
         EXPECT_EQ(s.surfaces.spheres[0].zmin, -1);
         EXPECT_EQ(s.surfaces.spheres[0].zmax, 1);
         EXPECT_DOUBLE_EQ(s.surfaces.spheres[0].thetamax, 2 * std::numbers::pi);
       }},
      {"sphere-world-range", in_world("Scale 10 10 10\nSphere 1e38 -1 1 360"),
       error(3, "Sphere", "radius 1e+38 lies beyond the float range in world space"),
       [](const Scene& s) { EXPECT_TRUE(s.surfaces.spheres.empty()); }},
      {"polygon-vertices", in_world("Polygon \"P\" [0 0 0  1 0 0]"),
       error(2, "Polygon", "a polygon needs at least 3 vertices, found 2"),
       [](const Scene& s) { EXPECT_TRUE(s.surfaces.polygons.empty()); }},
      {"pointspolygons-vertices", in_world("PointsPolygons [3 2] [0 1 2  0 1] \"P\" [0 0 0  1 0 0  0 1 0]"),
       error(2, "PointsPolygons", "loop 1 has 2 vertices (at least 3 required)"),
       [](const Scene& s) { EXPECT_TRUE(s.surfaces.polygons.empty()) << "the whole request is skipped"; }},
      {"generalpolygon-points", in_world("GeneralPolygon [3] \"P\" [0 0 0  1 0 0  0 1 0  1 1 0]"),
       error(2, "GeneralPolygon", "the loops have 3 vertices but 4 points are given"),
       [](const Scene& s) { EXPECT_TRUE(s.surfaces.polygons.empty()); }},
      {"pointspolygons-indices", in_world("PointsPolygons [3] [0 1 5] \"P\" [0 0 0  1 0 0  0 1 0]"),
       error(2, "PointsPolygons", "vertex index 5 out of range (3 points)"),
       [](const Scene& s) { EXPECT_TRUE(s.surfaces.polygons.empty()); }},
      {"pointspolygons-unused-points", in_world("PointsPolygons [3] [0 1 2] \"P\" [0 0 0  1 0 0  0 1 0  5 5 5]"),
       std::nullopt, [](const Scene& s) { EXPECT_EQ(s.surfaces.polygons.size(), 1u); }},
      {"pointsgeneralpolygons-nloops", in_world("PointsGeneralPolygons [0] [] [] \"P\" [0 0 0  1 0 0  0 1 0]"),
       error(2, "PointsGeneralPolygons", "face 0 has 0 loops (at least 1 required)"),
       [](const Scene& s) { EXPECT_TRUE(s.surfaces.polygons.empty()); }},
      {"polygon-world-range",
       in_world("Scale 1e10 1e10 1\nPointsPolygons [3 3] [0 1 2  0 2 3] \"P\" [0 0 0  1 0 0  0 1 0  1e30 1 0]"),
       warning(3, "PointsPolygons",
               "1 point lies beyond the float range in world space: the faces that use it are dropped"),
       [](const Scene& s) { EXPECT_EQ(s.surfaces.polygons.size(), 1u) << "the face without that point is kept"; }},
      {"points-p", in_world("Points \"width\" [1]"), error(2, "Points", "Points needs \"P\""),
       [](const Scene& s) { EXPECT_TRUE(s.points.empty()); }},
      {"points-width-negative", in_world("Points \"P\" [0 0 0  1 0 0] \"width\" [0.1 -0.01]"),
       warning(2, "Points", "\"width\" (varying) value 1 is -0.01, negative: clamped to 0 (1 number clamped)"),
       [](const Scene& s) {
         ASSERT_EQ(s.points.size(), 2u);
         EXPECT_EQ(s.points.radius[1], 0.0f);
       }},
      {"points-constantwidth-negative", in_world("Points \"P\" [0 0 0] \"constantwidth\" [-0.1]"),
       warning(2, "Points", "\"constantwidth\" -0.1 is negative: clamped to 0"),
       [](const Scene& s) {
         ASSERT_EQ(s.points.size(), 1u);
         EXPECT_EQ(s.points.radius[0], 0.0f);
       }},
      {"points-os", in_world("Points \"P\" [0 0 0] \"constant color Os\" [0.5 1.5 0.5]"),
       warning(2, "Points",
               "\"Os\" (constant) value 0 component 1 is 1.5, outside [0, 1]: clamped to 1 (1 number clamped)"),
       [](const Scene& s) {
         ASSERT_EQ(s.points.size(), 1u);
         EXPECT_EQ(s.points.opacity(0), (Vec3f{0.5f, 1, 0.5f}));
       }},
      {"points-count", in_world("Points \"P\" [0 0 0  1 0 0] \"width\" [0.1]"),
       error(2, "Points", "\"width\" (varying) needs 2 numbers for 2 values, found 1"),
       [](const Scene& s) { EXPECT_TRUE(s.points.empty()); }},
      {"points-world-range", in_world("Scale 1e30 1e30 1e30\nPoints \"P\" [0 0 0  1e10 0 0] \"constantwidth\" [1e-30]"),
       warning(3, "Points", "1 point lies beyond the float range in world space: dropped"),
       [](const Scene& s) { EXPECT_EQ(s.points.size(), 1u) << "the other point is kept"; }},
  };
}

std::vector<Row> all_rows() {
  std::vector<Row> rows;
  for (auto part :
       {option_rows(), unused_request_rows(), transform_rows(), motion_rows(), attribute_rows(), shader_rows(),
        geometry_rows()})
    rows.insert(rows.end(), part.begin(), part.end());
  return rows;
}

class ParameterValidation : public ::testing::TestWithParam<Row> {};

TEST_P(ParameterValidation, ReportsAndBuildsAsTheTableDecides) {
  const Row& row = GetParam();
  Built b = build(row.rib);
  // Most rows' frames hold no primitive, which WorldEnd reports on its own: not the row's business.
  std::erase_if(b.diagnostics, [](const Diagnostic& d) {
    return d.request == "WorldEnd" && d.message.starts_with("nothing renderable in frame");
  });
  ASSERT_EQ(b.scenes.size(), 1u) << "the frame is still built";
  if (!row.expected) {
    for (const Diagnostic& d : b.diagnostics) ADD_FAILURE() << "a valid value gave " << d.str();
  } else {
    std::string all;
    for (const Diagnostic& d : b.diagnostics) all += "\n  " + d.str();
    ASSERT_EQ(b.diagnostics.size(), 1u) << all;
    const Diagnostic& d = b.diagnostics[0];
    const Expected& e = *row.expected;
    EXPECT_EQ(d.severity, e.severity) << d.str();
    EXPECT_EQ(d.loc.line, e.line) << d.str();
    EXPECT_EQ(d.loc.column, e.column) << d.str();
    EXPECT_EQ(d.request, e.request);
    EXPECT_EQ(d.message, e.message);
    EXPECT_EQ(b.frame_errors[0].count, e.severity == Severity::Error ? 1 : 0) << "warnings fail nothing";
  }
  row.result(b.scenes[0]);
}

INSTANTIATE_TEST_SUITE_P(Table, ParameterValidation, ::testing::ValuesIn(all_rows()),
                         [](const ::testing::TestParamInfo<Row>& info) {
                           std::string name = info.param.id;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

// The table's ID column, in order (the first column of every row that starts with "| `").
std::vector<std::string> table_ids() {
  std::ifstream file(DARC_SOURCE_DIR "/docs/parameters.md");
  std::vector<std::string> ids;
  const std::regex row(R"(^\| `([a-z0-9-]+)` \|)");
  for (std::string line; std::getline(file, line);) {
    std::smatch m;
    if (std::regex_search(line, m, row)) ids.push_back(m[1]);
  }
  return ids;
}

TEST(ParameterValidationTable, EveryRowOfTheTableHasItsTestAndEveryTestItsRow) {
  const std::vector<std::string> ids = table_ids();
  ASSERT_FALSE(ids.empty()) << "docs/parameters.md not found or without rows";
  const std::set<std::string> documented(ids.begin(), ids.end());
  EXPECT_EQ(documented.size(), ids.size()) << "an ID appears twice";
  std::set<std::string> tested;
  for (const Row& r : all_rows()) tested.insert(r.id);
  for (const std::string& id : documented) EXPECT_TRUE(tested.count(id)) << "no test for row " << id;
  for (const std::string& id : tested) EXPECT_TRUE(documented.count(id)) << "no row for test " << id;
}

// The clamping pass over a large Curves call: every negative width of a 100k-strand call is
// clamped, one warning says how many.
TEST(ParameterValidationTable, OneWarningForAllTheNegativeWidthsOfALargeCall) {
  constexpr int kCurves = 100000;
  std::ostringstream rib;
  rib << "WorldBegin\nCurves \"linear\" [";
  for (int i = 0; i < kCurves; ++i) rib << "2 ";
  rib << "] \"nonperiodic\" \"P\" [";
  for (int i = 0; i < kCurves; ++i) rib << i << " 0 0 " << i << " 1 0 ";
  rib << "] \"width\" [";
  for (int i = 0; i < kCurves; ++i) rib << "0.1 -0.1 ";
  rib << "]\nWorldEnd\n";
  Built b = build(rib.str());
  ASSERT_EQ(b.scenes.size(), 1u);
  ASSERT_EQ(b.diagnostics.size(), 1u);
  EXPECT_EQ(b.diagnostics[0].message,
            "\"width\" (varying) value 1 is -0.1, negative: clamped to 0 (100000 numbers clamped)");
  EXPECT_EQ(b.scenes[0].curves.size(), size_t(kCurves));
  for (float w : b.scenes[0].curves.width) ASSERT_GE(w, 0.0f);
}

}  // namespace
}  // namespace darc::test
