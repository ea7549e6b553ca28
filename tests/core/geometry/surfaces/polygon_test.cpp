#include "core/geometry/surfaces/polygon.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace darc {
namespace {

using Loops = std::vector<std::vector<Vec3f>>;

// A ray straight down -z onto the point (x, y) of the z = 0 plane.
Ray down_at(float x, float y) { return Ray{{x, y, 5}, {0, 0, -1}}; }

const std::vector<Vec3f> kUnitSquareCcw = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

TEST(Polygon, SquareHitAndMiss) {
  auto square = PolygonShape::make({kUnitSquareCcw});
  ASSERT_TRUE(square);
  SurfaceHit h;
  ASSERT_TRUE(square->intersect(down_at(0.3f, 0.7f), h));
  EXPECT_FLOAT_EQ(h.t, 5.0f);
  EXPECT_FLOAT_EQ(h.p.x, 0.3f);
  EXPECT_FLOAT_EQ(h.p.y, 0.7f);
  EXPECT_FALSE(square->intersect(down_at(1.2f, 0.5f), h));
  EXPECT_FALSE(square->intersect(down_at(-0.1f, 0.5f), h));
  EXPECT_FALSE(square->intersect(Ray{{0.5f, 0.5f, 1}, {1, 0, 0}}, h));  // parallel to the plane
  Ray short_ray = down_at(0.5f, 0.5f);
  short_ray.tmax = 4.9f;
  EXPECT_FALSE(square->intersect(short_ray, h));
  BBox b = square->bounds();
  EXPECT_EQ(b.lo, (Vec3f{0, 0, 0}));
  EXPECT_EQ(b.hi, (Vec3f{1, 1, 0}));
}

TEST(Polygon, NormalFollowsVertexOrderByRightHandRule) {
  auto ccw = PolygonShape::make({kUnitSquareCcw});
  std::vector<Vec3f> cw(kUnitSquareCcw.rbegin(), kUnitSquareCcw.rend());
  auto clockwise = PolygonShape::make({cw});
  ASSERT_TRUE(ccw && clockwise);
  EXPECT_EQ(ccw->normal, (Vec3f{0, 0, 1}));  // (p1 - p0) x (p2 - p0) = x cross y = +z
  EXPECT_EQ(clockwise->normal, (Vec3f{0, 0, -1}));
  SurfaceHit h;
  ASSERT_TRUE(ccw->intersect(down_at(0.5f, 0.5f), h));
  EXPECT_EQ(h.ng, (Vec3f{0, 0, 1}));  // not flipped toward the ray
  // A tilted triangle: the normal is the normalized cross product of its edges.
  std::vector<Vec3f> tri = {{0, 0, 0}, {2, 0, 1}, {0, 3, 0}};
  auto t = PolygonShape::make({tri});
  ASSERT_TRUE(t);
  Vec3f expected = normalize(cross(tri[1] - tri[0], tri[2] - tri[0]));
  EXPECT_NEAR(t->normal.x, expected.x, 1e-6f);
  EXPECT_NEAR(t->normal.y, expected.y, 1e-6f);
  EXPECT_NEAR(t->normal.z, expected.z, 1e-6f);
}

TEST(Polygon, SquareWithSquareHole) {
  std::vector<Vec3f> hole = {{0.25f, 0.25f, 0}, {0.25f, 0.75f, 0}, {0.75f, 0.75f, 0}, {0.75f, 0.25f, 0}};
  auto shape = PolygonShape::make({kUnitSquareCcw, hole});
  ASSERT_TRUE(shape);
  SurfaceHit h;
  EXPECT_FALSE(shape->intersect(down_at(0.5f, 0.5f), h));  // through the hole
  EXPECT_TRUE(shape->intersect(down_at(0.1f, 0.5f), h));
  EXPECT_TRUE(shape->intersect(down_at(0.5f, 0.9f), h));
  EXPECT_FALSE(shape->intersect(down_at(1.5f, 0.5f), h));
  EXPECT_EQ(shape->normal, (Vec3f{0, 0, 1}));  // holes do not affect the normal
}

TEST(Polygon, ConcaveUShape) {
  // A U opening toward +y: the notch x in (1, 2), y in (1, 3) is outside.
  std::vector<Vec3f> u = {{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {2, 3, 0}, {2, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}};
  auto shape = PolygonShape::make({u});
  ASSERT_TRUE(shape);
  EXPECT_EQ(shape->normal, (Vec3f{0, 0, 1}));
  SurfaceHit h;
  EXPECT_FALSE(shape->intersect(down_at(1.5f, 2.0f), h));
  EXPECT_TRUE(shape->intersect(down_at(0.5f, 2.5f), h));
  EXPECT_TRUE(shape->intersect(down_at(2.5f, 2.5f), h));
  EXPECT_TRUE(shape->intersect(down_at(1.5f, 0.5f), h));
}

TEST(Polygon, VerticalPolygonUsesAnotherProjection) {
  // In the y = 0 plane (like the aqsis genpoly faces): the 2D test drops y.
  std::vector<Vec3f> quad = {{0, 0, 0}, {0, 0, 2}, {1, 0, 2}, {1, 0, 0}};
  auto shape = PolygonShape::make({quad});
  ASSERT_TRUE(shape);
  EXPECT_EQ(shape->drop_axis, 1);
  EXPECT_EQ(shape->normal, (Vec3f{0, 1, 0}));  // z cross x = +y
  SurfaceHit h;
  ASSERT_TRUE(shape->intersect(Ray{{0.5f, -3, 1}, {0, 1, 0}}, h));
  EXPECT_FLOAT_EQ(h.t, 3.0f);
  EXPECT_FALSE(shape->intersect(Ray{{0.5f, -3, 2.5f}, {0, 1, 0}}, h));
}

TEST(Polygon, DegenerateInputGivesNullopt) {
  EXPECT_FALSE(PolygonShape::make({}));
  EXPECT_FALSE(PolygonShape::make({{{0, 0, 0}, {1, 0, 0}}}));
  EXPECT_FALSE(PolygonShape::make({{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}}));  // collinear
  EXPECT_FALSE(PolygonShape::make({{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}}));             // coincident
  float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(PolygonShape::make({{{0, 0, 0}, {1, 0, 0}, {nan, 1, 0}}}));
  // A hole with too few points is ignored, not fatal.
  auto with_bad_hole = PolygonShape::make({kUnitSquareCcw, {{0.5f, 0.5f, 0}}});
  ASSERT_TRUE(with_bad_hole);
  SurfaceHit h;
  EXPECT_TRUE(with_bad_hole->intersect(down_at(0.5f, 0.5f), h));
}

TEST(Polygon, PointsGeneralPolygonsTwoFacesWithHoles) {
  // The configuration of aqsis genpoly_test (our own numbers): two unit squares side by side
  // sharing an edge, the first with a square hole, the second with a triangular hole.
  std::vector<Vec3f> P = {{0, 0, 0},       {0, 1, 0},       {1, 1, 0},       {1, 0, 0}, {0.2f, 0.2f, 0},
                          {0.2f, 0.8f, 0}, {0.8f, 0.8f, 0}, {0.8f, 0.2f, 0}, {2, 1, 0}, {2, 0, 0},
                          {1.2f, 0.2f, 0}, {1.5f, 0.8f, 0}, {1.8f, 0.2f, 0}};
  std::string error;
  auto shapes =
      make_points_general_polygons({2, 2}, {4, 4, 4, 3}, {0, 1, 2, 3, 4, 5, 6, 7, 3, 2, 8, 9, 10, 11, 12}, P, error);
  ASSERT_TRUE(error.empty()) << error;
  ASSERT_EQ(shapes.size(), 2u);
  EXPECT_EQ(shapes[0].source_face, 0);
  EXPECT_EQ(shapes[1].source_face, 1);
  EXPECT_EQ(shapes[0].normal, (Vec3f{0, 0, -1}));  // clockwise seen from +z
  SurfaceHit h;
  EXPECT_FALSE(shapes[0].intersect(down_at(0.5f, 0.5f), h));  // square hole
  EXPECT_TRUE(shapes[0].intersect(down_at(0.1f, 0.5f), h));
  EXPECT_FALSE(shapes[1].intersect(down_at(1.5f, 0.4f), h));  // triangle hole
  EXPECT_TRUE(shapes[1].intersect(down_at(1.5f, 0.9f), h));
  EXPECT_TRUE(shapes[1].intersect(down_at(1.1f, 0.5f), h));
  EXPECT_FALSE(shapes[1].intersect(down_at(0.5f, 0.1f), h));  // belongs to the other face
}

// Extracts the numbers of the next bracketed array at or after pos, and moves pos past it.
std::vector<double> bracketed_numbers(const std::string& text, size_t& pos) {
  size_t open = text.find('[', pos), close = text.find(']', open);
  std::istringstream in(text.substr(open + 1, close - open - 1));
  pos = close + 1;
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}

TEST(Polygon, AqsisGenpolyFile) {
  std::ifstream file(DARC_SHARED_RIBS_DIR "/aqsis/Polygons_genpoly_test.rib");
  if (!file) GTEST_SKIP() << "aqsis genpoly_test RIB not available";
  std::stringstream buf;
  buf << file.rdbuf();
  std::string text = buf.str();
  size_t pos = text.find("PointsGeneralPolygons [");  // the request, not the header comment
  ASSERT_NE(pos, std::string::npos);
  auto to_ints = [](const std::vector<double>& v) { return std::vector<int>(v.begin(), v.end()); };
  std::vector<int> nloops = to_ints(bracketed_numbers(text, pos));
  std::vector<int> nverts = to_ints(bracketed_numbers(text, pos));
  std::vector<int> indices = to_ints(bracketed_numbers(text, pos));
  std::vector<double> p = bracketed_numbers(text, pos);
  std::vector<Vec3f> P;
  for (size_t i = 0; i + 2 < p.size(); i += 3) P.push_back({float(p[i]), float(p[i + 1]), float(p[i + 2])});
  ASSERT_EQ(P.size(), 13u);
  std::string error;
  auto shapes = make_points_general_polygons(nloops, nverts, indices, P, error);
  ASSERT_TRUE(error.empty()) << error;
  ASSERT_EQ(shapes.size(), 2u);
  // Both faces lie in y = 0; rays along +y at (x, z) in object space.
  auto along_y = [](float x, float z) { return Ray{{x, -1, z}, {0, 1, 0}}; };
  SurfaceHit h;
  EXPECT_TRUE(shapes[0].intersect(along_y(0.1f, 1.0f), h));
  EXPECT_FALSE(shapes[0].intersect(along_y(0.5f, 1.0f), h));  // the square hole
  EXPECT_TRUE(shapes[1].intersect(along_y(1.1f, 1.0f), h));
  EXPECT_FALSE(shapes[1].intersect(along_y(1.5f, 0.8f), h));  // inside the triangle hole
  EXPECT_TRUE(shapes[1].intersect(along_y(1.5f, 1.9f), h));   // above the triangle's apex
  EXPECT_EQ(shapes[0].normal, (Vec3f{0, 1, 0}));              // (0,0,2)-(0,0,0) x (1,0,2)-(0,0,0)
}

TEST(Polygon, NonPlanarSingleLoopBecomesFan) {
  // A quad with one corner lifted well beyond kNonPlanarTolerance.
  std::vector<Vec3f> P = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5f}, {0, 1, 0}};
  std::string error;
  auto shapes = make_points_polygons({4}, {0, 1, 2, 3}, P, error);
  ASSERT_TRUE(error.empty());
  ASSERT_EQ(shapes.size(), 2u);
  for (const PolygonShape& s : shapes) {
    EXPECT_EQ(s.source_face, 0);
    for (const Vec3f& p : {P[0], P[2]}) EXPECT_NEAR(dot(Vec3d(s.normal), Vec3d(p)), s.plane_offset, 1e-6);
  }
  // Every point of the quad's xy square is covered by exactly one piece (the diagonal aside).
  for (float x : {0.2f, 0.7f})
    for (float y : {0.3f, 0.8f}) {
      int hits = 0;
      SurfaceHit h;
      for (const PolygonShape& s : shapes) hits += s.intersect(down_at(x, y), h);
      EXPECT_EQ(hits, 1) << x << " " << y;
    }
  // A flat quad stays whole.
  P[2].z = 0;
  shapes = make_points_polygons({4}, {0, 1, 2, 3}, P, error);
  EXPECT_EQ(shapes.size(), 1u);
}

