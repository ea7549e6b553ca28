// A test RiTarget that records every call with its arguments flattened into numbers and
// strings, so tests can look at what the parser delivered and compare two parses.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "parser/diagnostics.h"
#include "parser/ri_target.h"
#include "parser/rib_parser.h"

namespace darc::test {

struct RecordedCall {
  std::string request;
  std::vector<double> numbers;
  std::vector<std::string> strings;
  ParamList params;
  SourceLoc loc;

  // Same call and arguments (positions are not compared).
  bool same_as(const RecordedCall& o) const {
    if (request != o.request || numbers != o.numbers || strings != o.strings) return false;
    if (params.params.size() != o.params.params.size()) return false;
    for (size_t i = 0; i < params.params.size(); ++i) {
      const Param& a = params.params[i];
      const Param& b = o.params.params[i];
      if (a.name != b.name || !(a.decl == b.decl) || a.floats != b.floats || a.strings != b.strings) return false;
    }
    return true;
  }
};

class RecordingTarget : public RiTarget {
 public:
  std::vector<RecordedCall> calls;

  // The calls named `request`, in order.
  std::vector<RecordedCall> named(const std::string& request) const {
    std::vector<RecordedCall> out;
    for (const RecordedCall& c : calls) {
      if (c.request == request) out.push_back(c);
    }
    return out;
  }

  void version(double v, const SourceLoc& loc) override { add("version", {v}, {}, {}, loc); }
  void declare(const std::string& name, const std::string& decl, const SourceLoc& loc) override {
    add("Declare", {}, {name, decl}, {}, loc);
  }
  void option(const std::string& c, const ParamList& p, const SourceLoc& loc) override {
    add("Option", {}, {c}, p, loc);
  }
  void format(int x, int y, double a, const SourceLoc& loc) override {
    add("Format", {double(x), double(y), a}, {}, {}, loc);
  }
  void frame_aspect_ratio(double r, const SourceLoc& loc) override { add("FrameAspectRatio", {r}, {}, {}, loc); }
  void screen_window(double l, double r, double b, double t, const SourceLoc& loc) override {
    add("ScreenWindow", {l, r, b, t}, {}, {}, loc);
  }
  void crop_window(double a, double b, double c, double d, const SourceLoc& loc) override {
    add("CropWindow", {a, b, c, d}, {}, {}, loc);
  }
  void projection(const std::string& n, const ParamList& p, const SourceLoc& loc) override {
    add("Projection", {}, {n}, p, loc);
  }
  void clipping(double n, double f, const SourceLoc& loc) override { add("Clipping", {n, f}, {}, {}, loc); }
  void pixel_samples(double x, double y, const SourceLoc& loc) override { add("PixelSamples", {x, y}, {}, {}, loc); }
  void pixel_filter(const std::string& n, double x, double y, const SourceLoc& loc) override {
    add("PixelFilter", {x, y}, {n}, {}, loc);
  }
  void exposure(double g, double y, const SourceLoc& loc) override { add("Exposure", {g, y}, {}, {}, loc); }
  void quantize(const std::string& t, int one, int lo, int hi, double d, const SourceLoc& loc) override {
    add("Quantize", {double(one), double(lo), double(hi), d}, {t}, {}, loc);
  }
  void display(const std::string& n, const std::string& t, const std::string& m, const ParamList& p,
               const SourceLoc& loc) override {
    add("Display", {}, {n, t, m}, p, loc);
  }
  void hider(const std::string& t, const ParamList& p, const SourceLoc& loc) override { add("Hider", {}, {t}, p, loc); }
  void ignored_request(const std::string& r, const std::vector<double>& n, const std::vector<std::string>& s,
                       const SourceLoc& loc) override {
    add(r, n, s, {}, loc);
  }

