// Counting, validation and conversion of RiCurves input into world-space Bézier segments.
#include "core/geometry/curves/curve_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "parser/diagnostics.h"

namespace darc {
namespace {

constexpr float kFloatTolerance = 1e-5f;

size_t count(StorageClass storage, bool cubic, bool periodic, int step, const std::vector<int>& nv) {
  return expected_count(storage, CurvesTopology{cubic, periodic, step, nv});
}

// The examples of OpenUSD's BasisCurves documentation.
TEST(CurveCounts, NonperiodicCubic) {
  std::vector<int> bezier = {4, 7, 10, 4, 7};                            // segments 1 2 3 1 2
  EXPECT_EQ(count(StorageClass::Varying, true, false, 3, bezier), 14u);  // 2 3 4 2 3
  EXPECT_EQ(count(StorageClass::Vertex, true, false, 3, bezier), 32u);
  EXPECT_EQ(count(StorageClass::Uniform, true, false, 3, bezier), 5u);
  EXPECT_EQ(count(StorageClass::Constant, true, false, 3, bezier), 1u);
  EXPECT_EQ(count(StorageClass::FaceVarying, true, false, 3, bezier), 14u);
  std::vector<int> bspline = {5, 4, 6, 7};                                // segments 2 1 3 4
  EXPECT_EQ(count(StorageClass::Varying, true, false, 1, bspline), 14u);  // 3 2 4 5
  EXPECT_EQ(count(StorageClass::Vertex, true, false, 1, bspline), 22u);
}

TEST(CurveCounts, Periodic) {
  // Periodic Bézier with 12 vertices: 4 segments, 4 varying values (no +1 when closed).
  EXPECT_EQ(count(StorageClass::Varying, true, true, 3, {12}), 4u);
  EXPECT_EQ(count(StorageClass::Varying, true, true, 1, {4, 5}), 9u);
  EXPECT_EQ(count(StorageClass::Vertex, true, true, 1, {4, 5}), 9u);
  EXPECT_EQ(count(StorageClass::Varying, false, true, 1, {3, 4}), 7u);
}

TEST(CurveCounts, LinearVaryingEqualsVertex) {
  EXPECT_EQ(count(StorageClass::Varying, false, false, 1, {3, 2, 5}), 10u);
  EXPECT_EQ(count(StorageClass::Vertex, false, false, 1, {3, 2, 5}), 10u);
  EXPECT_EQ(count(StorageClass::Uniform, false, false, 1, {3, 2, 5}), 3u);
}

CurvesInput bezier_input(std::vector<int> nvertices) {
  CurvesInput in;
  in.cubic = true;
  in.basis = bezier_basis();
  in.nvertices = std::move(nvertices);
  size_t total = 0;
  for (int nv : in.nvertices) total += static_cast<size_t>(nv);
  for (size_t i = 0; i < total; ++i) {
    in.P.push_back(static_cast<float>(i));
    in.P.push_back(static_cast<float>(i % 3));
    in.P.push_back(0.5f * static_cast<float>(i));
  }
  return in;
}

std::string error_of(const CurvesInput& in) {
  CurveSet set;
  uint32_t next = 0;
  try {
    append_curves(set, in, 0, next);
  } catch (const RibError& e) {
    EXPECT_EQ(set.size(), 0u) << "nothing may be appended on error";
    return e.what();
  }
  return "";
}

TEST(CurveValidation, PCountMessage) {
  CurvesInput in = bezier_input({4, 4});
  in.P.resize(21);
  EXPECT_EQ(error_of(in), "\"P\" needs 24 floats for 8 vertices, found 21");
  in = bezier_input({4});
  in.p_components = 4;
  EXPECT_EQ(error_of(in), "\"Pw\" needs 16 floats for 4 vertices, found 12");
}

TEST(CurveValidation, VertexCountsPerType) {
  EXPECT_NE(error_of(bezier_input({5})).find("curve 0 has 5 vertices"), std::string::npos);
  EXPECT_NE(error_of(bezier_input({4, 3})).find("curve 1 has 3 vertices"), std::string::npos);
  CurvesInput periodic = bezier_input({4});
  periodic.periodic = true;
  EXPECT_NE(error_of(periodic).find("not a multiple of the basis step 3"), std::string::npos);
  CurvesInput linear = bezier_input({1});
  linear.cubic = false;
  EXPECT_NE(error_of(linear).find("needs at least 2"), std::string::npos);
  CurvesInput closed = bezier_input({2});
  closed.cubic = false;
  closed.periodic = true;
  EXPECT_NE(error_of(closed).find("needs at least 3"), std::string::npos);
  CurvesInput negative = bezier_input({4});
  negative.nvertices = {4, -2};
  EXPECT_NE(error_of(negative).find("nvertices must be positive"), std::string::npos);
}

TEST(CurveValidation, HugeCountsFailBeforeAllocating) {
  CurvesInput in;
  in.basis = *standard_basis("b-spline");
  in.nvertices = {2147483647, 2147483647};
  EXPECT_NE(error_of(in).find("\"P\" needs"), std::string::npos);
}

TEST(CurveValidation, PrimvarCountsAndComponents) {
  CurvesInput in = bezier_input({4, 7});  // 3 segments, 5 varying values
  in.width = PrimvarInput{StorageClass::Varying, {1, 1, 1, 1}, 1};
  EXPECT_EQ(error_of(in), "\"width\" (varying) needs 5 floats for 5 values, found 4");
  in.width = PrimvarInput{StorageClass::Uniform, {1, 1}, 1};
  EXPECT_EQ(error_of(in), "");
  in.Cs = PrimvarInput{StorageClass::Vertex, std::vector<float>(33, 0.5f), 3};
  EXPECT_EQ(error_of(in), "");
  in.Cs = PrimvarInput{StorageClass::Vertex, std::vector<float>(30, 0.5f), 3};
  EXPECT_EQ(error_of(in), "\"Cs\" (vertex) needs 33 floats for 11 values, found 30");
  in.Cs.reset();
  in.N = PrimvarInput{StorageClass::Varying, std::vector<float>(5, 1.0f), 1};
  EXPECT_EQ(error_of(in), "\"N\" must have 3 float(s) per value, found 1");
}

TEST(CurveValidation, NonFiniteP) {
  CurvesInput in = bezier_input({4});
  in.P[4] = std::nanf("");
  EXPECT_EQ(error_of(in), "\"P\" value 4 is not finite");
}

CurveSet build(const CurvesInput& in, uint32_t& next) {
  CurveSet set;
  append_curves(set, in, 7, next);
  return set;
}

void expect_near(const Vec3f& a, const Vec3f& b, float tolerance, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, tolerance) << what;
  EXPECT_NEAR(a.y, b.y, tolerance) << what;
  EXPECT_NEAR(a.z, b.z, tolerance) << what;
}

// Evaluates the original basis on the input vertices (object space, 3 floats per vertex).
Vec3f evaluate_input(const CurvesInput& in, const std::array<size_t, 4>& vertex, double t) {
  Vec3f out;
  for (int c = 0; c < 3; ++c) {
    std::array<double, 4> g;
    for (int i = 0; i < 4; ++i) g[i] = in.P[vertex[i] * 3 + c];
    out[c] = static_cast<float>(evaluate_basis(in.basis, g, t));
  }
  return out;
}

TEST(CurveBuilder, CatmullRomSegmentsMatchTheBasis) {
  CurvesInput in;
  in.basis = *standard_basis("catmull-rom");
  in.nvertices = {6};
  in.P = {0, 0, 0, 1, 2, 0, 2, -1, 1, 4, 0, 2, 5, 3, 1, 6, 1, 0};
  uint32_t next = 3;
  CurveSet set = build(in, next);
  ASSERT_EQ(set.size(), 3u);
  for (size_t k = 0; k < 3; ++k)
    for (double t : {0.0, 0.3, 0.7, 1.0})
      expect_near(bezier_evaluate(set.control_points(k), float(t)), evaluate_input(in, {k, k + 1, k + 2, k + 3}, t),
                  kFloatTolerance, "segment " + std::to_string(k));
  EXPECT_EQ(next, 4u);
  EXPECT_EQ(set.strand_id, (std::vector<uint32_t>{3, 3, 3}));
  EXPECT_EQ(set.attribute_id, (std::vector<uint32_t>{7, 7, 7}));
  EXPECT_EQ(set.cp.size(), 12u);
  EXPECT_TRUE(set.normal.empty());  // no segment is oriented
  for (size_t k = 0; k < 3; ++k) EXPECT_FALSE(set.oriented(k));
  // The strand's ends are its first and last segments' outer ends.
  EXPECT_TRUE(set.strand_start(0) && !set.strand_end(0));
  EXPECT_TRUE(!set.strand_start(1) && !set.strand_end(1));
  EXPECT_TRUE(!set.strand_start(2) && set.strand_end(2));
  // One colour for the whole call (no Cs or Os primvar): one shading entry.
  EXPECT_EQ(set.shading.size(), 1u);
}

TEST(CurveBuilder, PeriodicBSplineWraps) {
  CurvesInput in;
  in.basis = *standard_basis("b-spline");
  in.periodic = true;
  in.nvertices = {4};
  in.P = {0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0};
  uint32_t next = 0;
  CurveSet set = build(in, next);
  ASSERT_EQ(set.size(), 4u);
  // Segment 3 uses vertices 3, 0, 1, 2 and ends where segment 0 starts: a closed loop.
  for (double t : {0.0, 0.5, 1.0})
    expect_near(bezier_evaluate(set.control_points(3), float(t)), evaluate_input(in, {3, 0, 1, 2}, t), kFloatTolerance,
                "wrapped segment");
  expect_near(set.control_points(3)[3], set.control_points(0)[0], kFloatTolerance, "closed");
}

TEST(CurveBuilder, LinearSegmentsAreElevated) {
  CurvesInput in;
  in.cubic = false;
  in.periodic = true;
  in.nvertices = {3};
  in.P = {0, 0, 0, 3, 0, 0, 3, 6, 0};
  uint32_t next = 0;
  CurveSet set = build(in, next);
  ASSERT_EQ(set.size(), 3u);
  const Vec3f* cp = set.control_points(0);
  expect_near(cp[1], {1, 0, 0}, kFloatTolerance, "1/3");
  expect_near(cp[2], {2, 0, 0}, kFloatTolerance, "2/3");
  // The closing segment runs from the last vertex back to the first.
  expect_near(set.control_points(2)[0], {3, 6, 0}, kFloatTolerance, "closing start");
  expect_near(set.control_points(2)[2], {1, 2, 0}, kFloatTolerance, "closing 2/3");
  expect_near(set.control_points(2)[3], {0, 0, 0}, kFloatTolerance, "closing end");
}

TEST(CurveBuilder, HermiteConvertsBeforeTheTransform) {
  CurvesInput in;
  in.basis = *standard_basis("hermite");
  in.nvertices = {4};
  in.P = {0, 0, 0, /*T0*/ 3, 3, 0, /*P1*/ 2, 0, 0, /*T1*/ 3, -3, 0};
  in.object_to_world = Matrix4::translate({10, 20, 30});
  uint32_t next = 0;
  CurveSet set = build(in, next);
  ASSERT_EQ(set.size(), 1u);
  for (double t : {0.0, 0.25, 0.5, 1.0}) {
    Vec3f object = evaluate_input(in, {0, 1, 2, 3}, t);
    expect_near(bezier_evaluate(set.control_points(0), float(t)), object + Vec3f{10, 20, 30}, 1e-4f, "hermite");
  }
}

TEST(CurveBuilder, PwIsDividedByW) {
  CurvesInput in;
  in.p_components = 4;
  in.nvertices = {4};
  in.P = {0, 0, 0, 1, 2, 0, 0, 2, 4, 2, 0, 2, 9, 0, 0, 3};
  uint32_t next = 0;
  CurveSet set = build(in, next);
  ASSERT_EQ(set.size(), 1u);
  expect_near(set.control_points(0)[1], {1, 0, 0}, kFloatTolerance, "w=2");
  expect_near(set.control_points(0)[3], {3, 0, 0}, kFloatTolerance, "w=3");
}

TEST(CurveBuilder, WidthsAreLinearPerSegmentAndScaled) {
  CurvesInput in = bezier_input({4});
  in.width = PrimvarInput{StorageClass::Varying, {0.1f, 0.4f}, 1};
  in.object_to_world = Matrix4::scale({2, 2, 2});
  uint32_t next = 0;
  CurveSet set = build(in, next);
  ASSERT_EQ(set.size(), 1u);
  const float* w = set.widths(0);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(w[i], 2 * (0.1f + 0.1f * float(i)), kFloatTolerance) << i;

  // Non-uniform scale: the geometric mean of the axis scales, cbrt(1 * 8 * 1) = 2.
  in.width.reset();
  in.constantwidth = 0.25f;
  in.object_to_world = Matrix4::scale({1, 8, 1});
  set = build(in, next);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(set.widths(0)[i], 0.5f, kFloatTolerance);

  // Default width 1 in object space; bounds grow by half of it.
  in.constantwidth.reset();
  in.object_to_world = Matrix4::identity();
  set = build(in, next);
  EXPECT_NEAR(set.widths(0)[2], 1.0f, kFloatTolerance);
  BBox box = set.segment_bounds(0);
  EXPECT_NEAR(box.lo.x, -0.5f, kFloatTolerance);
  EXPECT_NEAR(box.hi.x, 3.5f, kFloatTolerance);
}

TEST(CurveBuilder, VertexWidthFollowsTheBasis) {
  CurvesInput in;
  in.basis = *standard_basis("b-spline");
  in.nvertices = {4};
  in.P = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0};
  in.width = PrimvarInput{StorageClass::Vertex, {0.6f, 0.0f, 0.6f, 1.2f}, 1};
  uint32_t next = 0;
  CurveSet set = build(in, next);
  ASSERT_EQ(set.size(), 1u);
  CurveBasis b = in.basis;
  for (double t : {0.0, 0.5, 1.0})
    EXPECT_NEAR(bezier_evaluate(set.widths(0), float(t)), evaluate_basis(b, {0.6, 0.0, 0.6, 1.2}, t), kFloatTolerance);
}

