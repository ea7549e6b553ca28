#include "parser/rib_writer.h"

#include "parser/primitive_signatures.h"

#include <charconv>
#include <type_traits>

namespace darc {

namespace {

// Spaces per block level.
constexpr int kIndentWidth = 2;

template <typename T>
std::string shortest(T v) {
  char buf[64];
  const auto result = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, result.ptr);
}

template <typename Range>
std::string bracketed(const Range& values) {
  std::string s = "[";
  bool first = true;
  for (const auto& v : values) {
    if (!first) s += ' ';
    first = false;
    if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::string>) {
      s += rib_string(v);
    } else if constexpr (std::is_same_v<std::decay_t<decltype(v)>, int>) {
      s += std::to_string(v);
    } else {
      s += rib_number(v);
    }
  }
  return s + "]";
}

// A handle that was written as an integer is written back as one.
std::string rib_handle(const std::string& handle) {
  const bool integer = !handle.empty() && handle.size() < 10 &&
                       handle.find_first_not_of("0123456789") == std::string::npos &&
                       (handle == "0" || handle.front() != '0');
  return integer ? handle : rib_string(handle);
}

std::string rib_basis(const BasisArg& b) { return b.name.empty() ? bracketed(b.matrix) : rib_string(b.name); }

}  // namespace

std::string rib_number(double v) { return shortest(v); }
std::string rib_number(float v) { return shortest(v); }

std::string rib_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        out += c;
    }
  }
  return out + "\"";
}

std::ostream& RibWriter::begin_line(const char* request) {
  out_ << std::string(static_cast<size_t>(depth_ * kIndentWidth), ' ') << request;
  return out_;
}

void RibWriter::open_block(const char* request) {
  begin_line(request) << '\n';
  ++depth_;
}

void RibWriter::close_block(const char* request) {
  if (depth_ > 0) --depth_;
  begin_line(request) << '\n';
}

void RibWriter::write_params(const ParamList& params) {
  for (const Param& p : params.params) {
    out_ << ' ' << rib_string(to_string(p.decl) + " " + p.name) << ' ';
    if (p.decl.is_string()) {
      out_ << bracketed(p.strings);
    } else {
      out_ << bracketed(p.floats);
    }
  }
  out_ << '\n';
}

void RibWriter::version(double v, const SourceLoc&) { begin_line("version") << ' ' << rib_number(v) << '\n'; }

void RibWriter::declare(const std::string& name, const std::string& declaration, const SourceLoc&) {
  begin_line("Declare") << ' ' << rib_string(name) << ' ' << rib_string(declaration) << '\n';
}

void RibWriter::option(const std::string& category, const ParamList& params, const SourceLoc&) {
  begin_line("Option") << ' ' << rib_string(category);
  write_params(params);
}

void RibWriter::format(int xres, int yres, double pixel_aspect, const SourceLoc&) {
  begin_line("Format") << ' ' << xres << ' ' << yres << ' ' << rib_number(pixel_aspect) << '\n';
}

void RibWriter::frame_aspect_ratio(double ratio, const SourceLoc&) {
  begin_line("FrameAspectRatio") << ' ' << rib_number(ratio) << '\n';
}

void RibWriter::screen_window(double left, double right, double bottom, double top, const SourceLoc&) {
  begin_line("ScreenWindow") << ' ' << rib_number(left) << ' ' << rib_number(right) << ' ' << rib_number(bottom) << ' '
                             << rib_number(top) << '\n';
}

void RibWriter::crop_window(double xmin, double xmax, double ymin, double ymax, const SourceLoc&) {
  begin_line("CropWindow") << ' ' << rib_number(xmin) << ' ' << rib_number(xmax) << ' ' << rib_number(ymin) << ' '
                           << rib_number(ymax) << '\n';
}

void RibWriter::projection(const std::string& name, const ParamList& params, const SourceLoc&) {
  begin_line("Projection") << ' ' << rib_string(name);
  write_params(params);
}

void RibWriter::clipping(double near_plane, double far_plane, const SourceLoc&) {
  begin_line("Clipping") << ' ' << rib_number(near_plane) << ' ' << rib_number(far_plane) << '\n';
}

void RibWriter::pixel_samples(double xs, double ys, const SourceLoc&) {
  begin_line("PixelSamples") << ' ' << rib_number(xs) << ' ' << rib_number(ys) << '\n';
}

void RibWriter::pixel_filter(const std::string& name, double xwidth, double ywidth, const SourceLoc&) {
  begin_line("PixelFilter") << ' ' << rib_string(name) << ' ' << rib_number(xwidth) << ' ' << rib_number(ywidth)
                            << '\n';
}

void RibWriter::exposure(double gain, double gamma, const SourceLoc&) {
  begin_line("Exposure") << ' ' << rib_number(gain) << ' ' << rib_number(gamma) << '\n';
}

