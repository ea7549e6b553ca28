// The RenderMan Interface as an abstract target: one virtual function per RI request, like the
// RenderMan C API (and pbrt's ParserTarget). The RIB parser calls it; SceneBuilder (core/)
// builds scenes from it, RibWriter pretty-prints it (darc --cat).
//
// Every call carries the SourceLoc of the request name. A target reports a scene error in a
// request by throwing RibError; the parser reports it with the position and continues at the
// next request. Warnings go to the Diagnostics object the target was constructed with.
#pragma once

#include "parser/param_list.h"
#include "parser/source_loc.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace darc {

// A Basis argument: a standard name ("bezier", "b-spline", "catmull-rom", "hermite", "power")
// or 16 numbers (row-major, rows multiply [t^3 t^2 t 1]).
struct BasisArg {
  std::string name;  // empty when a matrix was given
  std::array<double, 16> matrix{};
};

// What the frame being built makes of a procedural's bound, asked before the procedural is read
// or run (RiTarget::procedural_bound).
struct ProceduralBound {
  bool wanted = true;      // false: nothing inside it can reach an image (its frame is not rendered)
  double raster_area = 0;  // pixels the bound covers in the image (RunProgram's "detail"); 0: unknown
};

// A geometry request other than Curves and the four polygon requests (Sphere and the other
// quadrics, Patch, PatchMesh, NuPatch, SubdivisionMesh, Points): its name and its fixed
// arguments in the order the request has them, split by type (parser/primitive_signatures.h
// says which request has which). One RiTarget method carries them all, so that the interface
// does not grow a method per geometry request (DESIGN.md point 1); what each position means
// belongs to the target that builds it.
struct PrimitiveRequest {
  std::string name;
  std::vector<double> numbers;  // numeric scalars, integers included (PatchMesh's nu, nv)
  std::vector<std::string> strings;
  std::vector<std::vector<int>> integer_arrays;
  std::vector<std::vector<double>> number_arrays;
  std::vector<std::vector<std::string>> string_arrays;
};

class RiTarget {
 public:
  virtual ~RiTarget() = default;

  // The parser calls this before each call it replays from its archive cache with a number
  // unique, for the run, to that recorded call, and with 0 after it: the same number means the
  // same request with the same arguments, so a target may reuse what it built from it before.
  virtual void replayed_request(uint64_t id) { (void)id; }

  virtual void version(double v, const SourceLoc& loc) = 0;
  virtual void declare(const std::string& name, const std::string& declaration, const SourceLoc& loc) = 0;

  // Options
  virtual void option(const std::string& category, const ParamList& params, const SourceLoc& loc) = 0;
  virtual void format(int xres, int yres, double pixel_aspect, const SourceLoc& loc) = 0;
  virtual void frame_aspect_ratio(double ratio, const SourceLoc& loc) = 0;
  virtual void screen_window(double left, double right, double bottom, double top, const SourceLoc& loc) = 0;
  virtual void crop_window(double xmin, double xmax, double ymin, double ymax, const SourceLoc& loc) = 0;
  virtual void projection(const std::string& name, const ParamList& params, const SourceLoc& loc) = 0;
  virtual void clipping(double near_plane, double far_plane, const SourceLoc& loc) = 0;
  virtual void pixel_samples(double xs, double ys, const SourceLoc& loc) = 0;
  virtual void pixel_filter(const std::string& name, double xwidth, double ywidth, const SourceLoc& loc) = 0;
  virtual void exposure(double gain, double gamma, const SourceLoc& loc) = 0;
  virtual void quantize(const std::string& type, int one, int qmin, int qmax, double dither,
                        const SourceLoc& loc) = 0;
  virtual void display(const std::string& name, const std::string& type, const std::string& mode,
                       const ParamList& params, const SourceLoc& loc) = 0;
  virtual void hider(const std::string& type, const ParamList& params, const SourceLoc& loc) = 0;
  // Requests that are accepted and have no effect on our images (Shutter, ShadingRate,
  // ShadingInterpolation, ...): passed on with their raw numeric/string arguments so that a
  // writer can reproduce them.
  virtual void ignored_request(const std::string& request, const std::vector<double>& numbers,
                               const std::vector<std::string>& strings, const SourceLoc& loc) = 0;