TEST(CurveBuilder, NormalsUseTheInverseTranspose) {
  CurvesInput in = bezier_input({4});
  in.N = PrimvarInput{StorageClass::Varying, {0, 1, 0, 0, 2, 0}, 3};
  // Shear y' = y + x: the plane y = 0 becomes y = x, whose normal is (-1, 1, 0) / sqrt 2.
  Matrix4 shear;
  shear.m[0][1] = 1;
  in.object_to_world = shear;
  uint32_t next = 0;
  CurveSet set = build(in, next);
  ASSERT_EQ(set.size(), 1u);
  EXPECT_TRUE(set.oriented(0));
  float h = static_cast<float>(1 / std::sqrt(2.0));
  expect_near(set.normal[0], {-h, h, 0}, kFloatTolerance, "n0");
  expect_near(set.normal[1], {-h, h, 0}, kFloatTolerance, "n1 (normalized)");
}

TEST(CurveBuilder, ColoursByClassAndDefaults) {
  CurvesInput in = bezier_input({4, 4});
  in.Cs = PrimvarInput{StorageClass::Uniform, {1, 0, 0, 0, 1, 0}, 3};
  in.default_os = {0.5f, 0.5f, 0.5f};
  uint32_t next = 0;
  CurveSet set = build(in, next);
  ASSERT_EQ(set.size(), 2u);
  expect_near(set.colors(0)[2], {1, 0, 0}, 0, "curve 0");
  expect_near(set.colors(1)[1], {0, 1, 0}, 0, "curve 1");
  expect_near(set.opacities(1)[3], {0.5f, 0.5f, 0.5f}, 0, "default opacity");
  EXPECT_EQ(set.shading.size(), 2u);  // uniform Cs: one entry per curve
  EXPECT_EQ(set.strand_id, (std::vector<uint32_t>{0, 1}));
}

TEST(CurveBuilder, CoincidentControlPointsAreDropped) {
  CurvesInput in = bezier_input({4, 4});
  for (int i = 0; i < 12; ++i) in.P[i] = 1e5f;  // first curve: one point repeated
  uint32_t next = 10;
  CurveSet set = build(in, next);
  ASSERT_EQ(set.size(), 1u);
  EXPECT_EQ(set.strand_id[0], 11u);  // the dropped curve still used its id
  EXPECT_EQ(next, 12u);
}

}  // namespace
}  // namespace darc