void RibWriter::quantize(const std::string& type, int one, int qmin, int qmax, double dither, const SourceLoc&) {
  begin_line("Quantize") << ' ' << rib_string(type) << ' ' << one << ' ' << qmin << ' ' << qmax << ' '
                         << rib_number(dither) << '\n';
}

void RibWriter::display(const std::string& name, const std::string& type, const std::string& mode,
                        const ParamList& params, const SourceLoc&) {
  begin_line("Display") << ' ' << rib_string(name) << ' ' << rib_string(type) << ' ' << rib_string(mode);
  write_params(params);
}

void RibWriter::hider(const std::string& type, const ParamList& params, const SourceLoc&) {
  begin_line("Hider") << ' ' << rib_string(type);
  write_params(params);
}

void RibWriter::ignored_request(const std::string& request, const std::vector<double>& numbers,
                                const std::vector<std::string>& strings, const SourceLoc&) {
  // Strings first, then numbers: the order of every ignored request's fixed arguments.
  std::ostream& line = begin_line(request.c_str());
  for (const std::string& s : strings) line << ' ' << rib_string(s);
  for (double v : numbers) line << ' ' << rib_number(v);
  line << '\n';
}

void RibWriter::frame_begin(int number, const SourceLoc&) {
  begin_line("FrameBegin") << ' ' << number << '\n';
  ++depth_;
}
void RibWriter::frame_end(const SourceLoc&) { close_block("FrameEnd"); }
void RibWriter::world_begin(const SourceLoc&) { open_block("WorldBegin"); }
void RibWriter::world_end(const SourceLoc&) { close_block("WorldEnd"); }
void RibWriter::attribute_begin(const SourceLoc&) { open_block("AttributeBegin"); }
void RibWriter::attribute_end(const SourceLoc&) { close_block("AttributeEnd"); }
void RibWriter::transform_begin(const SourceLoc&) { open_block("TransformBegin"); }
void RibWriter::transform_end(const SourceLoc&) { close_block("TransformEnd"); }

void RibWriter::identity(const SourceLoc&) { begin_line("Identity") << '\n'; }

void RibWriter::transform(const std::array<double, 16>& m, const SourceLoc&) {
  begin_line("Transform") << ' ' << bracketed(m) << '\n';
}

void RibWriter::concat_transform(const std::array<double, 16>& m, const SourceLoc&) {
  begin_line("ConcatTransform") << ' ' << bracketed(m) << '\n';
}

void RibWriter::translate(double dx, double dy, double dz, const SourceLoc&) {
  begin_line("Translate") << ' ' << rib_number(dx) << ' ' << rib_number(dy) << ' ' << rib_number(dz) << '\n';
}

void RibWriter::rotate(double angle_degrees, double ax, double ay, double az, const SourceLoc&) {
  begin_line("Rotate") << ' ' << rib_number(angle_degrees) << ' ' << rib_number(ax) << ' ' << rib_number(ay) << ' '
                       << rib_number(az) << '\n';
}

void RibWriter::scale(double sx, double sy, double sz, const SourceLoc&) {
  begin_line("Scale") << ' ' << rib_number(sx) << ' ' << rib_number(sy) << ' ' << rib_number(sz) << '\n';
}

void RibWriter::perspective(double fov_degrees, const SourceLoc&) {
  begin_line("Perspective") << ' ' << rib_number(fov_degrees) << '\n';
}

void RibWriter::coordinate_system(const std::string& name, const SourceLoc&) {
  begin_line("CoordinateSystem") << ' ' << rib_string(name) << '\n';
}

void RibWriter::coord_sys_transform(const std::string& name, const SourceLoc&) {
  begin_line("CoordSysTransform") << ' ' << rib_string(name) << '\n';
}

void RibWriter::attribute(const std::string& category, const ParamList& params, const SourceLoc&) {
  begin_line("Attribute") << ' ' << rib_string(category);
  write_params(params);
}

void RibWriter::orientation(const std::string& name, const SourceLoc&) {
  begin_line("Orientation") << ' ' << rib_string(name) << '\n';
}

void RibWriter::reverse_orientation(const SourceLoc&) { begin_line("ReverseOrientation") << '\n'; }

void RibWriter::sides(int n, const SourceLoc&) { begin_line("Sides") << ' ' << n << '\n'; }

void RibWriter::color(const std::array<float, 3>& rgb, const SourceLoc&) {
  begin_line("Color") << ' ' << bracketed(rgb) << '\n';
}

void RibWriter::opacity(const std::array<float, 3>& rgb, const SourceLoc&) {
  begin_line("Opacity") << ' ' << bracketed(rgb) << '\n';
}

