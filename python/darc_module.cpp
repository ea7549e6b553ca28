// The Python module `darc`: a RenderMan Interface in the shape of RenderMan's prman.Ri()
// (ri = darc.Ri(); ri.Begin(...); ri.Curves("cubic", [4, 4], "nonperiodic", {"P": points})),
// over the same session as the C binding (ri/ri_session.h): ri.Begin(ri.RENDER) (or None, or "")
// renders in this process exactly as the darc command renders the same requests as RIB;
// ri.Begin("scene.rib") writes RIB. Parameter values are numbers, lists, tuples or numpy arrays
// (read without a Python call per element), or strings. Messages name the calling script's file
// and line; errors go to the error handler (ri.ErrorHandler("print" | "ignore" | "abort" | a
// callable taking code, severity and message), they do not raise.
#include "parser/rib_writer.h"
#include "python/python_params.h"
#include "ri/ri_session.h"
#include "ri/value_counts.h"

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <fmt/format.h>
#include <frameobject.h>

#include <array>
#include <cstdio>
#include <memory>
#include <optional>

namespace darc::python {

namespace {

// The RI error codes the handler receives (ri.h: RIE_CONSISTENCY, RIE_WARNING, RIE_ERROR).
constexpr int kCodeConsistency = 43, kSeverityWarning = 1, kSeverityError = 2;

// The calling script's file and line, for messages.
SourceLoc caller_position() {
  PyFrameObject* frame = PyEval_GetFrame();
  if (!frame) return SourceLoc{std::make_shared<const std::string>("<python>"), 1, 1};
  PyCodeObject* code = PyFrame_GetCode(frame);
  std::string file = "<python>";
  if (code) {
    if (const char* name = PyUnicode_AsUTF8(code->co_filename)) file = name;
    Py_DECREF(code);
  }
  return SourceLoc{std::make_shared<const std::string>(file), PyFrame_GetLineNumber(frame), 1};
}

std::array<double, 6> bound6(const py::handle& values) {
  const std::vector<double> v = doubles(values);
  if (v.size() != 6) throw py::value_error("a bound is 6 numbers: xmin xmax ymin ymax zmin zmax");
  std::array<double, 6> b{};
  std::copy(v.begin(), v.end(), b.begin());
  return b;
}

std::array<double, 16> matrix16(const py::handle& values) {
  const std::vector<double> v = doubles(values);
  if (v.size() != 16) throw py::value_error("a matrix is 16 numbers (4 x 4, row by row)");
  std::array<double, 16> m{};
  std::copy(v.begin(), v.end(), m.begin());
  return m;
}

std::array<float, 3> color3(const py::handle& values) {
  const std::vector<double> v = doubles(values);
  if (v.size() != 3) throw py::value_error("a colour is 3 numbers");
  return {float(v[0]), float(v[1]), float(v[2])};
}

BasisArg basis_arg(const py::handle& value) {
  BasisArg arg;
  if (py::isinstance<py::str>(value)) arg.name = py::cast<std::string>(value);
  else arg.matrix = matrix16(value);
  return arg;
}

class PyRi {
 public:
  using Call = std::function<void(RiSession&, const SourceLoc&)>;

  PyRi() = default;
  PyRi(const PyRi&) = delete;
  PyRi& operator=(const PyRi&) = delete;
  // A Ri dropped without End ends its session (the frame left open is reported) with no handler.
  ~PyRi() {
    handler_ = py::none();
    try {
      if (session_) session_->end();
    } catch (...) {
    }
  }

  void begin(const std::optional<std::string>& name) {
    if (session_) throw py::value_error("Begin: this Ri already has a session (call End first)");
    session_ = std::make_unique<RiSession>(name.value_or(""), [this](const Diagnostic& d) { report(d); });
    handler_ = py::none();
  }

  // Raises when an image or the RIB file could not be written.
  void end() {
    if (!session_) return;
    if (calls_in_progress_ > 0) throw py::value_error("End: called from inside a procedural or an error handler");
    std::unique_ptr<RiSession> ending = std::move(session_);
    if (!ending->end()) throw std::runtime_error("End: a file could not be written (see the messages)");
  }

