// The C binding: attributes, shaders and lights, transforms, instancing.
#include "ri/c_binding.h"

#include <cstdint>
#include <cstring>

using namespace darc;

namespace {

// A request accepted without effect: its string and number arguments, as the parser passes them.
void ignored(const char* request, std::vector<std::string> strings, std::vector<double> numbers) {
  with_session(request, [&](RiSession& s, const SourceLoc& loc) {
    s.target().ignored_request(request, numbers, strings, loc);
  });
}

void ris_node(const char* request, RtToken name, RtToken handle, RtInt n, RtToken tokens[], RtPointer values[],
              void (RiTarget::*method)(const std::string&, const std::string&, const ParamList&, const SourceLoc&)) {
  with_session(request, [&](RiSession& s, const SourceLoc& loc) {
    const ParamList params = c_param_list(s, request, single_values(), n, tokens, values, loc);
    (s.target().*method)(name ? name : "", handle ? handle : "", params, loc);
  });
}

// A handle returned to C: the number of the light or object, as a pointer-sized integer
// (handles count from 1, so no handle is null).
RtPointer handle_pointer(const std::string& handle) {
  return reinterpret_cast<RtPointer>(static_cast<std::uintptr_t>(std::stoull(handle)));
}
std::string handle_name(RtPointer handle) {
  return std::to_string(static_cast<unsigned long long>(reinterpret_cast<std::uintptr_t>(handle)));
}

RtLightHandle light(const char* request, RtToken name, RtInt n, RtToken tokens[], RtPointer values[],
                    void (RiTarget::*method)(const std::string&, const std::string&, const ParamList&,
                                             const SourceLoc&)) {
  RtLightHandle result = nullptr;
  with_session(request, [&](RiSession& s, const SourceLoc& loc) {
    const std::string handle = s.next_handle();
    result = handle_pointer(handle);
    const ParamList params = c_param_list(s, request, single_values(), n, tokens, values, loc);
    (s.target().*method)(name ? name : "", handle, params, loc);
  });
  return result;
}

std::array<double, 16> matrix(const RtMatrix m) {
  std::array<double, 16> out{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[size_t(r * 4 + c)] = decimal_double(m[r][c]);
  return out;
}

// A basis by name when it is one of the standard ones (as RIB names it), else its matrix.
BasisArg basis_arg(const RtBasis b) {
  const struct {
    const RtBasis* basis;
    const char* name;
  } standard[] = {{&RiBezierBasis, "bezier"},
                  {&RiBSplineBasis, "b-spline"},
                  {&RiCatmullRomBasis, "catmull-rom"},
                  {&RiHermiteBasis, "hermite"},
                  {&RiPowerBasis, "power"}};
  BasisArg arg;
  for (const auto& s : standard)
    if (std::memcmp(*s.basis, b, sizeof(RtBasis)) == 0) {
      arg.name = s.name;
      return arg;
    }
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) arg.matrix[size_t(r * 4 + c)] = decimal_double(b[r][c]);
  return arg;
}

}  // namespace

