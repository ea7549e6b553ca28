// The RI C binding builds the same scene as RIB text: a scene of curves, surfaces and lights over
// two frames, given as C calls rendered in-process, as C calls written to a RIB file that the
// darc command renders, and as hand-written RIB that the darc command renders, gives bitwise the
// same images all three ways (issue 21, "the same image whichever way").
#include "ri/ri.h"

#include <gtest/gtest.h>

#include <string>

#include "support/darc_command.h"

namespace darc::test {
namespace {

// The scene through the C binding; images "<prefix>.####.exr".
void emit_scene(const std::string& prefix) {
  for (int frame = 1; frame <= 2; ++frame) {
    RiFrameBegin(frame);
    RiFormat(64, 48, 1);
    RiDisplay((prefix + ".####.exr").c_str(), "openexr", "rgba", RI_NULL);
    RtFloat fov = 40;
    RiProjection(RI_PERSPECTIVE, RI_FOV, &fov, RI_NULL);
    RiTranslate(0, 0, 5);
    RiWorldBegin();
    RtFloat intensity = 1.5f;
    RtPoint from = {0, 1, -1}, to = {0, 0, 0};
    RiLightSource(RI_DISTANTLIGHT, RI_INTENSITY, &intensity, RI_FROM, from, RI_TO, to, RI_NULL);
    RtFloat ambient = 0.1f;
    RiLightSource(RI_AMBIENTLIGHT, RI_INTENSITY, &ambient, RI_NULL);

    RiAttributeBegin();
    RtColor floor_color = {0.8f, 0.3f, 0.2f};
    RiColor(floor_color);
    RtFloat kd = 0.7f;
    RiSurface(RI_PLASTIC, RI_KD, &kd, RI_NULL);
    RiTranslate(0, -1, 0);
    RiRotate(-90, 1, 0, 0);
    RtFloat floor[] = {-3, -3, 0, 3, -3, 0, 3, 3, 0, -3, 3, 0};
    RiPolygon(4, RI_P, floor, RI_NULL);
    RiAttributeEnd();

    RiAttributeBegin();
    RiRotate(10.0f * frame, 0, 1, 0);
    RiBasis(RiBSplineBasis, RI_BSPLINESTEP, RiBSplineBasis, RI_BSPLINESTEP);
    RtColor hair = {0.9f, 0.8f, 0.5f};
    RiColor(hair);
    RtInt nvertices[] = {6, 6};
    RtFloat points[] = {-0.6f, -1, 0, -0.6f, -0.6f, 0.1f, -0.5f, -0.2f, 0, -0.4f, 0.2f, -0.1f, -0.2f, 0.5f, 0,
                        0.0f,  0.8f, 0, 0.3f,  -1,    0,    0.3f,  -0.6f, 0.1f, 0.4f, -0.2f, 0,     0.5f, 0.2f,
                        -0.1f, 0.7f, 0.5f, 0, 0.9f,  0.8f, 0};
    RtFloat widths[] = {0.06f, 0.05f, 0.03f, 0.01f, 0.08f, 0.06f, 0.04f, 0.02f};  // varying: 4 per curve
    RiCurves(RI_CUBIC, 2, nvertices, RI_NONPERIODIC, RI_P, points, RI_WIDTH, widths, RI_NULL);
    RiAttributeEnd();

    RiAttributeBegin();
    RiTranslate(1, 0, 0.5f);
    RiSphere(0.5f, -0.5f, 0.5f, 360, RI_NULL);
    RiAttributeEnd();
    RiWorldEnd();
    RiFrameEnd();
  }
}

// The same scene as RIB text.
std::string scene_rib(const std::string& prefix) {
  std::string rib;
  for (int frame = 1; frame <= 2; ++frame) {
    rib += "FrameBegin " + std::to_string(frame) + "\n";
    rib += "Format 64 48 1\nDisplay \"" + prefix + ".####.exr\" \"openexr\" \"rgba\"\n";
    rib += "Projection \"perspective\" \"fov\" [40]\nTranslate 0 0 5\nWorldBegin\n";
    rib += "LightSource \"distantlight\" 1 \"intensity\" [1.5] \"from\" [0 1 -1] \"to\" [0 0 0]\n";
    rib += "LightSource \"ambientlight\" 2 \"intensity\" [0.1]\n";
    rib += "AttributeBegin\nColor [0.8 0.3 0.2]\nSurface \"plastic\" \"Kd\" [0.7]\nTranslate 0 -1 0\n";
    rib += "Rotate -90 1 0 0\nPolygon \"P\" [-3 -3 0 3 -3 0 3 3 0 -3 3 0]\nAttributeEnd\n";
    rib += "AttributeBegin\nRotate " + std::to_string(10 * frame) + " 0 1 0\n";
    rib += "Basis \"b-spline\" 1 \"b-spline\" 1\nColor [0.9 0.8 0.5]\n";
    rib += "Curves \"cubic\" [6 6] \"nonperiodic\" \"P\" [-0.6 -1 0 -0.6 -0.6 0.1 -0.5 -0.2 0 -0.4 0.2 -0.1 "
           "-0.2 0.5 0 0 0.8 0 0.3 -1 0 0.3 -0.6 0.1 0.4 -0.2 0 0.5 0.2 -0.1 0.7 0.5 0 0.9 0.8 0] "
           "\"width\" [0.06 0.05 0.03 0.01 0.08 0.06 0.04 0.02]\n";
    rib += "AttributeEnd\nAttributeBegin\nTranslate 1 0 0.5\nSphere 0.5 -0.5 0.5 360\nAttributeEnd\n";
    rib += "WorldEnd\nFrameEnd\n";
  }
  return rib;
}

Pixels read_or_fail(const fs::path& p) {
  Pixels pixels;
  EXPECT_TRUE(read_image(p, pixels)) << p;
  return pixels;
}

double alpha_sum(const Pixels& p) {
  double sum = 0;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) sum += p.at(x, y, 3);
  return sum;
}

TEST(CBindingScene, RendersBitwiseAsRibTextDoesInEveryWay) {
  ScratchDir dir("c_binding_scene");
  // In this process.
  RiBegin(RI_NULL);
  emit_scene((dir / "inprocess").string());
  RiEnd();
  // Written as RIB by the binding, rendered by the command.
  RiBegin((dir / "written.rib").string().c_str());
  emit_scene((dir / "written").string());
  RiEnd();
  ASSERT_TRUE(fs::exists(dir / "written.rib"));
  const RunResult written = run_darc(dir.path(), "--trust-rib written.rib");
  ASSERT_EQ(written.exit_code, 0) << written.err;
  // Hand-written RIB, rendered by the command.
  write_file(dir / "hand.rib", scene_rib("hand"));
  const RunResult hand = run_darc(dir.path(), "hand.rib");
  ASSERT_EQ(hand.exit_code, 0) << hand.err;

  for (const char* frame : {"0001", "0002"}) {
    const Pixels in_process = read_or_fail(dir / (std::string("inprocess.") + frame + ".exr"));
    const Pixels from_written = read_or_fail(dir / (std::string("written.") + frame + ".exr"));
    const Pixels from_hand = read_or_fail(dir / (std::string("hand.") + frame + ".exr"));
    ASSERT_EQ(in_process.width, 64);
    // Something of every part is in the picture: the floor covers the lower half, the strands
    // and the sphere stand in front of it.
    EXPECT_GT(alpha_sum(in_process), 0.3 * 64 * 48) << frame;
    EXPECT_TRUE(in_process.identical_to(from_hand)) << "frame " << frame << ": C calls differ from RIB text";
    EXPECT_TRUE(from_written.identical_to(from_hand)) << "frame " << frame << ": the written RIB differs";
  }
  // The two frames differ (the strands turn).
  EXPECT_FALSE(read_or_fail(dir / "hand.0001.exr").identical_to(read_or_fail(dir / "hand.0002.exr")));
}

TEST(CBindingScene, RiBeginTakesTheCommandsOptionsAfterDarc) {
  ScratchDir dir("c_binding_command_options");
  RiBegin("darc --hider stochastic --pixel-samples 2 --res 48x36 --threads 1");
  ASSERT_NE(RiGetContext(), nullptr);
  emit_scene((dir / "inprocess").string());
  RiEnd();
  write_file(dir / "hand.rib", scene_rib("hand"));
  const RunResult hand = run_darc(dir.path(), "--hider stochastic --pixel-samples 2 --res 48x36 hand.rib");
  ASSERT_EQ(hand.exit_code, 0) << hand.err;
  for (const char* frame : {"0001", "0002"}) {
    const fs::path in_process = dir / (std::string("inprocess.") + frame + ".exr");
    const Pixels a = read_or_fail(in_process), b = read_or_fail(dir / (std::string("hand.") + frame + ".exr"));
    EXPECT_EQ(a.width, 48);
    EXPECT_TRUE(a.identical_to(b)) << "frame " << frame;
    const std::optional<OIIO::ImageSpec> spec = read_image_header(in_process);
    ASSERT_TRUE(spec);
    EXPECT_EQ(spec->get_string_attribute("darc:hider"), "stochastic");
    EXPECT_EQ(spec->get_int_attribute("darc:spp"), 4);
  }
}

TEST(CBindingScene, ABadCommandLineStartsNoContext) {
  RiBegin("darc --no-such-option");
  EXPECT_EQ(RiGetContext(), nullptr);
  RiBegin("darc extra.rib");  // the session's requests are the only input
  EXPECT_EQ(RiGetContext(), nullptr);
}

}  // namespace
}  // namespace darc::test