  // Blocks
  virtual void frame_begin(int number, const SourceLoc& loc) = 0;
  virtual void frame_end(const SourceLoc& loc) = 0;
  virtual void world_begin(const SourceLoc& loc) = 0;
  virtual void world_end(const SourceLoc& loc) = 0;
  virtual void attribute_begin(const SourceLoc& loc) = 0;
  virtual void attribute_end(const SourceLoc& loc) = 0;
  virtual void transform_begin(const SourceLoc& loc) = 0;
  virtual void transform_end(const SourceLoc& loc) = 0;

  // Transforms (matrices are 16 numbers, RIB row-major order)
  virtual void identity(const SourceLoc& loc) = 0;
  virtual void transform(const std::array<double, 16>& m, const SourceLoc& loc) = 0;
  virtual void concat_transform(const std::array<double, 16>& m, const SourceLoc& loc) = 0;
  virtual void translate(double dx, double dy, double dz, const SourceLoc& loc) = 0;
  virtual void rotate(double angle_degrees, double ax, double ay, double az, const SourceLoc& loc) = 0;
  virtual void scale(double sx, double sy, double sz, const SourceLoc& loc) = 0;
  virtual void perspective(double fov_degrees, const SourceLoc& loc) = 0;
  virtual void coordinate_system(const std::string& name, const SourceLoc& loc) = 0;
  virtual void coord_sys_transform(const std::string& name, const SourceLoc& loc) = 0;

  // Attributes
  virtual void attribute(const std::string& category, const ParamList& params, const SourceLoc& loc) = 0;
  virtual void orientation(const std::string& name, const SourceLoc& loc) = 0;
  virtual void reverse_orientation(const SourceLoc& loc) = 0;
  virtual void sides(int n, const SourceLoc& loc) = 0;
  virtual void color(const std::array<float, 3>& rgb, const SourceLoc& loc) = 0;
  virtual void opacity(const std::array<float, 3>& rgb, const SourceLoc& loc) = 0;
  virtual void surface(const std::string& name, const ParamList& params, const SourceLoc& loc) = 0;
  virtual void displacement(const std::string& name, const ParamList& params, const SourceLoc& loc) = 0;
  // handle: the light's sequence number or name, as written.
  virtual void light_source(const std::string& name, const std::string& handle, const ParamList& params,
                            const SourceLoc& loc) = 0;
  virtual void area_light_source(const std::string& name, const std::string& handle, const ParamList& params,
                                 const SourceLoc& loc) = 0;
  virtual void illuminate(const std::string& handle, bool on, const SourceLoc& loc) = 0;
  virtual void basis(const BasisArg& ubasis, int ustep, const BasisArg& vbasis, int vstep, const SourceLoc& loc) = 0;

  // Instancing
  virtual void object_begin(const std::string& handle, const SourceLoc& loc) = 0;
  virtual void object_end(const SourceLoc& loc) = 0;
  virtual void object_instance(const std::string& handle, const SourceLoc& loc) = 0;

  // Geometry
  virtual void curves(const std::string& type, const std::vector<int>& nvertices, const std::string& wrap,
                      const ParamList& params, const SourceLoc& loc) = 0;
  virtual void primitive(const PrimitiveRequest& request, const ParamList& params, const SourceLoc& loc) = 0;
  virtual void polygon(const ParamList& params, const SourceLoc& loc) = 0;
  virtual void general_polygon(const std::vector<int>& nverts_per_loop, const ParamList& params,
                               const SourceLoc& loc) = 0;
  virtual void points_polygons(const std::vector<int>& nverts_per_face, const std::vector<int>& indices,
                               const ParamList& params, const SourceLoc& loc) = 0;
  virtual void points_general_polygons(const std::vector<int>& nloops_per_face, const std::vector<int>& nverts_per_loop,
                                       const std::vector<int>& indices, const ParamList& params,
                                       const SourceLoc& loc) = 0;
  // A geometric primitive request that darc knows but does not implement (Blobby, Curves of
  // a kind, ...: known_requests.h): the parser has warned and skips its
  // arguments. It lets a target tell a frame whose every primitive was skipped from an empty one.
  virtual void skipped_primitive(const std::string& request, const SourceLoc& loc) = 0;

  // Procedurals are expanded by the parser (the target sees what they produce, inside an
  // AttributeBegin/AttributeEnd pair); this asks first about the bound (xmin xmax ymin ymax zmin
  // zmax in the current object space). The default: wanted, area unknown.
  virtual ProceduralBound procedural_bound(const std::array<double, 6>& /*bound*/, const SourceLoc& /*loc*/) {
    return {};
  }
};

}  // namespace darc
