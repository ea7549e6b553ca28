#include "parser/known_requests.h"

#include <algorithm>
#include <array>

namespace darc {

namespace {

using O = RequestOrigin;
using K = RequestKind;

// RI Spec 3.2 Appendix C (the RIB binding) and §4-§8; the 3.3/3.4 specs and PRMan's RIB
// documentation (ArchiveBegin, IfBegin, Resource, DisplayChannel, Shader, Volume, ...);
// RenderMan 19-24 (Integrator, Bxdf, Pattern, Light, LightFilter, SampleFilter, DisplayFilter,
// Procedural2, Displace, ...). C-only calls without a RIB form (RiBegin, RiContext,
// RiTransformPoints, ...) are not RIB requests and are left out.
constexpr std::array kKnownRequests = {
    // RI Spec 3.2
    KnownRequest{"version", O::RiSpec32, K::Other},
    KnownRequest{"Declare", O::RiSpec32, K::Other},
    KnownRequest{"FrameBegin", O::RiSpec32, K::Other},
    KnownRequest{"FrameEnd", O::RiSpec32, K::Other},
    KnownRequest{"WorldBegin", O::RiSpec32, K::Other},
    KnownRequest{"WorldEnd", O::RiSpec32, K::Other},
    KnownRequest{"Format", O::RiSpec32, K::Other},
    KnownRequest{"FrameAspectRatio", O::RiSpec32, K::Other},
    KnownRequest{"ScreenWindow", O::RiSpec32, K::Other},
    KnownRequest{"CropWindow", O::RiSpec32, K::Other},
    KnownRequest{"Projection", O::RiSpec32, K::Other},
    KnownRequest{"Clipping", O::RiSpec32, K::Other},
    KnownRequest{"ClippingPlane", O::RiSpec32, K::Other},
    KnownRequest{"DepthOfField", O::RiSpec32, K::Other},
    KnownRequest{"Shutter", O::RiSpec32, K::Other},
    KnownRequest{"PixelVariance", O::RiSpec32, K::Other},
    KnownRequest{"PixelSamples", O::RiSpec32, K::Other},
    KnownRequest{"PixelFilter", O::RiSpec32, K::Other},
    KnownRequest{"Exposure", O::RiSpec32, K::Other},
    KnownRequest{"Imager", O::RiSpec32, K::Other},
    KnownRequest{"Quantize", O::RiSpec32, K::Other},
    KnownRequest{"Display", O::RiSpec32, K::Other},
    KnownRequest{"Hider", O::RiSpec32, K::Other},
    KnownRequest{"ColorSamples", O::RiSpec32, K::Other},
    KnownRequest{"RelativeDetail", O::RiSpec32, K::Other},
    KnownRequest{"Option", O::RiSpec32, K::Other},
    KnownRequest{"AttributeBegin", O::RiSpec32, K::Other},
    KnownRequest{"AttributeEnd", O::RiSpec32, K::Other},
    KnownRequest{"Color", O::RiSpec32, K::Other},
    KnownRequest{"Opacity", O::RiSpec32, K::Other},
    KnownRequest{"TextureCoordinates", O::RiSpec32, K::Other},
    KnownRequest{"LightSource", O::RiSpec32, K::Other},
    KnownRequest{"AreaLightSource", O::RiSpec32, K::Other},
    KnownRequest{"Illuminate", O::RiSpec32, K::Other},
    KnownRequest{"Surface", O::RiSpec32, K::Other},
    KnownRequest{"Displacement", O::RiSpec32, K::Other},
    KnownRequest{"Atmosphere", O::RiSpec32, K::Other},
    KnownRequest{"Interior", O::RiSpec32, K::Other},
    KnownRequest{"Exterior", O::RiSpec32, K::Other},
    KnownRequest{"ShadingRate", O::RiSpec32, K::Other},
    KnownRequest{"ShadingInterpolation", O::RiSpec32, K::Other},
    KnownRequest{"Matte", O::RiSpec32, K::Other},
    KnownRequest{"Bound", O::RiSpec32, K::Other},
    KnownRequest{"Detail", O::RiSpec32, K::Other},
    KnownRequest{"DetailRange", O::RiSpec32, K::Other},
    KnownRequest{"GeometricApproximation", O::RiSpec32, K::Other},
    KnownRequest{"Orientation", O::RiSpec32, K::Other},
    KnownRequest{"ReverseOrientation", O::RiSpec32, K::Other},
    KnownRequest{"Sides", O::RiSpec32, K::Other},
    KnownRequest{"Identity", O::RiSpec32, K::Other},
    KnownRequest{"Transform", O::RiSpec32, K::Other},
    KnownRequest{"ConcatTransform", O::RiSpec32, K::Other},
    KnownRequest{"Perspective", O::RiSpec32, K::Other},
    KnownRequest{"Translate", O::RiSpec32, K::Other},
    KnownRequest{"Rotate", O::RiSpec32, K::Other},
    KnownRequest{"Scale", O::RiSpec32, K::Other},
    KnownRequest{"Skew", O::RiSpec32, K::Other},
    KnownRequest{"Deformation", O::RiSpec32, K::Other},
    KnownRequest{"CoordinateSystem", O::RiSpec32, K::Other},
    KnownRequest{"CoordSysTransform", O::RiSpec32, K::Other},
    KnownRequest{"TransformBegin", O::RiSpec32, K::Other},
    KnownRequest{"TransformEnd", O::RiSpec32, K::Other},
    KnownRequest{"Attribute", O::RiSpec32, K::Other},
    KnownRequest{"Polygon", O::RiSpec32, K::Geometry},
    KnownRequest{"GeneralPolygon", O::RiSpec32, K::Geometry},
    KnownRequest{"PointsPolygons", O::RiSpec32, K::Geometry},
    KnownRequest{"PointsGeneralPolygons", O::RiSpec32, K::Geometry},
    KnownRequest{"Basis", O::RiSpec32, K::Other},
    KnownRequest{"Patch", O::RiSpec32, K::Geometry},
    KnownRequest{"PatchMesh", O::RiSpec32, K::Geometry},
    KnownRequest{"NuPatch", O::RiSpec32, K::Geometry},
    KnownRequest{"TrimCurve", O::RiSpec32, K::Other},
    KnownRequest{"SubdivisionMesh", O::RiSpec32, K::Geometry},
    KnownRequest{"Sphere", O::RiSpec32, K::Geometry},
    KnownRequest{"Cone", O::RiSpec32, K::Geometry},
    KnownRequest{"Cylinder", O::RiSpec32, K::Geometry},
    KnownRequest{"Hyperboloid", O::RiSpec32, K::Geometry},
    KnownRequest{"Paraboloid", O::RiSpec32, K::Geometry},
    KnownRequest{"Disk", O::RiSpec32, K::Geometry},
    KnownRequest{"Torus", O::RiSpec32, K::Geometry},
    KnownRequest{"Points", O::RiSpec32, K::Geometry},
    KnownRequest{"Curves", O::RiSpec32, K::Geometry},
    KnownRequest{"Blobby", O::RiSpec32, K::Geometry},
    KnownRequest{"Procedural", O::RiSpec32, K::Geometry},
    KnownRequest{"Geometry", O::RiSpec32, K::Geometry},
    KnownRequest{"SolidBegin", O::RiSpec32, K::Other},
    KnownRequest{"SolidEnd", O::RiSpec32, K::Other},
    KnownRequest{"ObjectBegin", O::RiSpec32, K::Other},
    KnownRequest{"ObjectEnd", O::RiSpec32, K::Other},
    KnownRequest{"ObjectInstance", O::RiSpec32, K::Other},
    KnownRequest{"MotionBegin", O::RiSpec32, K::Other},
    KnownRequest{"MotionEnd", O::RiSpec32, K::Other},
    KnownRequest{"MakeTexture", O::RiSpec32, K::Other},
    KnownRequest{"MakeBump", O::RiSpec32, K::Other},
    KnownRequest{"MakeLatLongEnvironment", O::RiSpec32, K::Other},
    KnownRequest{"MakeCubeFaceEnvironment", O::RiSpec32, K::Other},
    KnownRequest{"MakeShadow", O::RiSpec32, K::Other},
    KnownRequest{"ErrorHandler", O::RiSpec32, K::Other},
    KnownRequest{"ArchiveRecord", O::RiSpec32, K::Other},
    KnownRequest{"ReadArchive", O::RiSpec32, K::Other},
    // RI Spec 3.3/3.4 and PRMan 12-18
    KnownRequest{"ArchiveBegin", O::RiSpec34, K::Other},
    KnownRequest{"ArchiveEnd", O::RiSpec34, K::Other},
    KnownRequest{"IfBegin", O::RiSpec34, K::Other},
    KnownRequest{"ElseIf", O::RiSpec34, K::Other},
    KnownRequest{"Else", O::RiSpec34, K::Other},
    KnownRequest{"IfEnd", O::RiSpec34, K::Other},
    KnownRequest{"Resource", O::RiSpec34, K::Other},
    KnownRequest{"DisplayChannel", O::RiSpec34, K::Other},
    KnownRequest{"PixelSampleImager", O::RiSpec34, K::Other},
    KnownRequest{"Shader", O::RiSpec34, K::Other},
    KnownRequest{"ShaderLayer", O::RiSpec34, K::Other},
    KnownRequest{"ConnectShaderLayers", O::RiSpec34, K::Other},
    KnownRequest{"VPSurface", O::RiSpec34, K::Other},
    KnownRequest{"VPInterior", O::RiSpec34, K::Other},
    KnownRequest{"VPAtmosphere", O::RiSpec34, K::Other},
    KnownRequest{"MakeBrickMap", O::RiSpec34, K::Other},
    KnownRequest{"HierarchicalSubdivisionMesh", O::RiSpec34, K::Geometry},
    KnownRequest{"Volume", O::RiSpec34, K::Geometry},
    KnownRequest{"System", O::RiSpec34, K::Other},
    KnownRequest{"EditBegin", O::RiSpec34, K::Other},
    KnownRequest{"EditEnd", O::RiSpec34, K::Other},
    KnownRequest{"EditWorldBegin", O::RiSpec34, K::Other},
    KnownRequest{"EditWorldEnd", O::RiSpec34, K::Other},
    KnownRequest{"EditAttributeBegin", O::RiSpec34, K::Other},
    KnownRequest{"EditAttributeEnd", O::RiSpec34, K::Other},
    // RenderMan 19-24 RIB (RIS)
    KnownRequest{"Integrator", O::RenderManRis, K::Other},
    KnownRequest{"Bxdf", O::RenderManRis, K::Other},
    KnownRequest{"Pattern", O::RenderManRis, K::Other},
    KnownRequest{"Light", O::RenderManRis, K::Other},
    KnownRequest{"LightFilter", O::RenderManRis, K::Other},
    KnownRequest{"SampleFilter", O::RenderManRis, K::Other},
    KnownRequest{"DisplayFilter", O::RenderManRis, K::Other},
    KnownRequest{"Displace", O::RenderManRis, K::Other},
    KnownRequest{"Procedural2", O::RenderManRis, K::Geometry},
    KnownRequest{"NuCurves", O::RenderManRis, K::Geometry},
};

}  // namespace

std::optional<KnownRequest> find_known_request(std::string_view name) {
  // A linear scan: it runs once per request name that darc does not implement, and warnings
  // for those are once per name.
  const auto it =
      std::find_if(kKnownRequests.begin(), kKnownRequests.end(), [&](const KnownRequest& r) { return r.name == name; });
  if (it == kKnownRequests.end()) return std::nullopt;
  return *it;
}

std::span<const KnownRequest> known_requests() { return kKnownRequests; }

std::string_view describe(RequestOrigin origin) {
  switch (origin) {
    case RequestOrigin::RiSpec32:
      return "RI Spec 3.2";
    case RequestOrigin::RiSpec34:
      return "RI Spec 3.4 / PRMan";
    case RequestOrigin::RenderManRis:
      return "RenderMan 19+ RIB";
  }
  return "RenderMan";
}

}  // namespace darc
