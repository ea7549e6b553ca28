#include "core/geometry/surfaces/subdivision/subdivision_tags.h"

#include <fmt/format.h>

#include <cmath>
#include <span>

#include "core/geometry/surfaces/subdivision/subdivision_surface.h"

namespace darc {

namespace {

// One tag's arguments, cut from the shared arrays.
struct TagArguments {
  std::span<const int> ints;
  std::span<const float> floats;
  std::span<const std::string> strings;
};

bool check_sharpness(const std::string& tag, float s, std::string& error) {
  if (std::isfinite(s) && s >= 0.0f) return true;
  error = fmt::format("tag \"{}\": sharpness {} is not a finite number >= 0", tag, s);
  return false;
}

bool read_interpolate_boundary(const TagArguments& args, SubdivisionTags& tags, std::string& error) {
  if (args.ints.size() > 1 || !args.floats.empty()) {
    error = "tag \"interpolateboundary\" takes at most one integer (0, 1 or 2) and no floats";
    return false;
  }
  int mode = args.ints.empty() ? 1 : args.ints[0];
  switch (mode) {
    case 0:
      tags.boundary = BoundaryInterpolation::None;
      return true;
    case 1:
      tags.boundary = BoundaryInterpolation::EdgesAndCorners;
      return true;
    case 2:
      tags.boundary = BoundaryInterpolation::EdgesOnly;
      return true;
    default:
      break;
  }
  error = fmt::format("tag \"interpolateboundary\": mode {} is not 0 (none), 1 (edges and corners) or 2 (edges only)",
                      mode);
  return false;
}

bool check_vertices(const std::string& tag, std::span<const int> ints, uint32_t vertex_count, std::string& error) {
  for (int v : ints) {
    if (v < 0 || uint32_t(v) >= vertex_count) {
      error = fmt::format("tag \"{}\": vertex {} is out of range (the mesh has {} vertices)", tag, v, vertex_count);
      return false;
    }
  }
  return true;
}

bool read_crease(const TagArguments& args, uint32_t vertex_count, SubdivisionTags& tags, std::string& error) {
  size_t edges = args.ints.size() < 2 ? 0 : args.ints.size() - 1;
  if (edges == 0 || (args.floats.size() != 1 && args.floats.size() != edges)) {
    error = fmt::format(
        "tag \"crease\" takes a chain of at least 2 vertices and 1 sharpness (or one per edge); got {} "
        "integers and {} floats",
        args.ints.size(), args.floats.size());
    return false;
  }
  if (!check_vertices("crease", args.ints, vertex_count, error)) return false;
  for (size_t i = 0; i < edges; ++i) {
    float s = args.floats[args.floats.size() == 1 ? 0 : i];
    if (!check_sharpness("crease", s, error)) return false;
    tags.crease_edges.push_back({uint32_t(args.ints[i]), uint32_t(args.ints[i + 1]), s});
  }
  return true;
}

bool read_corner(const TagArguments& args, uint32_t vertex_count, SubdivisionTags& tags, std::string& error) {
  if (args.ints.empty() || (args.floats.size() != 1 && args.floats.size() != args.ints.size())) {
    error = fmt::format(
        "tag \"corner\" takes at least 1 vertex and 1 sharpness (or one per vertex); got {} integers and {} floats",
        args.ints.size(), args.floats.size());
    return false;
  }
  if (!check_vertices("corner", args.ints, vertex_count, error)) return false;
  for (size_t i = 0; i < args.ints.size(); ++i) {
    float s = args.floats[args.floats.size() == 1 ? 0 : i];
    if (!check_sharpness("corner", s, error)) return false;
    tags.corners.push_back({uint32_t(args.ints[i]), s});
  }
  return true;
}

bool read_hole(const TagArguments& args, uint32_t face_count, SubdivisionTags& tags, std::string& error) {
  if (!args.floats.empty()) {
    error = "tag \"hole\" takes face indices and no floats";
    return false;
  }
  for (int f : args.ints) {
    if (f < 0 || uint32_t(f) >= face_count) {
      error = fmt::format("tag \"hole\": face {} is out of range (the mesh has {} faces)", f, face_count);
      return false;
    }
    tags.hole_faces.push_back(uint32_t(f));
  }
  return true;
}

// Tags PRMan knows that change nothing darc draws (face-varying data, edits, crease methods).
bool is_known_unsupported_tag(const std::string& tag) {
  for (const char* name : {"facevaryinginterpolateboundary", "facevaryingpropagatecorners", "smoothtriangles",
                           "creasemethod", "vertexedit", "edgeedit", "faceedit", "stitch"}) {
    if (tag == name) return true;
  }
  return false;
}

}  // namespace

bool read_subdivision_tags(const SubdivisionMeshRequest& request, uint32_t vertex_count, uint32_t face_count,
                           SubdivisionTags& tags, std::vector<std::string>& warnings, std::string& error) {
  const size_t n = request.tags.size();
  if (n == 0 && request.nargs.empty()) return true;
  size_t stride = request.nargs.size() == 3 * n ? 3 : (request.nargs.size() == 2 * n ? 2 : 0);
  if (n == 0 || stride == 0) {
    error = fmt::format("nargs has {} values for {} tags (3 per tag: integers, floats, strings; or 2)",
                        request.nargs.size(), n);
    return false;
  }
  size_t int_at = 0, float_at = 0, string_at = 0;
  for (size_t i = 0; i < n; ++i) {
    const std::string& tag = request.tags[i];
    int counts[3] = {request.nargs[stride * i], request.nargs[stride * i + 1],
                     stride == 3 ? request.nargs[stride * i + 2] : 0};
    if (counts[0] < 0 || counts[1] < 0 || counts[2] < 0 || int_at + counts[0] > request.intargs.size() ||
        float_at + counts[1] > request.floatargs.size() || string_at + counts[2] > request.stringargs.size()) {
      error = fmt::format(
          "tag \"{}\": nargs ({} {} {}) are negative or run past the end of intargs, floatargs or "
          "stringargs",
          tag, counts[0], counts[1], counts[2]);
      return false;
    }
    TagArguments args{std::span(request.intargs).subspan(int_at, counts[0]),
                      std::span(request.floatargs).subspan(float_at, counts[1]),
                      std::span(request.stringargs).subspan(string_at, counts[2])};
    int_at += counts[0];
    float_at += counts[1];
    string_at += counts[2];
    bool ok = true;
    if (tag == "interpolateboundary") {
      ok = read_interpolate_boundary(args, tags, error);
    } else if (tag == "crease") {
      ok = read_crease(args, vertex_count, tags, error);
    } else if (tag == "corner") {
      ok = read_corner(args, vertex_count, tags, error);
    } else if (tag == "hole") {
      ok = read_hole(args, face_count, tags, error);
    } else if (is_known_unsupported_tag(tag)) {
      warnings.push_back(fmt::format("tag \"{}\" is not supported: ignored", tag));
    } else {
      warnings.push_back(fmt::format("unknown tag \"{}\": ignored", tag));
    }
    if (!ok) return false;
  }
  if (int_at != request.intargs.size() || float_at != request.floatargs.size() ||
      string_at != request.stringargs.size()) {
    error = fmt::format(
        "nargs uses {} integers, {} floats and {} strings, but intargs, floatargs and stringargs "
        "have {}, {} and {}",
        int_at, float_at, string_at, request.intargs.size(), request.floatargs.size(), request.stringargs.size());
    return false;
  }
  return true;
}

}  // namespace darc
