// The kinds of fixed argument an RI request takes (parser/ri_requests.def names one per
// argument). A kind says how the argument is passed to an RiTarget (`param`) and how it is kept
// by value (`value`); the parser reads it and RibWriter writes it by kind (request_table.cpp,
// rib_writer.cpp), so two kinds with the same C++ type (a handle and a string) still read and
// write differently.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace darc {

// A Basis argument: a standard name ("bezier", "b-spline", "catmull-rom", "hermite", "power")
// or 16 numbers (row-major, rows multiply [t^3 t^2 t 1]).
struct BasisArg {
  std::string name;  // empty when a matrix was given
  std::array<double, 16> matrix{};
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

template <typename Value, typename Param = Value>
struct RiArgKind {
  using value = Value;
  using param = Param;
};

struct RiInt : RiArgKind<int> {};
struct RiFloat : RiArgKind<double> {};
struct RiBool : RiArgKind<bool> {};  // written 0 or 1
struct RiString : RiArgKind<std::string, const std::string&> {};
// A light or object handle: an integer (kept without decimals, written back bare) or a string.
struct RiHandle : RiArgKind<std::string, const std::string&> {};
struct RiMatrix : RiArgKind<std::array<double, 16>, const std::array<double, 16>&> {};  // one bracketed array
struct RiColor : RiArgKind<std::array<float, 3>, const std::array<float, 3>&> {};       // one bracketed array
struct RiBasis : RiArgKind<BasisArg, const BasisArg&> {};
struct RiIntArray : RiArgKind<std::vector<int>, const std::vector<int>&> {};
struct RiFloatArray : RiArgKind<std::vector<double>, const std::vector<double>&> {};
struct RiStringArray : RiArgKind<std::vector<std::string>, const std::vector<std::string>&> {};
struct RiPrimitive : RiArgKind<PrimitiveRequest, const PrimitiveRequest&> {};
// A run of N numbers (DARC_RI_ARG2..4: Translate's three, ScreenWindow's four) written bare or
// as one bracketed array, passed as N doubles: the first of the run, then RiNumbersNext for each
// further one.
template <int N>
struct RiNumbers : RiArgKind<double> {};
struct RiNumbersNext : RiArgKind<double> {};

}  // namespace darc
