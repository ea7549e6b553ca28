// ScopedCoordinateSystem (RenderMan 16+): a named space that ends with the attribute block it is
// given in, over a space of the same name given outside; and ResourceBegin/ResourceEnd, read
// without effect.
#include <gtest/gtest.h>

#include <string>

#include "support/scenes_from_rib.h"

namespace darc::test {
namespace {

// The centre of the only surface of `rib`'s frame (a sphere placed through CoordSysTransform).
Vec3f sphere_centre(const Built& b) {
  EXPECT_EQ(b.scenes.size(), 1u);
  if (b.scenes.empty() || b.scenes[0].surfaces.size() != 1) {
    ADD_FAILURE() << "expected one surface";
    return {};
  }
  const BBox box = b.scenes[0].surfaces.bounds(0);
  return (box.lo + box.hi) * 0.5f;
}

std::string world(const std::string& body) { return "Format 8 8 1\nWorldBegin\n" + body + "WorldEnd\n"; }

TEST(ScopedCoordinateSystem, NamesTheSpaceInsideItsAttributeBlock) {
  const Built b = build(world("AttributeBegin\nTranslate 5 0 0\nScopedCoordinateSystem \"here\"\nAttributeEnd\n"
                              "AttributeBegin\nTranslate 0 7 0\nScopedCoordinateSystem \"here\"\n"
                              "AttributeBegin\nCoordSysTransform \"here\"\nSphere 1 -1 1 360\nAttributeEnd\n"
                              "AttributeEnd\n"));
  const Vec3f c = sphere_centre(b);
  EXPECT_NEAR(c.x, 0.0f, 1e-4f);
  EXPECT_NEAR(c.y, 7.0f, 1e-4f);
  EXPECT_TRUE(b.frame_errors.empty() || b.frame_errors[0].count == 0);
}

TEST(ScopedCoordinateSystem, HidesASpaceOfTheSameNameUntilItsBlockEnds) {
  const Built b = build(world("AttributeBegin\nTranslate 3 0 0\nCoordinateSystem \"s\"\nAttributeEnd\n"
                              "AttributeBegin\nTranslate 0 0 4\nScopedCoordinateSystem \"s\"\nAttributeEnd\n"
                              "AttributeBegin\nCoordSysTransform \"s\"\nSphere 1 -1 1 360\nAttributeEnd\n"));
  const Vec3f c = sphere_centre(b);
  EXPECT_NEAR(c.x, 3.0f, 1e-4f);  // the scoped "s" ended with its block: the global one again
  EXPECT_NEAR(c.z, 0.0f, 1e-4f);
}

TEST(ScopedCoordinateSystem, IsUnknownAfterItsBlock) {
  const Built b = build(world("AttributeBegin\nScopedCoordinateSystem \"gone\"\nAttributeEnd\n"
                              "CoordSysTransform \"gone\"\nSphere 1 -1 1 360\n"));
  ASSERT_FALSE(b.diagnostics.empty());
  bool found = false;
  for (const Diagnostic& d : b.diagnostics)
    if (d.severity == Severity::Error && d.message.find("unknown coordinate system \"gone\"") != std::string::npos) {
      found = true;
      EXPECT_EQ(d.loc.line, 6);
    }
  EXPECT_TRUE(found);
}

TEST(ResourceBlocks, AreReadWithoutEffectOrWarning) {
  const Built b = build(world("ResourceBegin\nAttributeBegin\nTranslate 2 0 0\nSphere 1 -1 1 360\nAttributeEnd\n"
                              "ResourceEnd\n"));
  const Vec3f c = sphere_centre(b);
  EXPECT_NEAR(c.x, 2.0f, 1e-4f);
  for (const Diagnostic& d : b.diagnostics) ADD_FAILURE() << d.str();
}

}  // namespace
}  // namespace darc::test
