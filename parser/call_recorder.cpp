#include "parser/call_recorder.h"

namespace darc {

// Each call captures its arguments by value; the replayed call passes the captured copies.

void CallRecorder::version(double v, const SourceLoc& loc) {
  keep("Version", loc, [v, loc](RiTarget& t) { t.version(v, loc); });
}

void CallRecorder::declare(const std::string& name, const std::string& declaration, const SourceLoc& loc) {
  keep("Declare", loc, [name, declaration, loc](RiTarget& t) { t.declare(name, declaration, loc); });
}

void CallRecorder::option(const std::string& category, const ParamList& params, const SourceLoc& loc) {
  auto kept = std::make_shared<const ParamList>(params);
  sink_(Entry{[category, kept, loc](RiTarget& t) { t.option(category, *kept, loc); }, "Option", loc, category, kept, 0});
}

void CallRecorder::format(int xres, int yres, double pixel_aspect, const SourceLoc& loc) {
  keep("Format", loc, [xres, yres, pixel_aspect, loc](RiTarget& t) { t.format(xres, yres, pixel_aspect, loc); });
}

void CallRecorder::frame_aspect_ratio(double ratio, const SourceLoc& loc) {
  keep("FrameAspectRatio", loc, [ratio, loc](RiTarget& t) { t.frame_aspect_ratio(ratio, loc); });
}

void CallRecorder::screen_window(double left, double right, double bottom, double top, const SourceLoc& loc) {
  keep("ScreenWindow", loc, [left, right, bottom, top, loc](RiTarget& t) { t.screen_window(left, right, bottom, top, loc); });
}

void CallRecorder::crop_window(double xmin, double xmax, double ymin, double ymax, const SourceLoc& loc) {
  keep("CropWindow", loc, [xmin, xmax, ymin, ymax, loc](RiTarget& t) { t.crop_window(xmin, xmax, ymin, ymax, loc); });
}

void CallRecorder::projection(const std::string& name, const ParamList& params, const SourceLoc& loc) {
  keep("Projection", loc, [name, params, loc](RiTarget& t) { t.projection(name, params, loc); });
}

void CallRecorder::clipping(double near_plane, double far_plane, const SourceLoc& loc) {
  keep("Clipping", loc, [near_plane, far_plane, loc](RiTarget& t) { t.clipping(near_plane, far_plane, loc); });
}

void CallRecorder::pixel_samples(double xs, double ys, const SourceLoc& loc) {
  keep("PixelSamples", loc, [xs, ys, loc](RiTarget& t) { t.pixel_samples(xs, ys, loc); });
}

void CallRecorder::pixel_filter(const std::string& name, double xwidth, double ywidth, const SourceLoc& loc) {
  keep("PixelFilter", loc, [name, xwidth, ywidth, loc](RiTarget& t) { t.pixel_filter(name, xwidth, ywidth, loc); });
}

void CallRecorder::exposure(double gain, double gamma, const SourceLoc& loc) {
  keep("Exposure", loc, [gain, gamma, loc](RiTarget& t) { t.exposure(gain, gamma, loc); });
}

void CallRecorder::quantize(const std::string& type, int one, int qmin, int qmax, double dither, const SourceLoc& loc) {
  keep("Quantize", loc, [type, one, qmin, qmax, dither, loc](RiTarget& t) { t.quantize(type, one, qmin, qmax, dither, loc); });
}

void CallRecorder::display(const std::string& name, const std::string& type, const std::string& mode, const ParamList& params, const SourceLoc& loc) {
  keep("Display", loc, [name, type, mode, params, loc](RiTarget& t) { t.display(name, type, mode, params, loc); });
}

void CallRecorder::hider(const std::string& type, const ParamList& params, const SourceLoc& loc) {
  keep("Hider", loc, [type, params, loc](RiTarget& t) { t.hider(type, params, loc); });
}

void CallRecorder::ignored_request(const std::string& request, const std::vector<double>& numbers, const std::vector<std::string>& strings, const SourceLoc& loc) {
  keep(request, loc, [request, numbers, strings, loc](RiTarget& t) { t.ignored_request(request, numbers, strings, loc); });
}

void CallRecorder::frame_begin(int number, const SourceLoc& loc) {
  sink_(Entry{[number, loc](RiTarget& t) { t.frame_begin(number, loc); }, "FrameBegin", loc, {}, nullptr, number});
}

void CallRecorder::frame_end(const SourceLoc& loc) {
  keep("FrameEnd", loc, [loc](RiTarget& t) { t.frame_end(loc); });
}

void CallRecorder::world_begin(const SourceLoc& loc) {
  keep("WorldBegin", loc, [loc](RiTarget& t) { t.world_begin(loc); });
}

void CallRecorder::world_end(const SourceLoc& loc) {
  keep("WorldEnd", loc, [loc](RiTarget& t) { t.world_end(loc); });
}

void CallRecorder::attribute_begin(const SourceLoc& loc) {
  keep("AttributeBegin", loc, [loc](RiTarget& t) { t.attribute_begin(loc); });
}

void CallRecorder::attribute_end(const SourceLoc& loc) {
  keep("AttributeEnd", loc, [loc](RiTarget& t) { t.attribute_end(loc); });
}

void CallRecorder::transform_begin(const SourceLoc& loc) {
  keep("TransformBegin", loc, [loc](RiTarget& t) { t.transform_begin(loc); });
}

void CallRecorder::transform_end(const SourceLoc& loc) {
  keep("TransformEnd", loc, [loc](RiTarget& t) { t.transform_end(loc); });
}

void CallRecorder::identity(const SourceLoc& loc) {
  keep("Identity", loc, [loc](RiTarget& t) { t.identity(loc); });
}

void CallRecorder::transform(const std::array<double, 16>& m, const SourceLoc& loc) {
  keep("Transform", loc, [m, loc](RiTarget& t) { t.transform(m, loc); });
}

void CallRecorder::concat_transform(const std::array<double, 16>& m, const SourceLoc& loc) {
  keep("ConcatTransform", loc, [m, loc](RiTarget& t) { t.concat_transform(m, loc); });
}

void CallRecorder::translate(double dx, double dy, double dz, const SourceLoc& loc) {
  keep("Translate", loc, [dx, dy, dz, loc](RiTarget& t) { t.translate(dx, dy, dz, loc); });
}

void CallRecorder::rotate(double angle_degrees, double ax, double ay, double az, const SourceLoc& loc) {
  keep("Rotate", loc, [angle_degrees, ax, ay, az, loc](RiTarget& t) { t.rotate(angle_degrees, ax, ay, az, loc); });
}

void CallRecorder::scale(double sx, double sy, double sz, const SourceLoc& loc) {
  keep("Scale", loc, [sx, sy, sz, loc](RiTarget& t) { t.scale(sx, sy, sz, loc); });
}

void CallRecorder::perspective(double fov_degrees, const SourceLoc& loc) {
  keep("Perspective", loc, [fov_degrees, loc](RiTarget& t) { t.perspective(fov_degrees, loc); });
}

void CallRecorder::coordinate_system(const std::string& name, const SourceLoc& loc) {
  keep("CoordinateSystem", loc, [name, loc](RiTarget& t) { t.coordinate_system(name, loc); });
}

void CallRecorder::coord_sys_transform(const std::string& name, const SourceLoc& loc) {
  keep("CoordSysTransform", loc, [name, loc](RiTarget& t) { t.coord_sys_transform(name, loc); });
}

void CallRecorder::attribute(const std::string& category, const ParamList& params, const SourceLoc& loc) {
  auto kept = std::make_shared<const ParamList>(params);
  sink_(Entry{[category, kept, loc](RiTarget& t) { t.attribute(category, *kept, loc); }, "Attribute", loc, category,
              kept, 0});
}

void CallRecorder::orientation(const std::string& name, const SourceLoc& loc) {
  keep("Orientation", loc, [name, loc](RiTarget& t) { t.orientation(name, loc); });
}

void CallRecorder::reverse_orientation(const SourceLoc& loc) {
  keep("ReverseOrientation", loc, [loc](RiTarget& t) { t.reverse_orientation(loc); });
}

void CallRecorder::sides(int n, const SourceLoc& loc) {
  keep("Sides", loc, [n, loc](RiTarget& t) { t.sides(n, loc); });
}

void CallRecorder::color(const std::array<float, 3>& rgb, const SourceLoc& loc) {
  keep("Color", loc, [rgb, loc](RiTarget& t) { t.color(rgb, loc); });
}

void CallRecorder::opacity(const std::array<float, 3>& rgb, const SourceLoc& loc) {
  keep("Opacity", loc, [rgb, loc](RiTarget& t) { t.opacity(rgb, loc); });
}

void CallRecorder::surface(const std::string& name, const ParamList& params, const SourceLoc& loc) {
  keep("Surface", loc, [name, params, loc](RiTarget& t) { t.surface(name, params, loc); });
}

void CallRecorder::displacement(const std::string& name, const ParamList& params, const SourceLoc& loc) {
  keep("Displacement", loc, [name, params, loc](RiTarget& t) { t.displacement(name, params, loc); });
}

void CallRecorder::light_source(const std::string& name, const std::string& handle, const ParamList& params, const SourceLoc& loc) {
  keep("LightSource", loc, [name, handle, params, loc](RiTarget& t) { t.light_source(name, handle, params, loc); });
}

void CallRecorder::area_light_source(const std::string& name, const std::string& handle, const ParamList& params, const SourceLoc& loc) {
  keep("AreaLightSource", loc, [name, handle, params, loc](RiTarget& t) { t.area_light_source(name, handle, params, loc); });
}

void CallRecorder::illuminate(const std::string& handle, bool on, const SourceLoc& loc) {
  keep("Illuminate", loc, [handle, on, loc](RiTarget& t) { t.illuminate(handle, on, loc); });
}

void CallRecorder::basis(const BasisArg& ubasis, int ustep, const BasisArg& vbasis, int vstep, const SourceLoc& loc) {
  keep("Basis", loc, [ubasis, ustep, vbasis, vstep, loc](RiTarget& t) { t.basis(ubasis, ustep, vbasis, vstep, loc); });
}

void CallRecorder::object_begin(const std::string& handle, const SourceLoc& loc) {
  keep("ObjectBegin", loc, [handle, loc](RiTarget& t) { t.object_begin(handle, loc); });
}

void CallRecorder::object_end(const SourceLoc& loc) {
  keep("ObjectEnd", loc, [loc](RiTarget& t) { t.object_end(loc); });
}

void CallRecorder::object_instance(const std::string& handle, const SourceLoc& loc) {
  keep("ObjectInstance", loc, [handle, loc](RiTarget& t) { t.object_instance(handle, loc); });
}

void CallRecorder::curves(const std::string& type, const std::vector<int>& nvertices, const std::string& wrap, const ParamList& params, const SourceLoc& loc) {
  keep("Curves", loc, [type, nvertices, wrap, params, loc](RiTarget& t) { t.curves(type, nvertices, wrap, params, loc); });
}

void CallRecorder::primitive(const PrimitiveRequest& request, const ParamList& params, const SourceLoc& loc) {
  keep(request.name, loc, [request, params, loc](RiTarget& t) { t.primitive(request, params, loc); });
}

void CallRecorder::polygon(const ParamList& params, const SourceLoc& loc) {
  keep("Polygon", loc, [params, loc](RiTarget& t) { t.polygon(params, loc); });
}

void CallRecorder::general_polygon(const std::vector<int>& nverts_per_loop, const ParamList& params, const SourceLoc& loc) {
  keep("GeneralPolygon", loc, [nverts_per_loop, params, loc](RiTarget& t) { t.general_polygon(nverts_per_loop, params, loc); });
}

void CallRecorder::points_polygons(const std::vector<int>& nverts_per_face, const std::vector<int>& indices, const ParamList& params, const SourceLoc& loc) {
  keep("PointsPolygons", loc, [nverts_per_face, indices, params, loc](RiTarget& t) { t.points_polygons(nverts_per_face, indices, params, loc); });
}

void CallRecorder::points_general_polygons(const std::vector<int>& nloops_per_face, const std::vector<int>& nverts_per_loop, const std::vector<int>& indices, const ParamList& params, const SourceLoc& loc) {
  keep("PointsGeneralPolygons", loc, [nloops_per_face, nverts_per_loop, indices, params, loc](RiTarget& t) { t.points_general_polygons(nloops_per_face, nverts_per_loop, indices, params, loc); });
}

void CallRecorder::skipped_primitive(const std::string& request, const SourceLoc& loc) {
  keep(request, loc, [request, loc](RiTarget& t) { t.skipped_primitive(request, loc); });
}

}  // namespace darc
