// The C binding's own behaviour: how many values a bare pointer holds, errors through the error
// handlers with the call's position, procedurals of the program's own, declarations, archives,
// several contexts, and calls outside any context.
#include "ri/ri.h"
#include "ri/value_counts.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "parser/diagnostics.h"
#include "support/darc_command.h"

namespace darc::test {
namespace {

TEST(ValueCounts, CurvesFollowTheBasisStepAndWrap) {
  const std::vector<int> two_bsplines{6, 6};
  const ValueCounts b = curves_counts("cubic", two_bsplines, "nonperiodic", 1);
  EXPECT_EQ(b.uniform, 2u);
  EXPECT_EQ(b.varying, 8u);  // (6 - 4) / 1 + 1 = 3 segments, 4 ends per curve
  EXPECT_EQ(b.vertex, 12u);
  EXPECT_EQ(b.of(StorageClass::FaceVertex), 12u);  // curves: as vertex
  EXPECT_EQ(b.of(StorageClass::FaceVarying), 8u);  // curves: as varying
  const std::vector<int> bezier{7};
  EXPECT_EQ(curves_counts("cubic", bezier, "nonperiodic", 3).varying, 3u);
  const std::vector<int> ring{6};
  EXPECT_EQ(curves_counts("cubic", ring, "periodic", 1).varying, 6u);
  const std::vector<int> lines{3, 4};
  EXPECT_EQ(curves_counts("linear", lines, "nonperiodic", 3).varying, 7u);
  const std::vector<int> bad{5};
  EXPECT_THROW(curves_counts("cubic", bad, "nonperiodic", 3), RibError);
  EXPECT_THROW(curves_counts("quintic", bad, "nonperiodic", 3), RibError);
}

TEST(ValueCounts, MeshesCountFacesPointsAndCorners) {
  const std::vector<int> nverts{3, 3}, indices{0, 1, 2, 2, 1, 3};
  const ValueCounts m = points_polygons_counts(nverts, indices);
  EXPECT_EQ(m.uniform, 2u);
  EXPECT_EQ(m.vertex, 4u);
  EXPECT_EQ(m.facevarying, 6u);
  EXPECT_EQ(m.of(StorageClass::FaceVertex), 6u);
  EXPECT_EQ(m.of(StorageClass::Constant), 1u);
  const std::vector<int> short_indices{0, 1, 2};
  EXPECT_THROW(points_polygons_counts(nverts, short_indices), RibError);
  EXPECT_EQ(polygon_counts(5).vertex, 5u);
  PrimitiveRequest mesh;
  mesh.name = "PatchMesh";
  mesh.strings = {"bicubic", "nonperiodic", "nonperiodic"};
  mesh.numbers = {7, 4};  // with step 3: 2 x 1 patches
  const ValueCounts p = primitive_counts(mesh, 3, 3);
  EXPECT_EQ(p.uniform, 2u);
  EXPECT_EQ(p.varying, 6u);
  EXPECT_EQ(p.vertex, 28u);
  PrimitiveRequest sphere;
  sphere.name = "Sphere";
  EXPECT_EQ(primitive_counts(sphere, 3, 3).varying, 4u);
}

// Diagnostics a handler was given.
struct Reported {
  RtInt code, severity;
  std::string message;
};
std::vector<Reported>& reported() {
  static std::vector<Reported> all;
  return all;
}
void collect(RtInt code, RtInt severity, const char* message) { reported().push_back({code, severity, message}); }

TEST(CBindingErrors, AnUndeclaredTokenIsAnErrorAtItsCallAndTheRestOfTheCallStays) {
  ScratchDir dir("c_binding_errors");
  reported().clear();
  const std::string rib = (dir / "out.rib").string();
  RiBegin(rib.c_str());
  RiErrorHandler(collect);  // call 1
  RiWorldBegin();           // call 2
  RtFloat p[] = {0, 0, 0, 1, 0, 0, 1, 1, 0};
  RtFloat mystery[] = {1, 2, 3};
  RiPolygon(3, RI_P, p, "mystery", mystery, RI_NULL);  // call 3
  RiWorldEnd();
  RiEnd();
  ASSERT_EQ(reported().size(), 1u);
  EXPECT_EQ(reported()[0].severity, RIE_ERROR);
  EXPECT_EQ(reported()[0].code, RIE_CONSISTENCY);
  EXPECT_NE(reported()[0].message.find("<ri call 3>:1:1"), std::string::npos) << reported()[0].message;
  EXPECT_NE(reported()[0].message.find("mystery"), std::string::npos);
  const std::string text = read_text_file(rib);
  EXPECT_NE(text.find("Polygon \"vertex point P\" [0 0 0 1 0 0 1 1 0]"), std::string::npos) << text;
  EXPECT_EQ(text.find("mystery"), std::string::npos);
}

TEST(CBindingErrors, UnderAbortNothingIsWrittenAndLaterCallsAreIgnored) {
  ScratchDir dir("c_binding_abort");
  reported().clear();
  const std::string rib = (dir / "out.rib").string();
  RiBegin(rib.c_str());
  RiErrorHandler(RiErrorAbort);
  RiWorldBegin();
  RtInt three[] = {3};
  RtFloat p[] = {0, 0, 0, 1, 0, 0, 1, 1, 0};
  RiCurves(RI_CUBIC, 1, three, RI_NONPERIODIC, RI_P, p, RI_NULL);  // 3 points make no cubic curve
  RiSphere(1, -1, 1, 360, RI_NULL);
  RiWorldEnd();
  RiEnd();
  EXPECT_TRUE(file_names(dir.path()).empty()) << "a RIB cut short by the abort handler was left";
}

TEST(CBindingErrors, AFrameOverTheMemoryLimitFailsAloneAndTheProgramGoesOn) {
  ScratchDir dir("c_binding_memory_limit");
  reported().clear();
  RiBegin("darc --memory-limit 4G");
  RiErrorHandler(collect);
  for (int frame = 1; frame <= 2; ++frame) {
    RiFrameBegin(frame);
    RiFormat(frame == 1 ? 16384 : 32, frame == 1 ? 16384 : 24, 1);  // frame 1's image: 32 GB
    RiDisplay((dir / "f.#.exr").string().c_str(), "openexr", "rgba", RI_NULL);
    RiProjection(RI_PERSPECTIVE, RI_NULL);
    RiTranslate(0, 0, 5);
    RiWorldBegin();
    RiSphere(1, -1, 1, 360, RI_NULL);
    RiWorldEnd();
    RiFrameEnd();
  }
  RiEnd();
  ASSERT_FALSE(reported().empty());
  EXPECT_NE(reported()[0].message.find("error: Sphere: the frame would need about 32.0 GB"), std::string::npos)
      << reported()[0].message;
  EXPECT_FALSE(fs::exists(dir / "f.1.exr"));
  EXPECT_TRUE(fs::exists(dir / "f.2.exr")) << "the next frame renders";
}

TEST(CBindingErrors, CallsOutsideAContextDoNothing) {
  RiWorldBegin();
  RtFloat p[] = {0, 0, 0, 1, 0, 0, 1, 1, 0};
  RiPolygon(3, RI_P, p, RI_NULL);
  RiEnd();
  EXPECT_EQ(RiGetContext(), nullptr);
}

int subdivisions = 0, frees = 0;
RtFloat last_detail = 0;
void make_sphere(RtPointer data, RtFloat detail) {
  ++subdivisions;
  last_detail = detail;
  RiSphere(*static_cast<RtFloat*>(data), -1, 1, 360, RI_NULL);
}
void count_free(RtPointer) { ++frees; }

TEST(CBindingProcedurals, AProgramsOwnFunctionIsCalledInsideAnAttributeBlock) {
  ScratchDir dir("c_binding_procedural");
  subdivisions = frees = 0;
  const std::string rib = (dir / "out.rib").string();
  RiBegin(rib.c_str());
  RiWorldBegin();
  RtFloat radius = 0.25f;
  RtBound bound = {-1, 1, -1, 1, -1, 1};
  RiProcedural(&radius, bound, make_sphere, count_free);
  RiWorldEnd();
  RiEnd();
  EXPECT_EQ(subdivisions, 1);
  EXPECT_EQ(frees, 1);
  EXPECT_EQ(last_detail, RI_INFINITY);  // a RIB file has no image to measure the bound in
  const std::string text = read_text_file(rib);
  EXPECT_NE(text.find("AttributeBegin\n    Sphere 0.25 -1 1 360\n  AttributeEnd"), std::string::npos) << text;
}

TEST(CBindingProcedurals, WhenRenderingTheDetailIsTheBoundsAreaInTheImage) {
  ScratchDir dir("c_binding_procedural_render");
  subdivisions = frees = 0;
  RiBegin(RI_NULL);
  RiFormat(32, 24, 1);
  RiDisplay((dir / "out.exr").string().c_str(), "openexr", "rgba", RI_NULL);
  RiProjection(RI_PERSPECTIVE, RI_NULL);  // 90 degrees over the 24 rows: 12 pixels per unit at distance 1
  RiTranslate(0, 0, 5);
  RiWorldBegin();
  RtFloat radius = 1;
  RtBound bound = {-1, 1, -1, 1, -1, 1};
  RiProcedural(&radius, bound, make_sphere, count_free);
  EXPECT_EQ(subdivisions, 1);
  // The box's near face (z = 4) spans 2 * 12 / 4 = 6 pixels each way: 36 square pixels.
  EXPECT_NEAR(last_detail, 36.0f, 1e-3f);
  RiWorldEnd();
  RiEnd();
  EXPECT_EQ(frees, 1);
  Pixels image;
  ASSERT_TRUE(read_image(dir / "out.exr", image));
  EXPECT_GT(image.at(16, 12, 3), 0.99f);  // the sphere in the middle
  EXPECT_EQ(image.at(2, 2, 3), 0.0f);
}

TEST(CBindingRequests, DeclarationsArchivesAndDelayedArchivesGoThroughTheParser) {
  ScratchDir dir("c_binding_parser_requests");
  write_file(dir / "part.rib", "Declare \"fromarchive\" \"uniform float\"\nSphere 2 -2 2 360\n");
  const std::string rib = (dir / "out.rib").string();
  RiBegin(rib.c_str());
  RtToken tint = RiDeclare("tint", "uniform color");
  RtColor red = {1, 0, 0};
  RiAttribute("user", tint, red, RI_NULL);
  RiWorldBegin();
  RiReadArchive((dir / "part.rib").string().c_str(), nullptr, RI_NULL);
  RtFloat one = 1;
  RiAttribute("user", "fromarchive", &one, RI_NULL);  // declared by the archive
  const std::string part = (dir / "part.rib").string();
  RtString args[] = {part.c_str()};
  RtBound bound = {-2, 2, -2, 2, -2, 2};
  RiProcedural(args, bound, RiProcDelayedReadArchive, nullptr);
  RiWorldEnd();
  RiEnd();
  const std::string text = read_text_file(rib);
  EXPECT_NE(text.find("Attribute \"user\" \"uniform color tint\" [1 0 0]"), std::string::npos) << text;
  EXPECT_NE(text.find("Attribute \"user\" \"uniform float fromarchive\" [1]"), std::string::npos) << text;
  // The archive read twice: once by ReadArchive, once by the delayed procedural.
  size_t spheres = 0;
  for (size_t at = text.find("Sphere 2 -2 2 360"); at != std::string::npos; at = text.find("Sphere 2 -2 2 360", at + 1))
    ++spheres;
  EXPECT_EQ(spheres, 2u) << text;
}

TEST(CBindingRequests, VaryingValuesFollowTheBasisStepInEffect) {
  ScratchDir dir("c_binding_basis_steps");
  const std::string rib = (dir / "out.rib").string();
  RiBegin(rib.c_str());
  RiWorldBegin();
  RiObjectBegin();  // a Basis recorded in an object does not last past it
  ::RiBasis(RiBSplineBasis, RI_BSPLINESTEP, RiBSplineBasis, RI_BSPLINESTEP);
  RiObjectEnd();
  RiAttributeBegin();
  ::RiBasis(RiCatmullRomBasis, RI_CATMULLROMSTEP, RiCatmullRomBasis, RI_CATMULLROMSTEP);
  RiAttributeEnd();
  RtInt seven[] = {7};
  RtFloat p[21] = {};
  RtFloat widths[] = {0.1f, 0.2f, 0.3f};  // Bezier, step 3: 2 segments, 3 ends
  RiCurves(RI_CUBIC, 1, seven, RI_NONPERIODIC, RI_P, p, RI_WIDTH, widths, RI_NULL);
  RiAttributeBegin();
  ::RiBasis(RiBSplineBasis, RI_BSPLINESTEP, RiBSplineBasis, RI_BSPLINESTEP);
  RtFloat bspline_widths[] = {1, 2, 3, 4, 5};  // B-spline, step 1: 4 segments, 5 ends
  RiCurves(RI_CUBIC, 1, seven, RI_NONPERIODIC, RI_P, p, RI_WIDTH, bspline_widths, RI_NULL);
  RiAttributeEnd();
  RiWorldEnd();
  RiEnd();
  const std::string text = read_text_file(rib);
  EXPECT_NE(text.find("\"varying float width\" [0.1 0.2 0.3]\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\"varying float width\" [1 2 3 4 5]\n"), std::string::npos) << text;
}

TEST(CBindingContexts, CallsGoToTheCurrentContext) {
  ScratchDir dir("c_binding_contexts");
  const std::string a = (dir / "a.rib").string(), b = (dir / "b.rib").string();
  RiBegin(a.c_str());
  RtContextHandle first = RiGetContext();
  RiBegin(b.c_str());
  RtContextHandle second = RiGetContext();
  ASSERT_NE(first, second);
  RiSides(1);
  RiContext(first);
  RiSides(2);
  RiEnd();
  RiContext(second);
  RiEnd();
  EXPECT_EQ(read_text_file(a), "Sides 2\n");
  EXPECT_EQ(read_text_file(b), "Sides 1\n");
}

}  // namespace
}  // namespace darc::test