extern "C" {

RtVoid RiAttributeV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]) {
  with_session("Attribute", [&](RiSession& s, const SourceLoc& loc) {
    const ParamList params = c_param_list(s, "Attribute", single_values(), n, tokens, values, loc);
    s.attribute(name ? name : "", params, loc);
  });
}
RtVoid RiAttribute(RtToken name, ...) { DARC_RI_WITH_TOKEN_VALUES(name, RiAttributeV(name, tv.size(), tv.tokens.data(), tv.values.data())); }
RtVoid RiColor(RtColor color) {
  with_session("Color", [&](RiSession& s, const SourceLoc& loc) { s.target().color({color[0], color[1], color[2]}, loc); });
}
RtVoid RiOpacity(RtColor opacity) {
  with_session("Opacity",
               [&](RiSession& s, const SourceLoc& loc) { s.target().opacity({opacity[0], opacity[1], opacity[2]}, loc); });
}
RtVoid RiSurfaceV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]) {
  name_and_params("Surface", name, n, tokens, values, &RiTarget::surface);
}
RtVoid RiSurface(RtToken name, ...) { DARC_RI_WITH_TOKEN_VALUES(name, RiSurfaceV(name, tv.size(), tv.tokens.data(), tv.values.data())); }
RtVoid RiDisplacementV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]) {
  name_and_params("Displacement", name, n, tokens, values, &RiTarget::displacement);
}
RtVoid RiDisplacement(RtToken name, ...) {
  DARC_RI_WITH_TOKEN_VALUES(name, RiDisplacementV(name, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiAtmosphereV(RtToken name, RtInt, RtToken[], RtPointer[]) { ignored("Atmosphere", {name ? name : ""}, {}); }
RtVoid RiAtmosphere(RtToken name, ...) { RiAtmosphereV(name, 0, nullptr, nullptr); }
RtVoid RiInteriorV(RtToken name, RtInt, RtToken[], RtPointer[]) { ignored("Interior", {name ? name : ""}, {}); }
RtVoid RiInterior(RtToken name, ...) { RiInteriorV(name, 0, nullptr, nullptr); }
RtVoid RiExteriorV(RtToken name, RtInt, RtToken[], RtPointer[]) { ignored("Exterior", {name ? name : ""}, {}); }
RtVoid RiExterior(RtToken name, ...) { RiExteriorV(name, 0, nullptr, nullptr); }
RtLightHandle RiLightSourceV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]) {
  return light("LightSource", name, n, tokens, values, &RiTarget::light_source);
}
RtLightHandle RiLightSource(RtToken name, ...) {
  DARC_RI_WITH_TOKEN_VALUES(name, return RiLightSourceV(name, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtLightHandle RiAreaLightSourceV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]) {
  return light("AreaLightSource", name, n, tokens, values, &RiTarget::area_light_source);
}
RtLightHandle RiAreaLightSource(RtToken name, ...) {
  DARC_RI_WITH_TOKEN_VALUES(name, return RiAreaLightSourceV(name, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiIlluminate(RtLightHandle light_handle, RtBoolean on) {
  with_session("Illuminate", [&](RiSession& s, const SourceLoc& loc) {
    s.target().illuminate(handle_name(light_handle), on != 0, loc);
  });
}
RtVoid RiSides(RtInt sides) {
  with_session("Sides", [&](RiSession& s, const SourceLoc& loc) { s.target().sides(sides, loc); });
}
RtVoid RiOrientation(RtToken orientation) {
  with_session("Orientation",
               [&](RiSession& s, const SourceLoc& loc) { s.target().orientation(orientation ? orientation : "", loc); });
}
RtVoid RiReverseOrientation(void) {
  with_session("ReverseOrientation", [](RiSession& s, const SourceLoc& loc) { s.target().reverse_orientation(loc); });
}
RtVoid RiBasis(RtBasis ubasis, RtInt ustep, RtBasis vbasis, RtInt vstep) {
  with_session("Basis", [&](RiSession& s, const SourceLoc& loc) {
    s.target().basis(basis_arg(ubasis), ustep, basis_arg(vbasis), vstep, loc);
  });
}
RtVoid RiMatte(RtBoolean onoff) { ignored("Matte", {}, {double(onoff)}); }
RtVoid RiShadingRate(RtFloat size) { ignored("ShadingRate", {}, {decimal_double(size)}); }
RtVoid RiShadingInterpolation(RtToken type) { ignored("ShadingInterpolation", {type ? type : ""}, {}); }
RtVoid RiGeometricApproximation(RtToken type, RtFloat value) {
  ignored("GeometricApproximation", {type ? type : ""}, {decimal_double(value)});
}
RtVoid RiDetail(RtBound bound) {
  std::vector<double> b;
  for (int i = 0; i < 6; ++i) b.push_back(decimal_double(bound[i]));
  ignored("Detail", {}, b);
}
RtVoid RiDetailRange(RtFloat minvisible, RtFloat lowertransition, RtFloat uppertransition, RtFloat maxvisible) {
  ignored("DetailRange", {},
          {decimal_double(minvisible), decimal_double(lowertransition), decimal_double(uppertransition),
           decimal_double(maxvisible)});
}
RtVoid RiRelativeDetail(RtFloat relativedetail) { ignored("RelativeDetail", {}, {decimal_double(relativedetail)}); }
RtVoid RiBound(RtBound bound) {
  std::vector<double> b;
  for (int i = 0; i < 6; ++i) b.push_back(decimal_double(bound[i]));
  ignored("Bound", {}, b);
}
RtVoid RiTextureCoordinates(RtFloat s1, RtFloat t1, RtFloat s2, RtFloat t2, RtFloat s3, RtFloat t3, RtFloat s4,
                            RtFloat t4) {
  ignored("TextureCoordinates", {},
          {decimal_double(s1), decimal_double(t1), decimal_double(s2), decimal_double(t2), decimal_double(s3),
           decimal_double(t3), decimal_double(s4), decimal_double(t4)});
}

// --- RIS shading ---

RtVoid RiBxdfV(RtToken name, RtToken handle, RtInt n, RtToken tokens[], RtPointer values[]) {
  ris_node("Bxdf", name, handle, n, tokens, values, &RiTarget::bxdf);
}
RtVoid RiBxdf(RtToken name, RtToken handle, ...) {
  DARC_RI_WITH_TOKEN_VALUES(handle, RiBxdfV(name, handle, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiPatternV(RtToken name, RtToken handle, RtInt n, RtToken tokens[], RtPointer values[]) {
  ris_node("Pattern", name, handle, n, tokens, values, &RiTarget::pattern);
}
RtVoid RiPattern(RtToken name, RtToken handle, ...) {
  DARC_RI_WITH_TOKEN_VALUES(handle, RiPatternV(name, handle, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiLightV(RtToken name, RtToken handle, RtInt n, RtToken tokens[], RtPointer values[]) {
  ris_node("Light", name, handle, n, tokens, values, &RiTarget::light);
}
RtVoid RiLight(RtToken name, RtToken handle, ...) {
  DARC_RI_WITH_TOKEN_VALUES(handle, RiLightV(name, handle, tv.size(), tv.tokens.data(), tv.values.data()));
}

// --- transforms ---

RtVoid RiIdentity(void) {
  with_session("Identity", [](RiSession& s, const SourceLoc& loc) { s.target().identity(loc); });
}
RtVoid RiTransform(RtMatrix transform) {
  with_session("Transform", [&](RiSession& s, const SourceLoc& loc) { s.target().transform(matrix(transform), loc); });
}
RtVoid RiConcatTransform(RtMatrix transform) {
  with_session("ConcatTransform",
               [&](RiSession& s, const SourceLoc& loc) { s.target().concat_transform(matrix(transform), loc); });
}
RtVoid RiPerspective(RtFloat fov) {
  with_session("Perspective", [&](RiSession& s, const SourceLoc& loc) { s.target().perspective(decimal_double(fov), loc); });
}
RtVoid RiTranslate(RtFloat dx, RtFloat dy, RtFloat dz) {
  with_session("Translate", [&](RiSession& s, const SourceLoc& loc) {
    s.target().translate(decimal_double(dx), decimal_double(dy), decimal_double(dz), loc);
  });
}
RtVoid RiRotate(RtFloat angle, RtFloat dx, RtFloat dy, RtFloat dz) {
  with_session("Rotate", [&](RiSession& s, const SourceLoc& loc) {
    s.target().rotate(decimal_double(angle), decimal_double(dx), decimal_double(dy), decimal_double(dz), loc);
  });
}
RtVoid RiScale(RtFloat sx, RtFloat sy, RtFloat sz) {
  with_session("Scale", [&](RiSession& s, const SourceLoc& loc) {
    s.target().scale(decimal_double(sx), decimal_double(sy), decimal_double(sz), loc);
  });
}
RtVoid RiSkew(RtFloat angle, RtFloat dx1, RtFloat dy1, RtFloat dz1, RtFloat dx2, RtFloat dy2, RtFloat dz2) {
  ignored("Skew", {},
          {decimal_double(angle), decimal_double(dx1), decimal_double(dy1), decimal_double(dz1), decimal_double(dx2),
           decimal_double(dy2), decimal_double(dz2)});
}
RtVoid RiCoordinateSystem(RtToken space) {
  with_session("CoordinateSystem",
               [&](RiSession& s, const SourceLoc& loc) { s.target().coordinate_system(space ? space : "", loc); });
}
RtVoid RiScopedCoordinateSystem(RtToken space) {
  with_session("ScopedCoordinateSystem", [&](RiSession& s, const SourceLoc& loc) {
    s.target().scoped_coordinate_system(space ? space : "", loc);
  });
}
RtVoid RiCoordSysTransform(RtToken space) {
  with_session("CoordSysTransform",
               [&](RiSession& s, const SourceLoc& loc) { s.target().coord_sys_transform(space ? space : "", loc); });
}

// --- instancing ---

RtObjectHandle RiObjectBegin(void) {
  RtObjectHandle result = nullptr;
  with_session("ObjectBegin", [&](RiSession& s, const SourceLoc& loc) {
    const std::string handle = s.next_handle();
    result = handle_pointer(handle);
    s.target().object_begin(handle, loc);
  });
  return result;
}
RtVoid RiObjectEnd(void) {
  with_session("ObjectEnd", [](RiSession& s, const SourceLoc& loc) { s.target().object_end(loc); });
}
RtVoid RiObjectInstance(RtObjectHandle handle) {
  with_session("ObjectInstance",
               [&](RiSession& s, const SourceLoc& loc) { s.target().object_instance(handle_name(handle), loc); });
}

}  // extern "C"
