#include "parser/request_table.h"

#include "parser/primitive_signatures.h"

#include <array>
#include <unordered_map>

namespace darc {

namespace {

using Ctx = RequestContext;

std::array<float, 3> to_rgb(const std::array<double, 3>& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

// --- requests without effect: arguments flattened, any parameter list checked and dropped ---

void ignored(Ctx& c) {
  std::vector<double> numbers;
  std::vector<std::string> strings;
  c.args.flatten_rest(numbers, strings);
  c.target.ignored_request(c.name, numbers, strings, c.loc);
}

// An ignored request with FixedStrings leading strings, then FixedNumbers numbers, then a plist.
template <int FixedStrings, int FixedNumbers>
void ignored_with_params(Ctx& c) {
  std::vector<double> numbers;
  std::vector<std::string> strings;
  for (int i = 0; i < FixedStrings; ++i) strings.push_back(c.args.string("a fixed argument"));
  for (int i = 0; i < FixedNumbers; ++i) numbers.push_back(c.args.number("a fixed argument"));
  c.args.skip_param_list(c.name);
  c.target.ignored_request(c.name, numbers, strings, c.loc);
}

// --- options ---

void version(Ctx& c) {
  const double v = c.args.number("the version");
  c.args.expect_request_end("version");
  c.target.version(v, c.loc);
}

void format(Ctx& c) {
  const int x = c.args.integer("xres");
  const int y = c.args.integer("yres");
  const double aspect = c.args.number("pixelaspect");
  c.args.expect_request_end("Format");
  c.target.format(x, y, aspect, c.loc);
}

void frame_aspect_ratio(Ctx& c) {
  const double r = c.args.number("the frame aspect ratio");
  c.args.expect_request_end("FrameAspectRatio");
  c.target.frame_aspect_ratio(r, c.loc);
}

void screen_window(Ctx& c) {
  const auto w = c.args.numbers<4>("the screen window");
  c.args.expect_request_end("ScreenWindow");
  c.target.screen_window(w[0], w[1], w[2], w[3], c.loc);
}

void crop_window(Ctx& c) {
  const auto w = c.args.numbers<4>("the crop window");
  c.args.expect_request_end("CropWindow");
  c.target.crop_window(w[0], w[1], w[2], w[3], c.loc);
}

void projection(Ctx& c) {
  const std::string name = c.args.string("the projection name");
  c.target.projection(name, c.args.param_list(c.name), c.loc);
}

void clipping(Ctx& c) {
  const auto n = c.args.numbers<2>("the clipping planes");
  c.args.expect_request_end("Clipping");
  c.target.clipping(n[0], n[1], c.loc);
}

void pixel_samples(Ctx& c) {
  const auto n = c.args.numbers<2>("the pixel samples");
  c.args.expect_request_end("PixelSamples");
  c.target.pixel_samples(n[0], n[1], c.loc);
}

void pixel_filter(Ctx& c) {
  const std::string name = c.args.string("the filter name");
  const double xw = c.args.number("xwidth");
  const double yw = c.args.number("ywidth");
  c.args.expect_request_end("PixelFilter");
  c.target.pixel_filter(name, xw, yw, c.loc);
}

void exposure(Ctx& c) {
  const double gain = c.args.number("gain");
  const double gamma = c.args.number("gamma");
  c.args.expect_request_end("Exposure");
  c.target.exposure(gain, gamma, c.loc);
}

void quantize(Ctx& c) {
  const std::string type = c.args.string("the quantize type");
  const int one = c.args.integer("one");
  const int qmin = c.args.integer("min");
  const int qmax = c.args.integer("max");
  const double dither = c.args.number("the dither amplitude");
  c.args.expect_request_end("Quantize");
  c.target.quantize(type, one, qmin, qmax, dither, c.loc);
}

void display(Ctx& c) {
  const std::string name = c.args.string("the display name");
  const std::string type = c.args.string("the display type");
  const std::string mode = c.args.string("the display mode");
  c.target.display(name, type, mode, c.args.param_list(c.name), c.loc);
}

void hider(Ctx& c) {
  const std::string type = c.args.string("the hider type");
  c.target.hider(type, c.args.param_list(c.name), c.loc);
}

// --- blocks ---

// Requests without arguments.
template <void (RiTarget::*Call)(const SourceLoc&)>
void no_arguments(Ctx& c) {
  c.args.expect_request_end(c.name.c_str());
  (c.target.*Call)(c.loc);
}

// --- transforms ---

void transform(Ctx& c) {
  const auto m = c.args.numbers<16>("the matrix");
  c.args.expect_request_end("Transform");
  c.target.transform(m, c.loc);
}

void concat_transform(Ctx& c) {
  const auto m = c.args.numbers<16>("the matrix");
  c.args.expect_request_end("ConcatTransform");
  c.target.concat_transform(m, c.loc);
}

void translate(Ctx& c) {
  const auto d = c.args.numbers<3>("the translation");
  c.args.expect_request_end("Translate");
  c.target.translate(d[0], d[1], d[2], c.loc);
}

void rotate(Ctx& c) {
  const auto r = c.args.numbers<4>("the angle and axis");
  c.args.expect_request_end("Rotate");
  c.target.rotate(r[0], r[1], r[2], r[3], c.loc);
}

void scale(Ctx& c) {
  const auto s = c.args.numbers<3>("the scale factors");
  c.args.expect_request_end("Scale");
  c.target.scale(s[0], s[1], s[2], c.loc);
}

void perspective(Ctx& c) {
  const double fov = c.args.number("the field of view");
  c.args.expect_request_end("Perspective");
  c.target.perspective(fov, c.loc);
}

void coordinate_system(Ctx& c) {
  const std::string name = c.args.string("the coordinate system name");
  c.args.expect_request_end("CoordinateSystem");
  c.target.coordinate_system(name, c.loc);
}

void coord_sys_transform(Ctx& c) {
  const std::string name = c.args.string("the coordinate system name");
  c.args.expect_request_end("CoordSysTransform");
  c.target.coord_sys_transform(name, c.loc);
}

// --- attributes ---

void orientation(Ctx& c) {
  const std::string name = c.args.string("the orientation");
  c.args.expect_request_end("Orientation");
  c.target.orientation(name, c.loc);
}

void sides(Ctx& c) {
  const int n = c.args.integer("the number of sides");
  c.args.expect_request_end("Sides");
  c.target.sides(n, c.loc);
}

void color(Ctx& c) {
  const auto rgb = c.args.numbers<3>("the color");
  c.args.expect_request_end("Color");
  c.target.color(to_rgb(rgb), c.loc);
}

void opacity(Ctx& c) {
  const auto rgb = c.args.numbers<3>("the opacity");
  c.args.expect_request_end("Opacity");
  c.target.opacity(to_rgb(rgb), c.loc);
}

void surface(Ctx& c) {
  const std::string name = c.args.string("the shader name");
  c.target.surface(name, c.args.param_list(c.name), c.loc);
}

void displacement(Ctx& c) {
  const std::string name = c.args.string("the shader name");
  c.target.displacement(name, c.args.param_list(c.name), c.loc);
}

void light_source(Ctx& c) {
  const std::string name = c.args.string("the light shader name");
  const std::string handle = c.args.handle("the light handle");
  c.target.light_source(name, handle, c.args.param_list(c.name), c.loc);
}

void area_light_source(Ctx& c) {
  const std::string name = c.args.string("the light shader name");
  const std::string handle = c.args.handle("the light handle");
  c.target.area_light_source(name, handle, c.args.param_list(c.name), c.loc);
}

void illuminate(Ctx& c) {
  const std::string handle = c.args.handle("the light handle");
  const int on = c.args.integer("the on/off flag");
  c.args.expect_request_end("Illuminate");
  c.target.illuminate(handle, on != 0, c.loc);
}

void basis(Ctx& c) {
  const BasisArg ubasis = c.args.basis("the u basis");
  const int ustep = c.args.integer("the u step");
  const BasisArg vbasis = c.args.basis("the v basis");
  const int vstep = c.args.integer("the v step");
  c.args.expect_request_end("Basis");
  c.target.basis(ubasis, ustep, vbasis, vstep, c.loc);
}

// --- instancing ---

void object_begin(Ctx& c) {
  const std::string handle = c.args.handle("the object handle");
  c.args.expect_request_end("ObjectBegin");
  c.target.object_begin(handle, c.loc);
}

void object_instance(Ctx& c) {
  const std::string handle = c.args.handle("the object handle");
  c.args.expect_request_end("ObjectInstance");
  c.target.object_instance(handle, c.loc);
}

// --- geometry ---

void curves(Ctx& c) {
  const std::string type = c.args.string("the curve type");
  const std::vector<int> nvertices = c.args.integer_array("nvertices");
  const std::string wrap = c.args.string("the wrap mode");
  c.target.curves(type, nvertices, wrap, c.args.param_list(c.name), c.loc);
}

// Sphere, the other quadrics, the patches, NuPatch, SubdivisionMesh, Points: read by their
// signature into one PrimitiveRequest.
void primitive(Ctx& c) {
  const PrimitiveSignature* signature = find_primitive_signature(c.name);
  PrimitiveRequest r;
  r.name = c.name;
  const auto args = signature->args;
  for (size_t i = 0; i < args.size(); ++i) {
    const PrimitiveArgSpec& a = args[i];
    if (a.optional && !c.args.at_array()) continue;
    switch (a.type) {
      case PrimitiveArgType::Number: {
        // A run of numbers may be written bare or as one bracketed array (Sphere [1 -1 1 360]).
        size_t n = 1;
        while (i + n < args.size() && args[i + n].type == PrimitiveArgType::Number) ++n;
        std::string what = a.name;
        for (size_t k = 1; k < n; ++k) what += std::string(k + 1 == n ? " and " : ", ") + args[i + k].name;
        const std::vector<double> v = c.args.fixed_numbers(n, what.c_str());
        r.numbers.insert(r.numbers.end(), v.begin(), v.end());
        i += n - 1;
        break;
      }
      case PrimitiveArgType::Integer: r.numbers.push_back(c.args.integer(a.name)); break;
      case PrimitiveArgType::String: r.strings.push_back(c.args.string(a.name)); break;
      case PrimitiveArgType::IntegerArray: r.integer_arrays.push_back(c.args.integer_array(a.name)); break;
      case PrimitiveArgType::NumberArray: r.number_arrays.push_back(c.args.number_array(a.name)); break;
      case PrimitiveArgType::StringArray: r.string_arrays.push_back(c.args.string_array(a.name)); break;
    }
  }
  c.target.primitive(r, c.args.param_list(c.name), c.loc);
}

void polygon(Ctx& c) { c.target.polygon(c.args.param_list(c.name), c.loc); }

void general_polygon(Ctx& c) {
  const std::vector<int> nverts = c.args.integer_array("nverts");
  c.target.general_polygon(nverts, c.args.param_list(c.name), c.loc);
}

void points_polygons(Ctx& c) {
  const std::vector<int> nverts = c.args.integer_array("nverts");
  const std::vector<int> indices = c.args.integer_array("vertices");
  c.target.points_polygons(nverts, indices, c.args.param_list(c.name), c.loc);
}

void points_general_polygons(Ctx& c) {
  const std::vector<int> nloops = c.args.integer_array("nloops");
  const std::vector<int> nverts = c.args.integer_array("nverts");
  const std::vector<int> indices = c.args.integer_array("vertices");
  c.target.points_general_polygons(nloops, nverts, indices, c.args.param_list(c.name), c.loc);
}

using Table = std::unordered_map<std::string_view, RequestHandler>;

Table make_table() {
  return Table{
      {"version", version},
      {"Format", format},
      {"FrameAspectRatio", frame_aspect_ratio},
      {"ScreenWindow", screen_window},
      {"CropWindow", crop_window},
      {"Projection", projection},
      {"Clipping", clipping},
      {"PixelSamples", pixel_samples},
      {"PixelFilter", pixel_filter},
      {"Exposure", exposure},
      {"Quantize", quantize},
      {"Display", display},
      {"Hider", hider},
      {"FrameEnd", no_arguments<&RiTarget::frame_end>},
      {"WorldBegin", no_arguments<&RiTarget::world_begin>},
      {"WorldEnd", no_arguments<&RiTarget::world_end>},
      {"AttributeBegin", no_arguments<&RiTarget::attribute_begin>},
      {"AttributeEnd", no_arguments<&RiTarget::attribute_end>},
      {"TransformBegin", no_arguments<&RiTarget::transform_begin>},
      {"TransformEnd", no_arguments<&RiTarget::transform_end>},
      {"Identity", no_arguments<&RiTarget::identity>},
      {"Transform", transform},
      {"ConcatTransform", concat_transform},
      {"Translate", translate},
      {"Rotate", rotate},
      {"Scale", scale},
      {"Perspective", perspective},
      {"CoordinateSystem", coordinate_system},
      {"CoordSysTransform", coord_sys_transform},
      {"Orientation", orientation},
      {"ReverseOrientation", no_arguments<&RiTarget::reverse_orientation>},
      {"Sides", sides},
      {"Color", color},
      {"Opacity", opacity},
      {"Surface", surface},
      {"Displacement", displacement},
      {"LightSource", light_source},
      {"AreaLightSource", area_light_source},
      {"Illuminate", illuminate},
      {"Basis", basis},
      {"ObjectBegin", object_begin},
      {"ObjectEnd", no_arguments<&RiTarget::object_end>},
      {"ObjectInstance", object_instance},
      {"Curves", curves},
      {"Sphere", primitive},
      {"Cone", primitive},
      {"Cylinder", primitive},
      {"Disk", primitive},
      {"Hyperboloid", primitive},
      {"Paraboloid", primitive},
      {"Torus", primitive},
      {"Patch", primitive},
      {"PatchMesh", primitive},
      {"NuPatch", primitive},
      {"SubdivisionMesh", primitive},
      {"Points", primitive},
      {"Polygon", polygon},
      {"GeneralPolygon", general_polygon},
      {"PointsPolygons", points_polygons},
      {"PointsGeneralPolygons", points_general_polygons},
      // Accepted without effect.
      {"Shutter", ignored},
      {"ShadingRate", ignored},
      {"ShadingInterpolation", ignored},
      {"RelativeDetail", ignored},
      {"PixelVariance", ignored},
      {"ColorSamples", ignored},
      {"Matte", ignored},
      {"Bound", ignored},
      {"Detail", ignored},
      {"DetailRange", ignored},
      {"GeometricApproximation", ignored},
      {"TextureCoordinates", ignored},
      {"DepthOfField", ignored},
      {"MotionBegin", ignored},
      {"MotionEnd", ignored},
      {"ArchiveRecord", ignored},
      {"Skew", ignored},
      {"Imager", ignored_with_params<1, 0>},
      {"Atmosphere", ignored_with_params<1, 0>},
      {"Interior", ignored_with_params<1, 0>},
      {"Exterior", ignored_with_params<1, 0>},
      {"MakeShadow", ignored_with_params<2, 0>},
      // MakeTexture "pic" "tex" swrap twrap filter swidth twidth plist
      {"MakeTexture", ignored_with_params<5, 2>},
  };
}

}  // namespace

RequestHandler find_request_handler(std::string_view name) {
  static const Table table = make_table();  // built once, read-only afterwards
  const auto it = table.find(name);
  return it == table.end() ? nullptr : it->second;
}

}  // namespace darc