void RibWriter::surface(const std::string& name, const ParamList& params, const SourceLoc&) {
  begin_line("Surface") << ' ' << rib_string(name);
  write_params(params);
}

void RibWriter::displacement(const std::string& name, const ParamList& params, const SourceLoc&) {
  begin_line("Displacement") << ' ' << rib_string(name);
  write_params(params);
}

void RibWriter::light_source(const std::string& name, const std::string& handle, const ParamList& params,
                             const SourceLoc&) {
  begin_line("LightSource") << ' ' << rib_string(name) << ' ' << rib_handle(handle);
  write_params(params);
}

void RibWriter::area_light_source(const std::string& name, const std::string& handle, const ParamList& params,
                                  const SourceLoc&) {
  begin_line("AreaLightSource") << ' ' << rib_string(name) << ' ' << rib_handle(handle);
  write_params(params);
}

void RibWriter::illuminate(const std::string& handle, bool on, const SourceLoc&) {
  begin_line("Illuminate") << ' ' << rib_handle(handle) << ' ' << (on ? 1 : 0) << '\n';
}

void RibWriter::basis(const BasisArg& ubasis, int ustep, const BasisArg& vbasis, int vstep, const SourceLoc&) {
  begin_line("Basis") << ' ' << rib_basis(ubasis) << ' ' << ustep << ' ' << rib_basis(vbasis) << ' ' << vstep << '\n';
}

void RibWriter::object_begin(const std::string& handle, const SourceLoc&) {
  begin_line("ObjectBegin") << ' ' << rib_handle(handle) << '\n';
  ++depth_;
}

void RibWriter::object_end(const SourceLoc&) { close_block("ObjectEnd"); }

void RibWriter::object_instance(const std::string& handle, const SourceLoc&) {
  begin_line("ObjectInstance") << ' ' << rib_handle(handle) << '\n';
}

void RibWriter::curves(const std::string& type, const std::vector<int>& nvertices, const std::string& wrap,
                       const ParamList& params, const SourceLoc&) {
  begin_line("Curves") << ' ' << rib_string(type) << ' ' << bracketed(nvertices) << ' ' << rib_string(wrap);
  write_params(params);
}

void RibWriter::primitive(const PrimitiveRequest& r, const ParamList& params, const SourceLoc&) {
  std::ostream& out = begin_line(r.name.c_str());
  size_t number = 0, string = 0, ints = 0, numbers = 0, strings = 0;
  // The typed lists are written back in the order of the request's signature; optional arrays
  // that were left out are not in the lists.
  const PrimitiveSignature* signature = find_primitive_signature(r.name);
  for (const PrimitiveArgSpec& a : signature ? signature->args : std::span<const PrimitiveArgSpec>{}) {
    switch (a.type) {
      case PrimitiveArgType::Number:
      case PrimitiveArgType::Integer:
        if (number < r.numbers.size()) out << ' ' << rib_number(r.numbers[number++]);
        break;
      case PrimitiveArgType::String:
        if (string < r.strings.size()) out << ' ' << rib_string(r.strings[string++]);
        break;
      case PrimitiveArgType::IntegerArray:
        if (ints < r.integer_arrays.size()) out << ' ' << bracketed(r.integer_arrays[ints++]);
        break;
      case PrimitiveArgType::NumberArray:
        if (numbers < r.number_arrays.size()) out << ' ' << bracketed(r.number_arrays[numbers++]);
        break;
      case PrimitiveArgType::StringArray:
        if (strings < r.string_arrays.size()) out << ' ' << bracketed(r.string_arrays[strings++]);
        break;
    }
  }
  write_params(params);
}

void RibWriter::polygon(const ParamList& params, const SourceLoc&) {
  begin_line("Polygon");
  write_params(params);
}

void RibWriter::general_polygon(const std::vector<int>& nverts_per_loop, const ParamList& params, const SourceLoc&) {
  begin_line("GeneralPolygon") << ' ' << bracketed(nverts_per_loop);
  write_params(params);
}

void RibWriter::points_polygons(const std::vector<int>& nverts_per_face, const std::vector<int>& indices,
                                const ParamList& params, const SourceLoc&) {
  begin_line("PointsPolygons") << ' ' << bracketed(nverts_per_face) << ' ' << bracketed(indices);
  write_params(params);
}

void RibWriter::points_general_polygons(const std::vector<int>& nloops_per_face,
                                        const std::vector<int>& nverts_per_loop, const std::vector<int>& indices,
                                        const ParamList& params, const SourceLoc&) {
  begin_line("PointsGeneralPolygons") << ' ' << bracketed(nloops_per_face) << ' ' << bracketed(nverts_per_loop) << ' '
                                      << bracketed(indices);
  write_params(params);
}

}  // namespace darc
