/* A tuft of hair on a ground disc under a shadowing spot light, made through darc's RenderMan
 * Interface C binding: two frames, the tuft leaning further in the second.
 *
 *   tuft PREFIX            renders PREFIX.0001.exr and PREFIX.0002.exr in this process
 *   tuft PREFIX scene.rib  writes the same requests as RIB instead (render it with darc)
 *
 * Build against an installed darc:   cc tuft.c $(pkg-config --cflags --libs darc) -o tuft
 * or with CMake:                     find_package(darc) and target_link_libraries(tuft darc::ri)
 * (this folder's CMakeLists.txt). The tests build it both ways and check that the images equal
 * those of the written RIB rendered by the darc command, bit for bit. */
#include <ri.h>

#include <stdio.h>
#include <string.h>

enum { kStrands = 400, kVertices = 5 };

/* A small linear congruential generator: the same strands on every machine. */
static unsigned int seed = 12345u;
static float next_random(void) {
  seed = seed * 1664525u + 1013904223u;
  return (float)(seed >> 8) / 16777216.0f;
}

static void tuft(float lean) {
  static RtInt nvertices[kStrands];
  static RtFloat points[kStrands * kVertices * 3];
  static RtFloat widths[kStrands * (kVertices - 2)]; /* b-spline, step 1: kVertices - 2 ends */
  seed = 12345u;
  for (int s = 0; s < kStrands; ++s) {
    const float x = next_random() * 2 - 1, z = next_random() * 2 - 1;
    const float height = 1.2f + 0.6f * next_random();
    nvertices[s] = kVertices;
    for (int v = 0; v < kVertices; ++v) {
      const float t = (float)v / (kVertices - 1);
      RtFloat* p = &points[(s * kVertices + v) * 3];
      p[0] = 0.3f * x + lean * t * t * height;
      p[1] = -1 + height * t;
      p[2] = 0.3f * z + 0.1f * t * x;
    }
    for (int e = 0; e < kVertices - 2; ++e) widths[s * (kVertices - 2) + e] = 0.012f * (1 - 0.3f * e);
  }
  RiBasis(RiBSplineBasis, RI_BSPLINESTEP, RiBSplineBasis, RI_BSPLINESTEP);
  RiCurves(RI_CUBIC, kStrands, nvertices, RI_NONPERIODIC, RI_P, points, RI_WIDTH, widths, RI_NULL);
}

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: tuft PREFIX [scene.rib]\n");
    return 2;
  }
  char display[4096];
  snprintf(display, sizeof display, "%s.####.exr", argv[1]);
  RiBegin(argc > 2 ? argv[2] : RI_NULL);
  for (int frame = 1; frame <= 2; ++frame) {
    RiFrameBegin(frame);
    RiFormat(160, 120, 1);
    RiDisplay(display, "openexr", "rgba", RI_NULL);
    RtFloat fov = 35;
    RiProjection(RI_PERSPECTIVE, RI_FOV, &fov, RI_NULL);
    RiTranslate(0, 0, 5);
    RiRotate(-15, 1, 0, 0);
    RiWorldBegin();
    RtFloat intensity = 40, cone = 0.5f;
    RtPoint from = {-2, 3, -3}, to = {0, 0, 0};
    RiAttributeBegin();
    RtString on = "on";
    RiAttribute("light", "string shadows", &on, RI_NULL);
    RiLightSource(RI_SPOTLIGHT, RI_INTENSITY, &intensity, RI_FROM, from, RI_TO, to, RI_CONEANGLE, &cone, RI_NULL);
    RiAttributeEnd();
    RtFloat ambient = 0.08f;
    RiLightSource(RI_AMBIENTLIGHT, RI_INTENSITY, &ambient, RI_NULL);

    RiAttributeBegin();
    RtColor ground = {0.35f, 0.4f, 0.3f};
    RiColor(ground);
    RiSurface(RI_MATTE, RI_NULL);
    RiTranslate(0, -1, 0);
    RiRotate(90, 1, 0, 0);
    RiDisk(0, 2.5f, 360, RI_NULL);
    RiAttributeEnd();

    RiAttributeBegin();
    RtColor hair = {0.55f, 0.35f, 0.2f};
    RiColor(hair);
    tuft(0.15f * (float)frame);
    RiAttributeEnd();
    RiWorldEnd();
    RiFrameEnd();
  }
  RiEnd();
  return 0;
}
