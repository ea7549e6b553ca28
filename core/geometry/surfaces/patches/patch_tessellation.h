// RI Patch and PatchMesh (RI Spec 3.2, section 5.4) lowered to triangles: bilinear patches, and
// bicubic ones in any u and v basis with its step (the current Basis), "periodic" or
// "nonperiodic" in each direction, from P, Pw (rational) or Pz (a height field).
// A single Patch is a PatchMesh of 2 x 2 (bilinear) or 4 x 4 (bicubic) nonperiodic points.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/math/curve_basis.h"
#include "core/geometry/surfaces/patches/parametric_grid.h"
#include "core/geometry/surfaces/triangle_mesh_data.h"

namespace darc {

enum class PatchType { bilinear, bicubic };

struct PatchMeshDescription {
  PatchType type = PatchType::bilinear;
  int nu = 0, nv = 0;                           // control points per direction
  bool u_periodic = false, v_periodic = false;  // "periodic": the control points wrap around
  CurveBasis u_basis, v_basis;                  // the current Basis (bicubic only)
  // nu * nv control points, u varying fastest, in object space. For a height field only each
  // point's z (divided by w) is used.
  std::vector<HomogeneousPoint> points;
  // "Pz": x and y are the mesh's own parameters (u, v), each from 0 to 1 (RI Spec 5.4).
  bool height_field = false;
};

// How many patches a mesh has in one direction (RI Spec 5.4): bilinear n - 1 ("nonperiodic") or
// n ("periodic"); bicubic (n - 4) / step + 1 or n / step, which must divide evenly.
struct PatchCounts {
  int nupatches = 0, nvpatches = 0;
};

// The counts, or nullopt with error set to what is wrong (for example "nonperiodic bicubic
// PatchMesh with u step 3 needs nu = 4 + 3 k points, found nu = 5").
std::optional<PatchCounts> patch_counts(const PatchMeshDescription& mesh, std::string& error);

// How many values a primitive variable of each class must give (RI Spec 5.4): uniform one per
// patch, varying one per patch corner (the corners of a periodic direction wrap), vertex nu * nv.
size_t uniform_count(const PatchCounts& c);
size_t varying_count(const PatchMeshDescription& mesh, const PatchCounts& c);

// The mesh's triangles (parametric_grid.h: vertices shared where patches meet, normals from the
// exact derivatives, uv from 0 to 1 over the whole mesh as RI parameterises it). On invalid input
// (counts, number of points, step, a weight w <= 0 or a non-finite coordinate, a periodic height
// field) returns an empty mesh and sets error.
TriangleMeshData tessellate_patch_mesh(const PatchMeshDescription& mesh, std::string& error, const DicingView* view = nullptr);

}  // namespace darc
