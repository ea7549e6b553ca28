// The C binding: geometry, procedurals and archives.
#include "ri/c_binding.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace darc;

// RI's variadic geometry requests end their named arguments with a float (thetamax, vmax):
// va_start after a promoted type is what the RI C binding is, and GCC and Clang handle it.
#if defined(__clang__)
#pragma clang diagnostic ignored "-Wvarargs"
#endif

namespace {

std::vector<int> ints(const RtInt* values, RtInt n) {
  if (!values || n <= 0) return {};
  return std::vector<int>(values, values + n);
}

size_t total(const std::vector<int>& counts) {
  size_t sum = 0;
  for (int c : counts) sum += c > 0 ? size_t(c) : 0;
  return sum;
}

// One geometry request through RiTarget::primitive: its fixed arguments, counts, parameters.
void primitive(PrimitiveRequest request, RtInt n, RtToken tokens[], RtPointer values[]) {
  const std::string name = request.name;
  with_session(name.c_str(), [&](RiSession& s, const SourceLoc& loc) {
    const ValueCounts counts = primitive_counts(request, s.ustep(), s.vstep());
    const ParamList params = c_param_list(s, name.c_str(), counts, n, tokens, values, loc);
    s.target().primitive(request, params, loc);
  });
}

PrimitiveRequest quadric(const char* name, std::initializer_list<RtFloat> numbers) {
  PrimitiveRequest r;
  r.name = name;
  for (RtFloat v : numbers) r.numbers.push_back(decimal_double(v));
  return r;
}

std::array<double, 6> bound_values(const RtBound bound) {
  std::array<double, 6> b{};
  for (size_t i = 0; i < 6; ++i) b[i] = decimal_double(bound[i]);
  return b;
}

}  // namespace