  // Runs `call` with the session and the caller's position; a RibError (a request the target
  // refuses) goes to the error handler, as in a RIB file.
  void run(const char* request, const Call& call) {
    if (!session_) throw py::value_error(fmt::format("{}: no session (call Begin first)", request));
    if (session_->stopped()) return;
    const SourceLoc loc = caller_position();
    RiSession& session = *session_;
    ++calls_in_progress_;
    try {
      call(session, loc);
    } catch (const RibError& e) {
      session.diagnostics().error(loc, request, e.what());
    } catch (...) {
      --calls_in_progress_;  // a Python exception (a procedural's, a bad argument) goes on up
      throw;
    }
    --calls_in_progress_;
  }

  ParamList params(RiSession& s, const char* request, const py::dict& values, const SourceLoc& loc) {
    return param_list(s, request, values, loc);
  }

  void error_handler(const py::object& handler) {
    if (py::isinstance<py::str>(handler)) {
      const std::string name = py::cast<std::string>(handler);
      handler_ = py::none();
      run("ErrorHandler", [&](RiSession& s, const SourceLoc& loc) { s.error_handler(name, loc); });
    } else {
      handler_ = handler;
      run("ErrorHandler", [&](RiSession& s, const SourceLoc& loc) { s.error_handler("print", loc); });
    }
  }

  std::string next_handle() { return session_ ? session_->next_handle() : std::string("0"); }

 private:
  void report(const Diagnostic& d) {
    if (handler_.is_none()) {
      std::fprintf(stderr, "%s\n", d.str().c_str());
      return;
    }
    try {
      handler_(kCodeConsistency, d.severity == Severity::Error ? kSeverityError : kSeverityWarning, d.str());
    } catch (py::error_already_set& e) {
      e.discard_as_unraisable("darc error handler");
    }
  }

