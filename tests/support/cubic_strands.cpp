#include "support/cubic_strands.h"

#include <cstdio>

namespace darc::test {

std::string cubic_strands(int strands, int vertices, const StrandPoint& point, float width) {
  std::string rib = "Curves \"cubic\" [";
  const std::string count = std::to_string(vertices);
  for (int i = 0; i < strands; ++i) rib.append(" ").append(count);
  rib += "] \"nonperiodic\" \"P\" [";
  char text[64];
  for (int i = 0; i < strands; ++i)
    for (int v = 0; v < vertices; ++v) {
      const Vec3f p = point(i, v);
      std::snprintf(text, sizeof text, " %.3f %.3f %.3f", p.x, p.y, p.z);
      rib += text;
    }
  std::snprintf(text, sizeof text, "] \"constantwidth\" [%g]\n", width);
  return rib + text;
}

}  // namespace darc::test