  void frame_begin(int n, const SourceLoc& loc) override { add("FrameBegin", {double(n)}, {}, {}, loc); }
  void frame_end(const SourceLoc& loc) override { add("FrameEnd", {}, {}, {}, loc); }
  void world_begin(const SourceLoc& loc) override { add("WorldBegin", {}, {}, {}, loc); }
  void world_end(const SourceLoc& loc) override { add("WorldEnd", {}, {}, {}, loc); }
  void attribute_begin(const SourceLoc& loc) override { add("AttributeBegin", {}, {}, {}, loc); }
  void attribute_end(const SourceLoc& loc) override { add("AttributeEnd", {}, {}, {}, loc); }
  void transform_begin(const SourceLoc& loc) override { add("TransformBegin", {}, {}, {}, loc); }
  void transform_end(const SourceLoc& loc) override { add("TransformEnd", {}, {}, {}, loc); }

  void identity(const SourceLoc& loc) override { add("Identity", {}, {}, {}, loc); }
  void transform(const std::array<double, 16>& m, const SourceLoc& loc) override {
    add("Transform", {m.begin(), m.end()}, {}, {}, loc);
  }
  void concat_transform(const std::array<double, 16>& m, const SourceLoc& loc) override {
    add("ConcatTransform", {m.begin(), m.end()}, {}, {}, loc);
  }
  void translate(double x, double y, double z, const SourceLoc& loc) override {
    add("Translate", {x, y, z}, {}, {}, loc);
  }
  void rotate(double a, double x, double y, double z, const SourceLoc& loc) override {
    add("Rotate", {a, x, y, z}, {}, {}, loc);
  }
  void scale(double x, double y, double z, const SourceLoc& loc) override { add("Scale", {x, y, z}, {}, {}, loc); }
  void perspective(double f, const SourceLoc& loc) override { add("Perspective", {f}, {}, {}, loc); }
  void coordinate_system(const std::string& n, const SourceLoc& loc) override {
    add("CoordinateSystem", {}, {n}, {}, loc);
  }
  void coord_sys_transform(const std::string& n, const SourceLoc& loc) override {
    add("CoordSysTransform", {}, {n}, {}, loc);
  }

  void attribute(const std::string& c, const ParamList& p, const SourceLoc& loc) override {
    add("Attribute", {}, {c}, p, loc);
  }
  void orientation(const std::string& n, const SourceLoc& loc) override { add("Orientation", {}, {n}, {}, loc); }
  void reverse_orientation(const SourceLoc& loc) override { add("ReverseOrientation", {}, {}, {}, loc); }
  void sides(int n, const SourceLoc& loc) override { add("Sides", {double(n)}, {}, {}, loc); }
  void color(const std::array<float, 3>& c, const SourceLoc& loc) override {
    add("Color", {c[0], c[1], c[2]}, {}, {}, loc);
  }
  void opacity(const std::array<float, 3>& c, const SourceLoc& loc) override {
    add("Opacity", {c[0], c[1], c[2]}, {}, {}, loc);
  }
  void surface(const std::string& n, const ParamList& p, const SourceLoc& loc) override {
    add("Surface", {}, {n}, p, loc);
  }
  void displacement(const std::string& n, const ParamList& p, const SourceLoc& loc) override {
    add("Displacement", {}, {n}, p, loc);
  }
  void light_source(const std::string& n, const std::string& h, const ParamList& p, const SourceLoc& loc) override {
    add("LightSource", {}, {n, h}, p, loc);
  }
  void area_light_source(const std::string& n, const std::string& h, const ParamList& p,
                         const SourceLoc& loc) override {
    add("AreaLightSource", {}, {n, h}, p, loc);
  }
  void illuminate(const std::string& h, bool on, const SourceLoc& loc) override {
    add("Illuminate", {on ? 1.0 : 0.0}, {h}, {}, loc);
  }
  void basis(const BasisArg& u, int us, const BasisArg& v, int vs, const SourceLoc& loc) override {
    std::vector<double> n(u.matrix.begin(), u.matrix.end());
    n.push_back(us);
    n.insert(n.end(), v.matrix.begin(), v.matrix.end());
    n.push_back(vs);
    add("Basis", n, {u.name, v.name}, {}, loc);
  }

