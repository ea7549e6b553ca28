// A RiTarget that keeps every call it is given, in order, to be replayed into another target
// later: the parsed form of an archive that the run reads many times (archive_cache.h). Each
// call keeps copies of its arguments, so a replay hands the target the same parameter lists
// every time.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "parser/ri_target.h"

namespace darc {

class CallRecorder : public RiTarget {
 public:
  using Call = std::function<void(RiTarget&)>;
  // What a recorded call is: the call itself, and its request and position for messages.
  struct Entry {
    Call call;
    std::string request;
    SourceLoc loc;
    // For the parser's own view of the state (conditional RIB): Option and Attribute keep their
    // category and parameters, FrameBegin its number.
    std::string category;
    std::shared_ptr<const ParamList> params;
    int number = 0;
  };
  // Each call is handed to `sink` as it arrives (so that it can be ordered with the diagnostics
  // of the same text).
  explicit CallRecorder(std::function<void(Entry)> sink) : sink_(std::move(sink)) {}

  void version(double v, const SourceLoc& loc) override;
  void declare(const std::string& name, const std::string& declaration, const SourceLoc& loc) override;
  void option(const std::string& category, const ParamList& params, const SourceLoc& loc) override;
  void format(int xres, int yres, double pixel_aspect, const SourceLoc& loc) override;
  void frame_aspect_ratio(double ratio, const SourceLoc& loc) override;
  void screen_window(double left, double right, double bottom, double top, const SourceLoc& loc) override;
  void crop_window(double xmin, double xmax, double ymin, double ymax, const SourceLoc& loc) override;
  void projection(const std::string& name, const ParamList& params, const SourceLoc& loc) override;
  void clipping(double near_plane, double far_plane, const SourceLoc& loc) override;
  void pixel_samples(double xs, double ys, const SourceLoc& loc) override;
  void pixel_filter(const std::string& name, double xwidth, double ywidth, const SourceLoc& loc) override;
  void exposure(double gain, double gamma, const SourceLoc& loc) override;
  void quantize(const std::string& type, int one, int qmin, int qmax, double dither, const SourceLoc& loc) override;
  void display(const std::string& name, const std::string& type, const std::string& mode, const ParamList& params,
               const SourceLoc& loc) override;
  void hider(const std::string& type, const ParamList& params, const SourceLoc& loc) override;
  void ignored_request(const std::string& request, const std::vector<double>& numbers,
                       const std::vector<std::string>& strings, const SourceLoc& loc) override;
  void frame_begin(int number, const SourceLoc& loc) override;
  void frame_end(const SourceLoc& loc) override;
  void world_begin(const SourceLoc& loc) override;
  void world_end(const SourceLoc& loc) override;
  void attribute_begin(const SourceLoc& loc) override;
  void attribute_end(const SourceLoc& loc) override;
  void transform_begin(const SourceLoc& loc) override;
  void transform_end(const SourceLoc& loc) override;
  void identity(const SourceLoc& loc) override;
  void transform(const std::array<double, 16>& m, const SourceLoc& loc) override;
  void concat_transform(const std::array<double, 16>& m, const SourceLoc& loc) override;
  void translate(double dx, double dy, double dz, const SourceLoc& loc) override;
  void rotate(double angle_degrees, double ax, double ay, double az, const SourceLoc& loc) override;
  void scale(double sx, double sy, double sz, const SourceLoc& loc) override;
  void perspective(double fov_degrees, const SourceLoc& loc) override;
  void coordinate_system(const std::string& name, const SourceLoc& loc) override;
  void coord_sys_transform(const std::string& name, const SourceLoc& loc) override;
  void attribute(const std::string& category, const ParamList& params, const SourceLoc& loc) override;
  void orientation(const std::string& name, const SourceLoc& loc) override;
  void reverse_orientation(const SourceLoc& loc) override;
  void sides(int n, const SourceLoc& loc) override;
  void color(const std::array<float, 3>& rgb, const SourceLoc& loc) override;
  void opacity(const std::array<float, 3>& rgb, const SourceLoc& loc) override;
  void surface(const std::string& name, const ParamList& params, const SourceLoc& loc) override;
  void displacement(const std::string& name, const ParamList& params, const SourceLoc& loc) override;
  void light_source(const std::string& name, const std::string& handle, const ParamList& params,
                    const SourceLoc& loc) override;
  void area_light_source(const std::string& name, const std::string& handle, const ParamList& params,
                         const SourceLoc& loc) override;
  void illuminate(const std::string& handle, bool on, const SourceLoc& loc) override;
  void basis(const BasisArg& ubasis, int ustep, const BasisArg& vbasis, int vstep, const SourceLoc& loc) override;
  void object_begin(const std::string& handle, const SourceLoc& loc) override;
  void object_end(const SourceLoc& loc) override;
  void object_instance(const std::string& handle, const SourceLoc& loc) override;
  void curves(const std::string& type, const std::vector<int>& nvertices, const std::string& wrap,
              const ParamList& params, const SourceLoc& loc) override;
  void primitive(const PrimitiveRequest& request, const ParamList& params, const SourceLoc& loc) override;
  void polygon(const ParamList& params, const SourceLoc& loc) override;
  void general_polygon(const std::vector<int>& nverts_per_loop, const ParamList& params, const SourceLoc& loc) override;
  void points_polygons(const std::vector<int>& nverts_per_face, const std::vector<int>& indices,
                       const ParamList& params, const SourceLoc& loc) override;
  void points_general_polygons(const std::vector<int>& nloops_per_face, const std::vector<int>& nverts_per_loop,
                               const std::vector<int>& indices, const ParamList& params,
                               const SourceLoc& loc) override;
  void skipped_primitive(const std::string& request, const SourceLoc& loc) override;

 private:
  void keep(std::string request, const SourceLoc& loc, Call call) {
    sink_(Entry{std::move(call), std::move(request), loc, {}, nullptr, 0});
  }
  std::function<void(Entry)> sink_;
};

}  // namespace darc
