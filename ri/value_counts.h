// How many values a parameter of each storage class has in one request (RI Spec 3.2 section 5 and
// the tables of each geometry request): what a C caller's bare value pointers hold. RIB and Python
// give the values with their length; the C binding must count them from the request's own
// arguments. A request whose arguments do not make a valid shape has no counts: the caller
// reports the reason and skips the request.
#pragma once

#include "parser/param_list.h"
#include "parser/ri_arg_kinds.h"

#include <cstddef>
#include <span>
#include <string>

namespace darc {

struct ValueCounts {
  size_t uniform = 1, varying = 1, vertex = 1, facevarying = 1, facevertex = 1;
  // Elements a parameter of `storage` has (constant: 1).
  size_t of(StorageClass storage) const;
};

// The counts of a request without geometry (options, attributes, shaders): one of each.
ValueCounts single_values();

// Each throws RibError, saying what is wrong, when the arguments make no valid shape.
ValueCounts polygon_counts(int nvertices);
ValueCounts points_counts(int npoints);
ValueCounts general_polygon_counts(std::span<const int> nverts_per_loop);
ValueCounts points_polygons_counts(std::span<const int> nverts_per_face, std::span<const int> indices);
ValueCounts points_general_polygons_counts(std::span<const int> nloops_per_face, std::span<const int> nverts_per_loop,
                                           std::span<const int> indices);
ValueCounts curves_counts(const std::string& type, std::span<const int> nvertices, const std::string& wrap, int vstep);
// Sphere and the other quadrics, Patch, PatchMesh, NuPatch, SubdivisionMesh (Points: points_counts).
ValueCounts primitive_counts(const PrimitiveRequest& request, int ustep, int vstep);

}  // namespace darc
