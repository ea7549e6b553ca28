// SceneBuilder warns about a frame that has nothing to render (it would come out black with
// exit code 0), saying why: every primitive skipped as unsupported, none at all, primitives
// skipped for errors, or a camera that sees none of the geometry.
#include <gtest/gtest.h>

#include "support/scenes_from_rib.h"

namespace darc {
namespace {

using test::build;
using test::Built;

// The "nothing renderable" warnings, in order.
std::vector<Diagnostic> nothing_renderable(const Built& b) {
  std::vector<Diagnostic> out;
  for (const Diagnostic& d : b.diagnostics)
    if (d.message.find("nothing renderable") != std::string::npos) out.push_back(d);
  return out;
}

// A perspective camera 5 units from the origin, looking at it.
const char* const kCamera = "Projection \"perspective\" \"fov\" [40]\nTranslate 0 0 5\n";

TEST(SceneBuilderRenderable, EveryPrimitiveUnsupported) {
  Built b = build(std::string(kCamera) + R"RIB(FrameBegin 7
WorldBegin
  Blobby 1 [1001 0] [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1] [""]
  Geometry "teapot"
  Blobby 1 [1001 0] [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1] [""]
WorldEnd
FrameEnd
)RIB");
  ASSERT_EQ(b.scenes.size(), 1u);
  const auto w = nothing_renderable(b);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].severity, Severity::Warning);
  EXPECT_EQ(w[0].message,
            "nothing renderable in frame 7: every primitive in it is of a kind darc does not support "
            "(Blobby x2, Geometry)");
  EXPECT_EQ(w[0].loc.str(), "test.rib:8:1") << "at the WorldEnd";
}

TEST(SceneBuilderRenderable, NoPrimitiveAtAll) {
  Built b = build("WorldBegin\nSurface \"plastic\"\nWorldEnd\nWorldBegin\nWorldEnd\n");
  const auto w = nothing_renderable(b);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0].message, "nothing renderable in frame 1: its world block has no primitive");
  EXPECT_EQ(w[1].message, "nothing renderable in frame 2: its world block has no primitive");
}

TEST(SceneBuilderRenderable, PrimitivesSkippedForErrors) {
  Built b = build("WorldBegin\nCurves \"cubic\" [5] \"nonperiodic\" \"P\" [0 0 0 0 1 0 1 2 0 1 3 0 0 4 0]\nWorldEnd\n");
  const auto w = nothing_renderable(b);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].message, "nothing renderable in frame 1: no primitive was built (the frame has 1 error)");
}

TEST(SceneBuilderRenderable, UnsupportedPrimitivesInAnInstanceCount) {
  Built b = build("WorldBegin\nObjectBegin \"o\" Geometry \"teapot\" ObjectEnd\nObjectInstance \"o\"\nWorldEnd\n");
  const auto w = nothing_renderable(b);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].message,
            "nothing renderable in frame 1: every primitive in it is of a kind darc does not support (Geometry)");
}

TEST(SceneBuilderRenderable, GeometryTheCameraCannotSee) {
  Built behind =
      build("Projection \"perspective\" \"fov\" [40]\nTranslate 0 0 -5\nWorldBegin\nSphere 1 -1 1 360\nWorldEnd\n");
  ASSERT_EQ(nothing_renderable(behind).size(), 1u);
  EXPECT_EQ(nothing_renderable(behind)[0].message,
            "nothing renderable in frame 1: all of its geometry is behind the camera or nearer than the near "
            "clipping plane");
  Built aside = build(std::string(kCamera) + "WorldBegin\nTranslate 100 0 0\nSphere 1 -1 1 360\nWorldEnd\n");
  ASSERT_EQ(nothing_renderable(aside).size(), 1u);
  EXPECT_EQ(nothing_renderable(aside)[0].message,
            "nothing renderable in frame 1: all of its geometry is outside the camera's view");
  Built far =
      build(std::string(kCamera) + "Clipping 0.1 10\nWorldBegin\nTranslate 0 0 100\nSphere 1 -1 1 360\nWorldEnd\n");
  ASSERT_EQ(nothing_renderable(far).size(), 1u);
  EXPECT_EQ(nothing_renderable(far)[0].message,
            "nothing renderable in frame 1: all of its geometry is beyond the far clipping plane");
}

TEST(SceneBuilderRenderable, AVisibleFrameDoesNotWarn) {
  for (const char* world : {"Sphere 1 -1 1 360", "Cylinder 1 0 1 360 Sphere 1 -1 1 360",
                            "Translate 2.2 0 0 Sphere 1 -1 1 360",    // partly in view
                            "Translate 0 0 -5 Sphere 1 -1 1 360"}) {  // around the camera
    SCOPED_TRACE(world);
    Built b = build(std::string(kCamera) + "WorldBegin\n" + world + "\nWorldEnd\n");
    EXPECT_TRUE(nothing_renderable(b).empty()) << nothing_renderable(b)[0].str();
  }
}

TEST(SceneBuilderRenderable, AFrameNotSelectedIsNotChecked) {
  Built b =
      build("FrameBegin 1 WorldBegin WorldEnd FrameEnd FrameBegin 2 WorldBegin Sphere 1 -1 1 360 WorldEnd FrameEnd",
            [](int frame) { return frame == 2; });
  EXPECT_TRUE(nothing_renderable(b).empty());
}

}  // namespace
}  // namespace darc