extern "C" {

RtVoid RiPolygonV(RtInt nvertices, RtInt n, RtToken tokens[], RtPointer values[]) {
  with_session("Polygon", [&](RiSession& s, const SourceLoc& loc) {
    const ParamList params = c_param_list(s, "Polygon", polygon_counts(nvertices), n, tokens, values, loc);
    s.target().polygon(params, loc);
  });
}
RtVoid RiPolygon(RtInt nvertices, ...) {
  DARC_RI_WITH_TOKEN_VALUES(nvertices, RiPolygonV(nvertices, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiGeneralPolygonV(RtInt nloops, RtInt nverts[], RtInt n, RtToken tokens[], RtPointer values[]) {
  with_session("GeneralPolygon", [&](RiSession& s, const SourceLoc& loc) {
    const std::vector<int> loops = ints(nverts, nloops);
    const ParamList params = c_param_list(s, "GeneralPolygon", general_polygon_counts(loops), n, tokens, values, loc);
    s.target().general_polygon(loops, params, loc);
  });
}
RtVoid RiGeneralPolygon(RtInt nloops, RtInt nverts[], ...) {
  DARC_RI_WITH_TOKEN_VALUES(nverts, RiGeneralPolygonV(nloops, nverts, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiPointsPolygonsV(RtInt npolys, RtInt nverts[], RtInt verts[], RtInt n, RtToken tokens[], RtPointer values[]) {
  with_session("PointsPolygons", [&](RiSession& s, const SourceLoc& loc) {
    const std::vector<int> per_face = ints(nverts, npolys);
    const std::vector<int> indices = ints(verts, RtInt(total(per_face)));
    const ParamList params =
        c_param_list(s, "PointsPolygons", points_polygons_counts(per_face, indices), n, tokens, values, loc);
    s.target().points_polygons(per_face, indices, params, loc);
  });
}
RtVoid RiPointsPolygons(RtInt npolys, RtInt nverts[], RtInt verts[], ...) {
  DARC_RI_WITH_TOKEN_VALUES(verts,
                            RiPointsPolygonsV(npolys, nverts, verts, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiPointsGeneralPolygonsV(RtInt npolys, RtInt nloops[], RtInt nverts[], RtInt verts[], RtInt n,
                                RtToken tokens[], RtPointer values[]) {
  with_session("PointsGeneralPolygons", [&](RiSession& s, const SourceLoc& loc) {
    const std::vector<int> loops_per_face = ints(nloops, npolys);
    const std::vector<int> per_loop = ints(nverts, RtInt(total(loops_per_face)));
    const std::vector<int> indices = ints(verts, RtInt(total(per_loop)));
    const ParamList params = c_param_list(s, "PointsGeneralPolygons",
                                          points_general_polygons_counts(loops_per_face, per_loop, indices), n, tokens,
                                          values, loc);
    s.target().points_general_polygons(loops_per_face, per_loop, indices, params, loc);
  });
}
RtVoid RiPointsGeneralPolygons(RtInt npolys, RtInt nloops[], RtInt nverts[], RtInt verts[], ...) {
  DARC_RI_WITH_TOKEN_VALUES(
      verts, RiPointsGeneralPolygonsV(npolys, nloops, nverts, verts, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiPatchV(RtToken type, RtInt n, RtToken tokens[], RtPointer values[]) {
  PrimitiveRequest r;
  r.name = "Patch";
  r.strings = {type ? type : ""};
  primitive(std::move(r), n, tokens, values);
}
RtVoid RiPatch(RtToken type, ...) { DARC_RI_WITH_TOKEN_VALUES(type, RiPatchV(type, tv.size(), tv.tokens.data(), tv.values.data())); }
RtVoid RiPatchMeshV(RtToken type, RtInt nu, RtToken uwrap, RtInt nv, RtToken vwrap, RtInt n, RtToken tokens[],
                    RtPointer values[]) {
  PrimitiveRequest r;
  r.name = "PatchMesh";
  r.strings = {type ? type : "", uwrap ? uwrap : "", vwrap ? vwrap : ""};
  r.numbers = {double(nu), double(nv)};
  primitive(std::move(r), n, tokens, values);
}
RtVoid RiPatchMesh(RtToken type, RtInt nu, RtToken uwrap, RtInt nv, RtToken vwrap, ...) {
  DARC_RI_WITH_TOKEN_VALUES(vwrap,
                            RiPatchMeshV(type, nu, uwrap, nv, vwrap, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiNuPatchV(RtInt nu, RtInt uorder, RtFloat uknot[], RtFloat umin, RtFloat umax, RtInt nv, RtInt vorder,
                  RtFloat vknot[], RtFloat vmin, RtFloat vmax, RtInt n, RtToken tokens[], RtPointer values[]) {
  PrimitiveRequest r;
  r.name = "NuPatch";
  r.numbers = {double(nu),           double(uorder), decimal_double(umin), decimal_double(umax),
               double(nv),           double(vorder), decimal_double(vmin), decimal_double(vmax)};
  auto knots = [](const RtFloat* k, RtInt count) {
    std::vector<double> out;
    for (RtInt i = 0; k && i < count; ++i) out.push_back(decimal_double(k[i]));
    return out;
  };
  r.number_arrays = {knots(uknot, nu + uorder), knots(vknot, nv + vorder)};
  primitive(std::move(r), n, tokens, values);
}
RtVoid RiNuPatch(RtInt nu, RtInt uorder, RtFloat uknot[], RtFloat umin, RtFloat umax, RtInt nv, RtInt vorder,
                 RtFloat vknot[], RtFloat vmin, RtFloat vmax, ...) {
  DARC_RI_WITH_TOKEN_VALUES(vmax, RiNuPatchV(nu, uorder, uknot, umin, umax, nv, vorder, vknot, vmin, vmax, tv.size(),
                                             tv.tokens.data(), tv.values.data()));
}
RtVoid RiSubdivisionMeshV(RtToken scheme, RtInt nfaces, RtInt nvertices[], RtInt vertices[], RtInt ntags,
                          RtToken tags[], RtInt nargs[], RtInt intargs[], RtFloat floatargs[], RtInt n,
                          RtToken tokens[], RtPointer values[]) {
  PrimitiveRequest r;
  r.name = "SubdivisionMesh";
  r.strings = {scheme ? scheme : ""};
  const std::vector<int> per_face = ints(nvertices, nfaces);
  r.integer_arrays = {per_face, ints(vertices, RtInt(total(per_face)))};
  if (ntags > 0) {
    std::vector<std::string> tag_names;
    for (RtInt i = 0; i < ntags; ++i) tag_names.emplace_back(tags && tags[i] ? tags[i] : "");
    const std::vector<int> counts = ints(nargs, 2 * ntags);  // integers and floats per tag (RI 3.2)
    size_t nint = 0, nfloat = 0;
    for (size_t i = 0; i < counts.size(); i += 2) {
      nint += size_t(std::max(counts[i], 0));
      nfloat += size_t(std::max(counts[i + 1], 0));
    }
    std::vector<double> floats;
    for (size_t i = 0; floatargs && i < nfloat; ++i) floats.push_back(decimal_double(floatargs[i]));
    r.string_arrays = {tag_names};
    r.integer_arrays.push_back(counts);
    r.integer_arrays.push_back(ints(intargs, RtInt(nint)));
    r.number_arrays = {floats};
  }
  primitive(std::move(r), n, tokens, values);
}
RtVoid RiSubdivisionMesh(RtToken scheme, RtInt nfaces, RtInt nvertices[], RtInt vertices[], RtInt ntags,
                         RtToken tags[], RtInt nargs[], RtInt intargs[], RtFloat floatargs[], ...) {
  DARC_RI_WITH_TOKEN_VALUES(floatargs, RiSubdivisionMeshV(scheme, nfaces, nvertices, vertices, ntags, tags, nargs,
                                                          intargs, floatargs, tv.size(), tv.tokens.data(),
                                                          tv.values.data()));
}
RtVoid RiSphereV(RtFloat radius, RtFloat zmin, RtFloat zmax, RtFloat thetamax, RtInt n, RtToken tokens[],
                 RtPointer values[]) {
  primitive(quadric("Sphere", {radius, zmin, zmax, thetamax}), n, tokens, values);
}
RtVoid RiSphere(RtFloat radius, RtFloat zmin, RtFloat zmax, RtFloat thetamax, ...) {
  DARC_RI_WITH_TOKEN_VALUES(thetamax,
                            RiSphereV(radius, zmin, zmax, thetamax, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiConeV(RtFloat height, RtFloat radius, RtFloat thetamax, RtInt n, RtToken tokens[], RtPointer values[]) {
  primitive(quadric("Cone", {height, radius, thetamax}), n, tokens, values);
}
RtVoid RiCone(RtFloat height, RtFloat radius, RtFloat thetamax, ...) {
  DARC_RI_WITH_TOKEN_VALUES(thetamax, RiConeV(height, radius, thetamax, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiCylinderV(RtFloat radius, RtFloat zmin, RtFloat zmax, RtFloat thetamax, RtInt n, RtToken tokens[],
                   RtPointer values[]) {
  primitive(quadric("Cylinder", {radius, zmin, zmax, thetamax}), n, tokens, values);
}
RtVoid RiCylinder(RtFloat radius, RtFloat zmin, RtFloat zmax, RtFloat thetamax, ...) {
  DARC_RI_WITH_TOKEN_VALUES(thetamax,
                            RiCylinderV(radius, zmin, zmax, thetamax, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiHyperboloidV(RtPoint point1, RtPoint point2, RtFloat thetamax, RtInt n, RtToken tokens[],
                      RtPointer values[]) {
  primitive(quadric("Hyperboloid", {point1[0], point1[1], point1[2], point2[0], point2[1], point2[2], thetamax}), n,
            tokens, values);
}
RtVoid RiHyperboloid(RtPoint point1, RtPoint point2, RtFloat thetamax, ...) {
  DARC_RI_WITH_TOKEN_VALUES(thetamax,
                            RiHyperboloidV(point1, point2, thetamax, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiParaboloidV(RtFloat rmax, RtFloat zmin, RtFloat zmax, RtFloat thetamax, RtInt n, RtToken tokens[],
                     RtPointer values[]) {
  primitive(quadric("Paraboloid", {rmax, zmin, zmax, thetamax}), n, tokens, values);
}
RtVoid RiParaboloid(RtFloat rmax, RtFloat zmin, RtFloat zmax, RtFloat thetamax, ...) {
  DARC_RI_WITH_TOKEN_VALUES(thetamax,
                            RiParaboloidV(rmax, zmin, zmax, thetamax, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiDiskV(RtFloat height, RtFloat radius, RtFloat thetamax, RtInt n, RtToken tokens[], RtPointer values[]) {
  primitive(quadric("Disk", {height, radius, thetamax}), n, tokens, values);
}
RtVoid RiDisk(RtFloat height, RtFloat radius, RtFloat thetamax, ...) {
  DARC_RI_WITH_TOKEN_VALUES(thetamax, RiDiskV(height, radius, thetamax, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiTorusV(RtFloat majorradius, RtFloat minorradius, RtFloat phimin, RtFloat phimax, RtFloat thetamax, RtInt n,
                RtToken tokens[], RtPointer values[]) {
  primitive(quadric("Torus", {majorradius, minorradius, phimin, phimax, thetamax}), n, tokens, values);
}
RtVoid RiTorus(RtFloat majorradius, RtFloat minorradius, RtFloat phimin, RtFloat phimax, RtFloat thetamax, ...) {
  DARC_RI_WITH_TOKEN_VALUES(thetamax, RiTorusV(majorradius, minorradius, phimin, phimax, thetamax, tv.size(),
                                               tv.tokens.data(), tv.values.data()));
}
RtVoid RiPointsV(RtInt npoints, RtInt n, RtToken tokens[], RtPointer values[]) {
  with_session("Points", [&](RiSession& s, const SourceLoc& loc) {
    PrimitiveRequest r;
    r.name = "Points";
    const ParamList params = c_param_list(s, "Points", points_counts(npoints), n, tokens, values, loc);
    s.target().primitive(r, params, loc);
  });
}
RtVoid RiPoints(RtInt npoints, ...) {
  DARC_RI_WITH_TOKEN_VALUES(npoints, RiPointsV(npoints, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiCurvesV(RtToken type, RtInt ncurves, RtInt nvertices[], RtToken wrap, RtInt n, RtToken tokens[],
                 RtPointer values[]) {
  with_session("Curves", [&](RiSession& s, const SourceLoc& loc) {
    const std::string curve_type = type ? type : "", wrap_mode = wrap ? wrap : "";
    const std::vector<int> per_curve = ints(nvertices, ncurves);
    const ValueCounts counts = curves_counts(curve_type, per_curve, wrap_mode, s.vstep());
    const ParamList params = c_param_list(s, "Curves", counts, n, tokens, values, loc);
    s.target().curves(curve_type, per_curve, wrap_mode, params, loc);
  });
}
RtVoid RiCurves(RtToken type, RtInt ncurves, RtInt nvertices[], RtToken wrap, ...) {
  DARC_RI_WITH_TOKEN_VALUES(wrap,
                            RiCurvesV(type, ncurves, nvertices, wrap, tv.size(), tv.tokens.data(), tv.values.data()));
}

// --- procedurals ---

// Called by RiProcedural's expansion only by name (RiProcedural recognises them); a program
// calling one itself from its own subdivide function gets what the name says.
RtVoid RiProcDelayedReadArchive(RtPointer data, RtFloat) {
  const auto* strings = static_cast<const RtString*>(data);
  RiReadArchive(strings && strings[0] ? strings[0] : "", nullptr, RI_NULL);
}
RtVoid RiProcRunProgram(RtPointer, RtFloat) {
  with_session("Procedural", [](RiSession& s, const SourceLoc& loc) {
    s.diagnostics().warning(loc, "Procedural", "RiProcRunProgram called directly (not through RiProcedural): skipped");
  });
}
RtVoid RiProcDynamicLoad(RtPointer, RtFloat) {
  with_session("Procedural", [](RiSession& s, const SourceLoc& loc) {
    s.diagnostics().warning(loc, "Procedural", "DynamicLoad procedurals are not supported: skipped");
  });
}
RtVoid RiProcFree(RtPointer data) { std::free(data); }

RtVoid RiProcedural(RtPointer data, RtBound bound, RtProcSubdivFunc subdivide, RtProcFreeFunc free_data) {
  with_session("Procedural", [&](RiSession& s, const SourceLoc& loc) {
    const auto* strings = static_cast<const RtString*>(data);
    auto string_at = [&](int i) -> std::string { return strings && strings[i] ? strings[i] : ""; };
    if (subdivide == RiProcDelayedReadArchive) {
      s.delayed_read_archive(string_at(0), bound_values(bound), loc);
    } else if (subdivide == RiProcRunProgram) {
      s.run_program(string_at(0), string_at(1), bound_values(bound), loc);
    } else if (subdivide == RiProcDynamicLoad || !subdivide) {
      s.diagnostics().warning(loc, "Procedural",
                              "DynamicLoad procedurals (and a null subdivide function) are not supported: skipped");
    } else {
      s.expand_procedural(bound_values(bound), [&](double detail) {
        subdivide(data, detail > 0 ? RtFloat(detail) : RI_INFINITY);
      }, loc);
    }
  });
  if (free_data) free_data(data);
}

// --- archives ---

RtVoid RiReadArchiveV(RtToken name, RtArchiveCallback, RtInt, RtToken[], RtPointer[]) {
  with_session("ReadArchive", [&](RiSession& s, const SourceLoc& loc) {
    s.read_archive(name ? name : "", loc);
  });
}
RtVoid RiReadArchive(RtToken name, RtArchiveCallback callback, ...) {
  DARC_RI_WITH_TOKEN_VALUES(callback, RiReadArchiveV(name, callback, tv.size(), tv.tokens.data(), tv.values.data()));
}
RtVoid RiArchiveRecord(RtToken type, const char* format, ...) {
  va_list args, again;
  va_start(args, format);
  va_copy(again, args);
  const int size = std::vsnprintf(nullptr, 0, format ? format : "", args);
  std::string text(size_t(std::max(size, 0)) + 1, '\0');
  std::vsnprintf(text.data(), text.size(), format ? format : "", again);
  text.resize(size_t(std::max(size, 0)));
  va_end(again);
  va_end(args);
  with_session("ArchiveRecord", [&](RiSession& s, const SourceLoc& loc) {
    s.target().ignored_request("ArchiveRecord", {}, {type ? type : "comment", text}, loc);
  });
}

}  // extern "C"