  // The handler first: the session's end may still report through it.
  py::object handler_ = py::none();
  std::unique_ptr<RiSession> session_;
  int calls_in_progress_ = 0;
};

using Params = py::dict;

void define_requests(py::class_<PyRi>& c) {
  auto& ri = c;
  // --- session, blocks ---
  ri.def("Begin", &PyRi::begin, py::arg("name") = py::none());
  ri.def("End", &PyRi::end);
  ri.def("ErrorHandler", &PyRi::error_handler);
  ri.def("Declare", [](PyRi& r, const std::string& name, const std::string& decl) {
    r.run("Declare", [&](RiSession& s, const SourceLoc& loc) { s.declare(name, decl, loc); });
    return name;
  });
  ri.def("FrameBegin", [](PyRi& r, int n) {
    r.run("FrameBegin", [&](RiSession& s, const SourceLoc& loc) { s.frame_begin(n, loc); });
  });
#define DARC_PY_NO_ARGS(Name, method)                                                                  \
  ri.def(#Name, [](PyRi& r) {                                                                          \
    r.run(#Name, [](RiSession& s, const SourceLoc& loc) { s.target().method(loc); });                  \
  });
  DARC_PY_NO_ARGS(FrameEnd, frame_end)
  DARC_PY_NO_ARGS(WorldBegin, world_begin)
  DARC_PY_NO_ARGS(WorldEnd, world_end)
  DARC_PY_NO_ARGS(AttributeBegin, attribute_begin)
  DARC_PY_NO_ARGS(AttributeEnd, attribute_end)
  DARC_PY_NO_ARGS(TransformBegin, transform_begin)
  DARC_PY_NO_ARGS(TransformEnd, transform_end)
  DARC_PY_NO_ARGS(MotionEnd, motion_end)
  DARC_PY_NO_ARGS(ResourceBegin, resource_begin)
  DARC_PY_NO_ARGS(ResourceEnd, resource_end)
  DARC_PY_NO_ARGS(Identity, identity)
  DARC_PY_NO_ARGS(ReverseOrientation, reverse_orientation)
  DARC_PY_NO_ARGS(ObjectEnd, object_end)
#undef DARC_PY_NO_ARGS
  ri.def("MotionBegin", [](PyRi& r, const py::object& times) {
    const std::vector<double> t = doubles(times);
    r.run("MotionBegin", [&](RiSession& s, const SourceLoc& loc) { s.target().motion_begin(t, loc); });
  });

  // --- options ---
  ri.def("Format", [](PyRi& r, int x, int y, double aspect) {
    r.run("Format", [&](RiSession& s, const SourceLoc& loc) { s.target().format(x, y, aspect, loc); });
  }, py::arg("xres"), py::arg("yres"), py::arg("pixelaspect") = 1.0);
  ri.def("FrameAspectRatio", [](PyRi& r, double a) {
    r.run("FrameAspectRatio", [&](RiSession& s, const SourceLoc& loc) { s.target().frame_aspect_ratio(a, loc); });
  });
  ri.def("ScreenWindow", [](PyRi& r, double l, double rt, double b, double t) {
    r.run("ScreenWindow", [&](RiSession& s, const SourceLoc& loc) { s.target().screen_window(l, rt, b, t, loc); });
  });
  ri.def("CropWindow", [](PyRi& r, double x0, double x1, double y0, double y1) {
    r.run("CropWindow", [&](RiSession& s, const SourceLoc& loc) { s.target().crop_window(x0, x1, y0, y1, loc); });
  });
  ri.def("Clipping", [](PyRi& r, double n, double f) {
    r.run("Clipping", [&](RiSession& s, const SourceLoc& loc) { s.target().clipping(n, f, loc); });
  });
  ri.def("DepthOfField", [](PyRi& r, double fstop, double length, double distance) {
    r.run("DepthOfField",
          [&](RiSession& s, const SourceLoc& loc) { s.target().depth_of_field(fstop, length, distance, loc); });
  });
  ri.def("Shutter", [](PyRi& r, double open, double close) {
    r.run("Shutter", [&](RiSession& s, const SourceLoc& loc) { s.target().shutter(open, close, loc); });
  });
  ri.def("PixelSamples", [](PyRi& r, double x, double y) {
    r.run("PixelSamples", [&](RiSession& s, const SourceLoc& loc) { s.target().pixel_samples(x, y, loc); });
  });
  ri.def("PixelFilter", [](PyRi& r, const std::string& name, double xw, double yw) {
    r.run("PixelFilter", [&](RiSession& s, const SourceLoc& loc) { s.target().pixel_filter(name, xw, yw, loc); });
  });
  ri.def("Exposure", [](PyRi& r, double gain, double gamma) {
    r.run("Exposure", [&](RiSession& s, const SourceLoc& loc) { s.target().exposure(gain, gamma, loc); });
  });
  ri.def("Quantize", [](PyRi& r, const std::string& type, int one, int lo, int hi, double dither) {
    r.run("Quantize", [&](RiSession& s, const SourceLoc& loc) { s.target().quantize(type, one, lo, hi, dither, loc); });
  });
  ri.def("Display", [](PyRi& r, const std::string& name, const std::string& type, const std::string& mode,
                       const Params& p) {
    r.run("Display", [&](RiSession& s, const SourceLoc& loc) {
      s.target().display(name, type, mode, r.params(s, "Display", p, loc), loc);
    });
  }, py::arg("name"), py::arg("type"), py::arg("mode"), py::arg("params") = Params());
#define DARC_PY_NAME_PARAMS(Name, method)                                                              \
  ri.def(#Name, [](PyRi& r, const std::string& name, const Params& p) {                                \
    r.run(#Name, [&](RiSession& s, const SourceLoc& loc) { s.method(name, r.params(s, #Name, p, loc), loc); }); \
  }, py::arg("name"), py::arg("params") = Params());
  DARC_PY_NAME_PARAMS(Projection, target().projection)
  DARC_PY_NAME_PARAMS(Hider, target().hider)
  DARC_PY_NAME_PARAMS(Camera, target().camera)
  DARC_PY_NAME_PARAMS(Surface, target().surface)
  DARC_PY_NAME_PARAMS(Displacement, target().displacement)
  DARC_PY_NAME_PARAMS(Option, option)
  DARC_PY_NAME_PARAMS(Attribute, attribute)
#undef DARC_PY_NAME_PARAMS
#define DARC_PY_NODE(Name, method)                                                                     \
  ri.def(#Name, [](PyRi& r, const std::string& name, const std::string& handle, const Params& p) {     \
    r.run(#Name, [&](RiSession& s, const SourceLoc& loc) {                                             \
      s.target().method(name, handle, r.params(s, #Name, p, loc), loc);                                \
    });                                                                                                \
  }, py::arg("name"), py::arg("handle"), py::arg("params") = Params());
  DARC_PY_NODE(Integrator, integrator)
  DARC_PY_NODE(Bxdf, bxdf)
  DARC_PY_NODE(Pattern, pattern)
  DARC_PY_NODE(Light, light)
#undef DARC_PY_NODE
  // LightSource and AreaLightSource return their handle ("1", "2", ...) unless one is given.
#define DARC_PY_LIGHT(Name, method)                                                                    \
  ri.def(#Name, [](PyRi& r, const std::string& name, const Params& p, const std::optional<std::string>& handle) { \
    const std::string h = handle ? *handle : r.next_handle();                                          \
    r.run(#Name, [&](RiSession& s, const SourceLoc& loc) {                                             \
      s.target().method(name, h, r.params(s, #Name, p, loc), loc);                                     \
    });                                                                                                \
    return h;                                                                                          \
  }, py::arg("name"), py::arg("params") = Params(), py::arg("handle") = py::none());
  DARC_PY_LIGHT(LightSource, light_source)
  DARC_PY_LIGHT(AreaLightSource, area_light_source)
#undef DARC_PY_LIGHT

  // --- attributes ---
  ri.def("Illuminate", [](PyRi& r, const std::string& handle, bool on) {
    r.run("Illuminate", [&](RiSession& s, const SourceLoc& loc) { s.target().illuminate(handle, on, loc); });
  });
  ri.def("Color", [](PyRi& r, const py::object& c) {
    const auto rgb = color3(c);
    r.run("Color", [&](RiSession& s, const SourceLoc& loc) { s.target().color(rgb, loc); });
  });
  ri.def("Opacity", [](PyRi& r, const py::object& c) {
    const auto rgb = color3(c);
    r.run("Opacity", [&](RiSession& s, const SourceLoc& loc) { s.target().opacity(rgb, loc); });
  });
  ri.def("Sides", [](PyRi& r, int n) {
    r.run("Sides", [&](RiSession& s, const SourceLoc& loc) { s.target().sides(n, loc); });
  });
  ri.def("Orientation", [](PyRi& r, const std::string& o) {
    r.run("Orientation", [&](RiSession& s, const SourceLoc& loc) { s.target().orientation(o, loc); });
  });
  ri.def("Basis", [](PyRi& r, const py::object& u, int ustep, const py::object& v, int vstep) {
    const BasisArg ub = basis_arg(u), vb = basis_arg(v);
    r.run("Basis", [&](RiSession& s, const SourceLoc& loc) { s.target().basis(ub, ustep, vb, vstep, loc); });
  });
  ri.def("ShadingRate", [](PyRi& r, double rate) {
    r.run("ShadingRate", [&](RiSession& s, const SourceLoc& loc) { s.target().ignored_request("ShadingRate", {rate}, {}, loc); });
  });
  ri.def("Matte", [](PyRi& r, bool on) {
    r.run("Matte", [&](RiSession& s, const SourceLoc& loc) { s.target().ignored_request("Matte", {on ? 1.0 : 0.0}, {}, loc); });
  });

  // --- transforms ---
  ri.def("Transform", [](PyRi& r, const py::object& m) {
    const auto t = matrix16(m);
    r.run("Transform", [&](RiSession& s, const SourceLoc& loc) { s.target().transform(t, loc); });
  });
  ri.def("ConcatTransform", [](PyRi& r, const py::object& m) {
    const auto t = matrix16(m);
    r.run("ConcatTransform", [&](RiSession& s, const SourceLoc& loc) { s.target().concat_transform(t, loc); });
  });
  ri.def("Perspective", [](PyRi& r, double fov) {
    r.run("Perspective", [&](RiSession& s, const SourceLoc& loc) { s.target().perspective(fov, loc); });
  });
  ri.def("Translate", [](PyRi& r, double x, double y, double z) {
    r.run("Translate", [&](RiSession& s, const SourceLoc& loc) { s.target().translate(x, y, z, loc); });
  });
  ri.def("Rotate", [](PyRi& r, double a, double x, double y, double z) {
    r.run("Rotate", [&](RiSession& s, const SourceLoc& loc) { s.target().rotate(a, x, y, z, loc); });
  });
  ri.def("Scale", [](PyRi& r, double x, double y, double z) {
    r.run("Scale", [&](RiSession& s, const SourceLoc& loc) { s.target().scale(x, y, z, loc); });
  });
#define DARC_PY_SPACE(Name, method)                                                                    \
  ri.def(#Name, [](PyRi& r, const std::string& space) {                                               \
    r.run(#Name, [&](RiSession& s, const SourceLoc& loc) { s.target().method(space, loc); });          \
  });
  DARC_PY_SPACE(CoordinateSystem, coordinate_system)
  DARC_PY_SPACE(ScopedCoordinateSystem, scoped_coordinate_system)
  DARC_PY_SPACE(CoordSysTransform, coord_sys_transform)
#undef DARC_PY_SPACE

  // --- instancing ---
  ri.def("ObjectBegin", [](PyRi& r, const std::optional<std::string>& handle) {
    const std::string h = handle ? *handle : r.next_handle();
    r.run("ObjectBegin", [&](RiSession& s, const SourceLoc& loc) { s.target().object_begin(h, loc); });
    return h;
  }, py::arg("handle") = py::none());
  ri.def("ObjectInstance", [](PyRi& r, const std::string& h) {
    r.run("ObjectInstance", [&](RiSession& s, const SourceLoc& loc) { s.target().object_instance(h, loc); });
  });
}

void define_geometry(py::class_<PyRi>& ri) {
  ri.def("Curves", [](PyRi& r, const std::string& type, const py::object& nvertices, const std::string& wrap,
                      const Params& p) {
    const std::vector<int> nv = ints(nvertices);
    r.run("Curves", [&](RiSession& s, const SourceLoc& loc) {
      s.target().curves(type, nv, wrap, r.params(s, "Curves", p, loc), loc);
    });
  }, py::arg("type"), py::arg("nvertices"), py::arg("wrap"), py::arg("params") = Params());
  // Polygon(params) or Polygon(nvertices, params), as prman takes it.
  ri.def("Polygon", [](PyRi& r, const py::object& first, const py::object& second) {
    const Params p = py::isinstance<py::dict>(first) ? first.cast<Params>() : second.cast<Params>();
    r.run("Polygon", [&](RiSession& s, const SourceLoc& loc) { s.target().polygon(r.params(s, "Polygon", p, loc), loc); });
  }, py::arg("nvertices"), py::arg("params") = Params());
  ri.def("GeneralPolygon", [](PyRi& r, const py::object& nverts, const Params& p) {
    const std::vector<int> loops = ints(nverts);
    r.run("GeneralPolygon", [&](RiSession& s, const SourceLoc& loc) {
      s.target().general_polygon(loops, r.params(s, "GeneralPolygon", p, loc), loc);
    });
  }, py::arg("nverts"), py::arg("params") = Params());
  ri.def("PointsPolygons", [](PyRi& r, const py::object& nverts, const py::object& verts, const Params& p) {
    const std::vector<int> per_face = ints(nverts), indices = ints(verts);
    r.run("PointsPolygons", [&](RiSession& s, const SourceLoc& loc) {
      s.target().points_polygons(per_face, indices, r.params(s, "PointsPolygons", p, loc), loc);
    });
  }, py::arg("nverts"), py::arg("verts"), py::arg("params") = Params());
  ri.def("PointsGeneralPolygons", [](PyRi& r, const py::object& nloops, const py::object& nverts,
                                     const py::object& verts, const Params& p) {
    const std::vector<int> loops = ints(nloops), per_loop = ints(nverts), indices = ints(verts);
    r.run("PointsGeneralPolygons", [&](RiSession& s, const SourceLoc& loc) {
      s.target().points_general_polygons(loops, per_loop, indices, r.params(s, "PointsGeneralPolygons", p, loc), loc);
    });
  }, py::arg("nloops"), py::arg("nverts"), py::arg("verts"), py::arg("params") = Params());

  // The requests of RiTarget::primitive: a PrimitiveRequest of their fixed arguments.
  auto primitive = [](PyRi& r, PrimitiveRequest request, const Params& p) {
    r.run(request.name.c_str(), [&](RiSession& s, const SourceLoc& loc) {
      s.target().primitive(request, r.params(s, request.name.c_str(), p, loc), loc);
    });
  };
  auto numbers_request = [](const char* name, std::vector<double> numbers) {
    PrimitiveRequest r;
    r.name = name;
    r.numbers = std::move(numbers);
    return r;
  };
  ri.def("Sphere", [=](PyRi& r, double radius, double zmin, double zmax, double thetamax, const Params& p) {
    primitive(r, numbers_request("Sphere", {radius, zmin, zmax, thetamax}), p);
  }, py::arg("radius"), py::arg("zmin"), py::arg("zmax"), py::arg("thetamax"), py::arg("params") = Params());
  ri.def("Cylinder", [=](PyRi& r, double radius, double zmin, double zmax, double thetamax, const Params& p) {
    primitive(r, numbers_request("Cylinder", {radius, zmin, zmax, thetamax}), p);
  }, py::arg("radius"), py::arg("zmin"), py::arg("zmax"), py::arg("thetamax"), py::arg("params") = Params());
  ri.def("Cone", [=](PyRi& r, double height, double radius, double thetamax, const Params& p) {
    primitive(r, numbers_request("Cone", {height, radius, thetamax}), p);
  }, py::arg("height"), py::arg("radius"), py::arg("thetamax"), py::arg("params") = Params());
  ri.def("Disk", [=](PyRi& r, double height, double radius, double thetamax, const Params& p) {
    primitive(r, numbers_request("Disk", {height, radius, thetamax}), p);
  }, py::arg("height"), py::arg("radius"), py::arg("thetamax"), py::arg("params") = Params());
  ri.def("Paraboloid", [=](PyRi& r, double rmax, double zmin, double zmax, double thetamax, const Params& p) {
    primitive(r, numbers_request("Paraboloid", {rmax, zmin, zmax, thetamax}), p);
  }, py::arg("rmax"), py::arg("zmin"), py::arg("zmax"), py::arg("thetamax"), py::arg("params") = Params());
  ri.def("Hyperboloid", [=](PyRi& r, const py::object& p1, const py::object& p2, double thetamax, const Params& p) {
    std::vector<double> n = doubles(p1), second = doubles(p2);
    if (n.size() != 3 || second.size() != 3) throw py::value_error("Hyperboloid: two points of 3 numbers");
    n.insert(n.end(), second.begin(), second.end());
    n.push_back(thetamax);
    primitive(r, numbers_request("Hyperboloid", n), p);
  }, py::arg("point1"), py::arg("point2"), py::arg("thetamax"), py::arg("params") = Params());
  ri.def("Torus", [=](PyRi& r, double rmajor, double rminor, double phimin, double phimax, double thetamax,
                      const Params& p) {
    primitive(r, numbers_request("Torus", {rmajor, rminor, phimin, phimax, thetamax}), p);
  }, py::arg("rmajor"), py::arg("rminor"), py::arg("phimin"), py::arg("phimax"), py::arg("thetamax"),
     py::arg("params") = Params());
  // Points(params) or Points(npoints, params).
  ri.def("Points", [=](PyRi& r, const py::object& first, const py::object& second) {
    const Params p = py::isinstance<py::dict>(first) ? first.cast<Params>() : second.cast<Params>();
    primitive(r, numbers_request("Points", {}), p);
  }, py::arg("npoints"), py::arg("params") = Params());
  ri.def("Patch", [=](PyRi& r, const std::string& type, const Params& p) {
    PrimitiveRequest req;
    req.name = "Patch";
    req.strings = {type};
    primitive(r, req, p);
  }, py::arg("type"), py::arg("params") = Params());
  ri.def("PatchMesh", [=](PyRi& r, const std::string& type, int nu, const std::string& uwrap, int nv,
                          const std::string& vwrap, const Params& p) {
    PrimitiveRequest req;
    req.name = "PatchMesh";
    req.strings = {type, uwrap, vwrap};
    req.numbers = {double(nu), double(nv)};
    primitive(r, req, p);
  }, py::arg("type"), py::arg("nu"), py::arg("uwrap"), py::arg("nv"), py::arg("vwrap"), py::arg("params") = Params());
  ri.def("NuPatch", [=](PyRi& r, int nu, int uorder, const py::object& uknot, double umin, double umax, int nv,
                        int vorder, const py::object& vknot, double vmin, double vmax, const Params& p) {
    PrimitiveRequest req;
    req.name = "NuPatch";
    req.numbers = {double(nu), double(uorder), umin, umax, double(nv), double(vorder), vmin, vmax};
    req.number_arrays = {doubles(uknot), doubles(vknot)};
    primitive(r, req, p);
  }, py::arg("nu"), py::arg("uorder"), py::arg("uknot"), py::arg("umin"), py::arg("umax"), py::arg("nv"),
     py::arg("vorder"), py::arg("vknot"), py::arg("vmin"), py::arg("vmax"), py::arg("params") = Params());
  ri.def("SubdivisionMesh", [=](PyRi& r, const std::string& scheme, const py::object& nverts, const py::object& verts,
                                const py::object& tags, const py::object& nargs, const py::object& intargs,
                                const py::object& floatargs, const Params& p) {
    PrimitiveRequest req;
    req.name = "SubdivisionMesh";
    req.strings = {scheme};
    req.integer_arrays = {ints(nverts), ints(verts)};
    const std::vector<std::string> tag_names = tags.is_none() ? std::vector<std::string>{} : strings(tags);
    if (!tag_names.empty()) {
      req.string_arrays = {tag_names};
      req.integer_arrays.push_back(ints(nargs));
      req.integer_arrays.push_back(intargs.is_none() ? std::vector<int>{} : ints(intargs));
      req.number_arrays = {floatargs.is_none() ? std::vector<double>{} : doubles(floatargs)};
    }
    primitive(r, req, p);
  }, py::arg("scheme"), py::arg("nverts"), py::arg("verts"), py::arg("tags") = py::none(),
     py::arg("nargs") = py::none(), py::arg("intargs") = py::none(), py::arg("floatargs") = py::none(),
     py::arg("params") = Params());

  // --- procedurals and archives ---
  ri.def("ReadArchive", [](PyRi& r, const std::string& name) {
    r.run("ReadArchive", [&](RiSession& s, const SourceLoc& loc) { s.read_archive(name, loc); });
  });
  ri.def("ArchiveRecord", [](PyRi& r, const std::string& type, const std::string& text) {
    r.run("ArchiveRecord", [&](RiSession& s, const SourceLoc& loc) {
      s.target().ignored_request("ArchiveRecord", {}, {type, text}, loc);
    });
  });
  // Procedural(data, bound, subdivide): subdivide is ri.ProcDelayedReadArchive (data: [file]),
  // ri.ProcRunProgram (data: [program, argument]) or a callable, called as subdivide(data, detail)
  // when the bound can reach the image (detail: its area in pixels, 1e38 when unknown), inside an
  // attribute block; it makes its own calls on this Ri.
  ri.def("Procedural", [](PyRi& r, const py::object& data, const py::object& bound, const py::object& subdivide,
                          const py::object& free_data) {
    const std::array<double, 6> b = bound6(bound);
    if (py::isinstance<py::str>(subdivide)) {
      const std::string kind = py::cast<std::string>(subdivide);
      const std::vector<std::string> args = strings(data);
      r.run("Procedural", [&](RiSession& s, const SourceLoc& loc) {
        if (kind == "DelayedReadArchive" && !args.empty()) s.delayed_read_archive(args[0], b, loc);
        else if (kind == "RunProgram" && args.size() >= 2) s.run_program(args[0], args[1], b, loc);
        else s.diagnostics().warning(loc, "Procedural", "\"" + kind + "\" with these arguments is not supported: skipped");
      });
    } else {
      r.run("Procedural", [&](RiSession& s, const SourceLoc& loc) {
        s.expand_procedural(b, [&](double detail) { subdivide(data, detail > 0 ? detail : 1e38); }, loc);
      });
    }
    if (!free_data.is_none()) free_data(data);
  }, py::arg("data"), py::arg("bound"), py::arg("subdivide"), py::arg("free") = py::none());
}

void define_tokens(py::class_<PyRi>& ri) {
  const std::pair<const char*, const char*> tokens[] = {
      {"P", "P"}, {"PW", "Pw"}, {"PZ", "Pz"}, {"N", "N"}, {"NP", "Np"}, {"CS", "Cs"}, {"OS", "Os"}, {"S", "s"},
      {"T", "t"}, {"ST", "st"}, {"WIDTH", "width"}, {"CONSTANTWIDTH", "constantwidth"},
      {"PERSPECTIVE", "perspective"}, {"ORTHOGRAPHIC", "orthographic"}, {"FOV", "fov"},
      {"INTENSITY", "intensity"}, {"LIGHTCOLOR", "lightcolor"}, {"FROM", "from"}, {"TO", "to"},
      {"CONEANGLE", "coneangle"}, {"CONEDELTAANGLE", "conedeltaangle"}, {"KA", "Ka"}, {"KD", "Kd"}, {"KS", "Ks"},
      {"ROUGHNESS", "roughness"}, {"SPECULARCOLOR", "specularcolor"}, {"LINEAR", "linear"}, {"CUBIC", "cubic"},
      {"PERIODIC", "periodic"}, {"NONPERIODIC", "nonperiodic"}, {"BILINEAR", "bilinear"}, {"BICUBIC", "bicubic"},
      {"RGB", "rgb"}, {"RGBA", "rgba"}, {"FILE", "file"}, {"FRAMEBUFFER", "framebuffer"},
      {"BEZIERBASIS", "bezier"}, {"BSPLINEBASIS", "b-spline"}, {"CATMULLROMBASIS", "catmull-rom"},
      {"HERMITEBASIS", "hermite"}, {"POWERBASIS", "power"}, {"ProcDelayedReadArchive", "DelayedReadArchive"},
      {"ProcRunProgram", "RunProgram"}};
  for (const auto& [name, value] : tokens) ri.attr(name) = value;
  ri.attr("BEZIERSTEP") = 3;
  ri.attr("BSPLINESTEP") = 1;
  ri.attr("CATMULLROMSTEP") = 1;
  ri.attr("HERMITESTEP") = 2;
  ri.attr("POWERSTEP") = 4;
  ri.attr("RENDER") = py::none();
  ri.attr("RIE_WARNING") = kSeverityWarning;
  ri.attr("RIE_ERROR") = kSeverityError;
}

}  // namespace

void define_module(py::module_& m) {
  m.doc() = "darc's RenderMan Interface: ri = darc.Ri(); ri.Begin(ri.RENDER or 'out.rib'); ...; ri.End()";
  py::class_<PyRi> ri(m, "Ri");
  ri.def(py::init<>());
  define_requests(ri);
  define_geometry(ri);
  define_tokens(ri);
}

}  // namespace darc::python

PYBIND11_MODULE(darc, m) { darc::python::define_module(m); }
