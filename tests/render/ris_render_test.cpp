// A RenderMan 21+ scene (PxrSurface lit by PxrDistantLight) renders like the RI scene it maps to
// (plastic lit by distantlight with the same colours, gains and light), with both hiders.
#include "support/darc_command.h"
#include "support/image_compare.h"
#include "support/image_files.h"

namespace darc::test {
namespace {

std::string frame(const std::string& display, const std::string& light, const std::string& surface) {
  return "Display \"" + display +
         "\" \"file\" \"rgba\"\n"
         "Format 48 36 1\nPixelSamples 2 2\nProjection \"perspective\" \"fov\" [40]\nTranslate 0 0 5\n"
         "WorldBegin\n"
         // The last rotation turns the light's +z (where RenderMan's lights shine) toward the
         // sphere's side the camera sees, as hand-written RIS scenes do.
         "  TransformBegin\n    Rotate 150 0 1 0\n    Rotate 30 1 0 0\n    Rotate 180 0 1 0\n    " +
         light +
         "\n  TransformEnd\n"
         "  AttributeBegin\n    " +
         surface +
         "\n    Sphere 1 -1 1 360\n  AttributeEnd\n"
         "WorldEnd\n";
}

double mean_red(const Pixels& p) {
  double sum = 0;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) sum += p.at(x, y, 0);
  return sum / (p.width * p.height);
}

TEST(RisRender, PxrSurfaceUnderPxrDistantLightLooksLikeItsPlasticAndDistantlight) {
  ScratchDir dir("ris-render");
  // intensity 1.5 * 2^1 = 3; the light travels along its +z axis (RenderMan's Pxr lights emit
  // toward their own +z: ../shared/docs/lookdev.md §2.2), 0.53 degrees across (angleExtent's default).
  write_file(dir / "ris.rib",
             frame("ris.exr",
                   "Light \"PxrDistantLight\" \"sun\" \"float intensity\" [1.5] \"float exposure\" [1] "
                   "\"color lightColor\" [1 0.9 0.8]",
                   "Bxdf \"PxrSurface\" \"s\" \"color diffuseColor\" [0.8 0.3 0.2] \"float diffuseGain\" [0.6] "
                   "\"color specularFaceColor\" [0.4 0.4 0.4] \"float specularRoughness\" [0.1]"));
  write_file(dir / "ri.rib", frame("ri.exr",
                                   "LightSource \"distantlight\" 1 \"intensity\" [3] \"lightcolor\" [1 0.9 0.8] "
                                   "\"from\" [0 0 0] \"to\" [0 0 1] \"float angle\" [0.53] "
                                   "\"string shadowname\" [\"raytrace\"]",
                                   "Color [0.8 0.3 0.2]\n    Surface \"plastic\" \"Ka\" [0.6] \"Kd\" [0.6] \"Ks\" [1] "
                                   "\"roughness\" [0.1] \"specularcolor\" [0.4 0.4 0.4]"));
  for (const char* hider : {"distance", "stochastic"}) {
    SCOPED_TRACE(hider);
    ASSERT_EQ(run_darc(dir.path(), std::string("--hider ") + hider + " ris.rib").exit_code, 0);
    ASSERT_EQ(run_darc(dir.path(), std::string("--hider ") + hider + " ri.rib").exit_code, 0);
    Pixels ris, ri;
    ASSERT_TRUE(read_image(dir / "ris.exr", ris));
    ASSERT_TRUE(read_image(dir / "ri.exr", ri));
    ASSERT_EQ(ris.v.size(), ri.v.size());
    EXPECT_GT(mean_red(ri), 0.05) << "the sphere is lit: the comparison means something";
    EXPECT_LT(compare(ris, ri).rmse, 1e-6);
  }
}

}  // namespace
}  // namespace darc::test
