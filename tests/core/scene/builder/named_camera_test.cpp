// Camera (PRMan, RI Spec 3.4): a named camera is the coordinate system of that name inside the
// world, where the transform was at the request; the image is rendered from the camera in
// effect at WorldBegin, and the camera's parameters are warned about once ("shutteropening" aside:
// tests/render/motion_blur_render_test.cpp).
#include <gtest/gtest.h>

#include <string>

#include "support/scenes_from_rib.h"

namespace darc::test {
namespace {

TEST(NamedCamera, IsACoordinateSystemWhereTheCameraWas) {
  const Built b = build("Format 8 8 1\nProjection \"perspective\"\nTranslate 0 0 5\nCamera \"main\"\n"
                        "Translate 1 0 0\nWorldBegin\nCoordSysTransform \"main\"\nTranslate 0 0 3\n"
                        "Sphere 0.5 -0.5 0.5 360\nWorldEnd\n");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_TRUE(b.diagnostics.empty()) << b.diagnostics.front().str();
  ASSERT_EQ(b.scenes[0].surfaces.size(), 1u);
  const BBox box = b.scenes[0].surfaces.bounds(0);
  const Vec3f c = (box.lo + box.hi) * 0.5f;
  // World to "main" is a translation by (0 0 5): 3 units in front of it is z = -2 in the world,
  // whatever the render camera (one unit further along x) is.
  EXPECT_NEAR(c.x, 0.0f, 1e-4f);
  EXPECT_NEAR(c.z, -2.0f, 1e-4f);
  // The image's camera is the one at WorldBegin.
  EXPECT_NEAR(b.scenes[0].camera.world_to_camera.transform_point(Vec3d{0, 0, 0}).x, 1.0, 1e-9);
}

TEST(NamedCamera, ParametersAreWarnedAboutOnceAndInsideTheWorldItIsIgnored) {
  const Built b = build("Format 8 8 1\nCamera \"a\" \"float apertureNSides\" [6]\n"
                        "Camera \"b\" \"float apertureNSides\" [6]\nWorldBegin\nCamera \"c\"\n"
                        "CoordSysTransform \"b\"\nSphere 1 -1 1 360\nWorldEnd\n");
  std::string all;
  for (const Diagnostic& d : b.diagnostics) all += d.str() + "\n";
  ASSERT_EQ(b.diagnostics.size(), 2u) << all;
  EXPECT_EQ(b.diagnostics[0].severity, Severity::Warning);
  EXPECT_NE(b.diagnostics[0].message.find("\"apertureNSides\""), std::string::npos) << b.diagnostics[0].message;
  EXPECT_EQ(b.diagnostics[0].loc.line, 2);
  EXPECT_EQ(b.diagnostics[1].loc.line, 5);
  EXPECT_NE(b.diagnostics[1].message.find("options cannot change inside WorldBegin"), std::string::npos);
}

}  // namespace
}  // namespace darc::test