TEST(Polygon, IndexAndCountValidation) {
  std::vector<Vec3f> P(13, Vec3f{0, 0, 0});
  std::string error;
  auto shapes = make_points_polygons({3}, {0, 1, 17}, P, error);
  EXPECT_TRUE(shapes.empty());
  EXPECT_EQ(error, "vertex index 17 out of range (13 points)");
  error.clear();
  EXPECT_TRUE(make_points_polygons({3}, {0, -1, 2}, P, error).empty());
  EXPECT_EQ(error, "vertex index -1 out of range (13 points)");
  error.clear();
  EXPECT_TRUE(make_points_polygons({4}, {0, 1, 2}, P, error).empty());
  EXPECT_NE(error.find("4 vertices but 3 indices"), std::string::npos) << error;
  error.clear();
  EXPECT_TRUE(make_points_general_polygons({2}, {3}, {0, 1, 2}, P, error).empty());
  EXPECT_NE(error.find("2 loops but 1 vertex counts"), std::string::npos) << error;
  error.clear();
  EXPECT_TRUE(make_points_general_polygons({0}, {}, {}, P, error).empty());
  EXPECT_FALSE(error.empty());
  error.clear();
  EXPECT_TRUE(make_points_general_polygons({1}, {-3}, {}, P, error).empty());
  EXPECT_FALSE(error.empty());
  // Valid counts, degenerate geometry: no shapes, no error.
  error.clear();
  EXPECT_TRUE(make_points_polygons({3}, {0, 1, 2}, P, error).empty());
  EXPECT_TRUE(error.empty());
}

}  // namespace
}  // namespace darc