  void object_begin(const std::string& h, const SourceLoc& loc) override { add("ObjectBegin", {}, {h}, {}, loc); }
  void object_end(const SourceLoc& loc) override { add("ObjectEnd", {}, {}, {}, loc); }
  void object_instance(const std::string& h, const SourceLoc& loc) override { add("ObjectInstance", {}, {h}, {}, loc); }

  void curves(const std::string& type, const std::vector<int>& nv, const std::string& wrap, const ParamList& p,
              const SourceLoc& loc) override {
    add("Curves", {nv.begin(), nv.end()}, {type, wrap}, p, loc);
  }
  // Numbers, then every array's values in order; strings, then every string array's.
  void primitive(const PrimitiveRequest& r, const ParamList& p, const SourceLoc& loc) override {
    std::vector<double> n = r.numbers;
    for (const auto& a : r.integer_arrays) n.insert(n.end(), a.begin(), a.end());
    for (const auto& a : r.number_arrays) n.insert(n.end(), a.begin(), a.end());
    std::vector<std::string> s = r.strings;
    for (const auto& a : r.string_arrays) s.insert(s.end(), a.begin(), a.end());
    add(r.name, n, s, p, loc);
  }
  void polygon(const ParamList& p, const SourceLoc& loc) override { add("Polygon", {}, {}, p, loc); }
  void general_polygon(const std::vector<int>& nv, const ParamList& p, const SourceLoc& loc) override {
    add("GeneralPolygon", {nv.begin(), nv.end()}, {}, p, loc);
  }
  void points_polygons(const std::vector<int>& nv, const std::vector<int>& idx, const ParamList& p,
                       const SourceLoc& loc) override {
    std::vector<double> n(nv.begin(), nv.end());
    n.push_back(-1);  // separator
    n.insert(n.end(), idx.begin(), idx.end());
    add("PointsPolygons", n, {}, p, loc);
  }
  void points_general_polygons(const std::vector<int>& nl, const std::vector<int>& nv, const std::vector<int>& idx,
                               const ParamList& p, const SourceLoc& loc) override {
    std::vector<double> n(nl.begin(), nl.end());
    n.push_back(-1);
    n.insert(n.end(), nv.begin(), nv.end());
    n.push_back(-1);
    n.insert(n.end(), idx.begin(), idx.end());
    add("PointsGeneralPolygons", n, {}, p, loc);
  }
  // Kept apart from `calls`: they are not requests the target models.
  std::vector<std::string> skipped_primitives;
  void skipped_primitive(const std::string& r, const SourceLoc&) override { skipped_primitives.push_back(r); }

 private:
  void add(const std::string& request, std::vector<double> numbers, std::vector<std::string> strings,
           const ParamList& params, const SourceLoc& loc) {
    calls.push_back({request, std::move(numbers), std::move(strings), params, loc});
  }
};

// The outcome of parsing a text with a RecordingTarget and silent Diagnostics.
struct ParseResult {
  RecordingTarget target;
  Diagnostics diag{[](const Diagnostic&) {}};
  bool ok = false;

  std::vector<Diagnostic> errors() const { return of(Severity::Error); }
  std::vector<Diagnostic> warnings() const { return of(Severity::Warning); }

 private:
  std::vector<Diagnostic> of(Severity s) const {
    std::vector<Diagnostic> out;
    for (const Diagnostic& d : diag.all()) {
      if (d.severity == s) out.push_back(d);
    }
    return out;
  }
};

inline std::unique_ptr<ParseResult> parse_rib(const std::string& text, const std::string& name = "test.rib") {
  auto result = std::make_unique<ParseResult>();
  RibParser parser(result->target, result->diag);
  result->ok = parser.parse_string(text, name);
  return result;
}

}  // namespace darc::test
