// SceneBuilder and the error policy (RI ErrorHandler "print"): a request with an error is
// skipped as a whole, the frame is built from the rest, and each error counts for one frame:
// the one being described when it was reported (since the previous frame ended).
#include <gtest/gtest.h>

#include "support/scenes_from_rib.h"

namespace darc {
namespace {

using test::build;
using test::Built;

TEST(SceneBuilderErrors, ErrorsBeforeWorldBeginAreTheFramesAndTheirRequestsAreSkipped) {
  Built b = build(R"(Basis "bsline" 1 "bezier" 3
FrameBegin 1
Projection "perspective" "fov" [200]
WorldBegin
Sphere 1 -1 1 360
WorldEnd
FrameEnd
)");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes[0].surfaces.spheres.size(), 1u);
  EXPECT_EQ(b.scenes[0].camera.projection, Camera::Projection::Orthographic)
      << "the Projection with a bad fov changes nothing, not even the projection";
  ASSERT_EQ(b.frame_errors.size(), 1u);
  EXPECT_EQ(b.frame_errors[0].count, 2) << "errors before FrameBegin count for the frame";
  EXPECT_EQ(b.frame_errors[0].first, "test.rib:1:1: error: Basis: unknown basis \"bsline\"");
}

TEST(SceneBuilderErrors, ErrorsBetweenFramesCountForTheNextFrame) {
  Built b = build(R"(FrameBegin 1 WorldBegin Sphere 1 -1 1 360 WorldEnd FrameEnd
Sides 3
FrameBegin 2 WorldBegin Sphere 1 -1 1 360 WorldEnd FrameEnd
FrameBegin 3 WorldBegin Sphere 1 -1 1 360 WorldEnd FrameEnd
)");
  ASSERT_EQ(b.frame_errors.size(), 3u);
  EXPECT_EQ(b.frame_errors[0].count, 0);
  EXPECT_EQ(b.frame_errors[1].count, 1);
  EXPECT_EQ(b.frame_errors[1].first, "test.rib:2:1: error: Sides: Sides must be 1 or 2, found 3");
  EXPECT_EQ(b.frame_errors[2].count, 0);
}

TEST(SceneBuilderErrors, AFrameNotSelectedStillClosesItsErrors) {
  Built b = build(R"(FrameBegin 1 WorldBegin Sides 3 WorldEnd FrameEnd
FrameBegin 2 WorldBegin Sphere 1 -1 1 360 WorldEnd FrameEnd
)",
                  [](int frame) { return frame == 2; });
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.frame_errors[0].count, 0) << "frame 1's error is not frame 2's";
}

TEST(SceneBuilderErrors, ABadRequestInAnObjectIsSkippedAtEachInstance) {
  Built b = build(R"(WorldBegin
ObjectBegin "o" Sides 3 Sphere 1 -1 1 360 ObjectEnd
ObjectInstance "o"
ObjectInstance "o"
Sphere 2 -2 2 360
WorldEnd
)");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.scenes[0].surfaces.spheres.size(), 3u) << "the object's other requests and the rest are built";
  EXPECT_EQ(b.frame_errors[0].count, 2);
  EXPECT_EQ(b.frame_errors[0].first,
            "test.rib:3:1: error: ObjectInstance: object \"o\": Sides must be 1 or 2, found 3");
}

TEST(SceneBuilderErrors, WorldEndClosesEveryBlockLeftOpenWithAnErrorEach) {
  Built b = build(R"(WorldBegin
AttributeBegin
Color [1 0 0]
TransformBegin
Translate 5 0 0
ObjectBegin "o" Sphere 1 -1 1 360
WorldEnd
)");
  ASSERT_EQ(b.scenes.size(), 1u);
  EXPECT_EQ(b.frame_errors[0].count, 3) << "ObjectBegin, TransformBegin and AttributeBegin";
  EXPECT_EQ(b.frame_errors[0].first,
            "test.rib:7:1: error: WorldEnd: ObjectBegin at test.rib:6:1 is still open: closed here");
  EXPECT_TRUE(b.scenes[0].surfaces.spheres.empty()) << "the sphere inside the object is recorded, not drawn";
  EXPECT_TRUE(b.failed.empty());
}

TEST(SceneBuilderErrors, ErrorHandlerIsNotGraphicsStateAndHoldsPastFrameEnd) {
  Built b = build(R"(FrameBegin 1 ErrorHandler "ignore" WorldBegin WorldEnd FrameEnd
FrameBegin 2 WorldBegin Sides 3 Sphere 1 -1 1 360 WorldEnd FrameEnd
)");
  ASSERT_EQ(b.scenes.size(), 2u);
  EXPECT_TRUE(b.diagnostics.empty()) << "\"ignore\" set in frame 1 still holds in frame 2";
  EXPECT_EQ(b.frame_errors[1].count, 1) << "and the error is still the frame's";
}

TEST(SceneBuilderErrors, UnderAbortNoFrameIsHandedOverAfterTheFirstError) {
  Built b = build(R"(ErrorHandler "abort"
FrameBegin 1 WorldBegin Sphere 1 -1 1 360 WorldEnd FrameEnd
FrameBegin 2 WorldBegin Sides 3 Sphere 1 -1 1 360 WorldEnd FrameEnd
FrameBegin 3 WorldBegin Sphere 1 -1 1 360 WorldEnd FrameEnd
)");
  ASSERT_EQ(b.scenes.size(), 1u) << "frame 1 was done before the error";
  EXPECT_EQ(b.scenes[0].output.frame_number, 1);
  EXPECT_TRUE(b.failed.empty()) << "the blocks left open by the stop are no new errors";
  ASSERT_EQ(b.diagnostics.size(), 1u);
  EXPECT_EQ(b.diagnostics[0].str(), "test.rib:3:25: error: Sides: Sides must be 1 or 2, found 3");
}

}  // namespace
}  // namespace darc
