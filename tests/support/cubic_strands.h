// The RIB text of many cubic strands in one Curves request, for the tests that need a lot of hair
// (a frame over a memory limit, an archive a camera moves over) and draw its control points at
// random themselves.
#pragma once

#include <functional>
#include <string>

#include "core/math/vec.h"

namespace darc::test {

// The control point `vertex` of strand `strand`. Called strand by strand and, within a strand,
// vertex by vertex from 0, so that it may draw random numbers as it goes (a strand's root at
// vertex 0, say) and give the same points for the same seed.
using StrandPoint = std::function<Vec3f(int strand, int vertex)>;

// `Curves "cubic" [vertices ...] "nonperiodic" "P" [...] "constantwidth" [width]` with `strands`
// strands of `vertices` points each, the points written to three decimals; one line.
std::string cubic_strands(int strands, int vertices, const StrandPoint& point, float width);

}  // namespace darc::test
