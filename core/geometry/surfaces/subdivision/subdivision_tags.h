// The tags of a SubdivisionMesh request (subdivision_surface.h lists them), read from RI's
// tag/nargs/intargs/floatargs/stringargs arrays into what refinement needs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace darc {

struct SubdivisionMeshRequest;

enum class BoundaryInterpolation { None, EdgesAndCorners, EdgesOnly };

struct SubdivisionCreaseEdge {
  uint32_t a = 0, b = 0;
  float sharpness = 0;
};

struct SubdivisionCorner {
  uint32_t vertex = 0;
  float sharpness = 0;
};

struct SubdivisionTags {
  BoundaryInterpolation boundary = BoundaryInterpolation::None;  // PRMan's default
  std::vector<SubdivisionCreaseEdge> crease_edges;               // not yet checked to be edges of the mesh
  std::vector<SubdivisionCorner> corners;
  std::vector<uint32_t> hole_faces;
};

// Reads the tags of a request whose vertex_count and face_count are known to be valid. Returns
// false with error set for a malformed tag (nargs not 2 or 3 per tag, counts past the end of the
// argument arrays or not using them up, wrong argument counts for a tag, an index out of range,
// a negative or non-finite sharpness, an interpolateboundary mode other than 0, 1, 2); unknown
// or unsupported tags add a warning and are ignored.
bool read_subdivision_tags(const SubdivisionMeshRequest& request, uint32_t vertex_count, uint32_t face_count,
                           SubdivisionTags& tags, std::vector<std::string>& warnings, std::string& error);

}  // namespace darc
