#include "parser/primitive_signatures.h"

#include <array>

namespace darc {

namespace {

using T = PrimitiveArgType;
using A = PrimitiveArgSpec;

constexpr A kSphere[] = {{T::Number, "radius"}, {T::Number, "zmin"}, {T::Number, "zmax"}, {T::Number, "thetamax"}};
constexpr A kCone[] = {{T::Number, "height"}, {T::Number, "radius"}, {T::Number, "thetamax"}};
constexpr A kCylinder[] = {{T::Number, "radius"}, {T::Number, "zmin"}, {T::Number, "zmax"}, {T::Number, "thetamax"}};
constexpr A kDisk[] = {{T::Number, "height"}, {T::Number, "radius"}, {T::Number, "thetamax"}};
constexpr A kHyperboloid[] = {{T::Number, "x1"}, {T::Number, "y1"}, {T::Number, "z1"}, {T::Number, "x2"},
                              {T::Number, "y2"}, {T::Number, "z2"}, {T::Number, "thetamax"}};
constexpr A kParaboloid[] = {{T::Number, "rmax"}, {T::Number, "zmin"}, {T::Number, "zmax"}, {T::Number, "thetamax"}};
constexpr A kTorus[] = {{T::Number, "rmajor"}, {T::Number, "rminor"}, {T::Number, "phimin"}, {T::Number, "phimax"},
                        {T::Number, "thetamax"}};
constexpr A kPatch[] = {{T::String, "the patch type"}};
constexpr A kPatchMesh[] = {{T::String, "the patch type"}, {T::Integer, "nu"}, {T::String, "uwrap"},
                            {T::Integer, "nv"}, {T::String, "vwrap"}};
constexpr A kNuPatch[] = {{T::Integer, "nu"},    {T::Integer, "uorder"},    {T::NumberArray, "uknot"},
                          {T::Number, "umin"},   {T::Number, "umax"},       {T::Integer, "nv"},
                          {T::Integer, "vorder"}, {T::NumberArray, "vknot"}, {T::Number, "vmin"},
                          {T::Number, "vmax"}};
constexpr A kSubdivisionMesh[] = {{T::String, "the subdivision scheme"},
                                  {T::IntegerArray, "nvertices"},
                                  {T::IntegerArray, "vertices"},
                                  {T::StringArray, "tags", true},
                                  {T::IntegerArray, "nargs", true},
                                  {T::IntegerArray, "intargs", true},
                                  {T::NumberArray, "floatargs", true},
                                  {T::StringArray, "stringargs", true}};

constexpr std::array kSignatures = {
    PrimitiveSignature{"Sphere", kSphere},
    PrimitiveSignature{"Cone", kCone},
    PrimitiveSignature{"Cylinder", kCylinder},
    PrimitiveSignature{"Disk", kDisk},
    PrimitiveSignature{"Hyperboloid", kHyperboloid},
    PrimitiveSignature{"Paraboloid", kParaboloid},
    PrimitiveSignature{"Torus", kTorus},
    PrimitiveSignature{"Patch", kPatch},
    PrimitiveSignature{"PatchMesh", kPatchMesh},
    PrimitiveSignature{"NuPatch", kNuPatch},
    PrimitiveSignature{"SubdivisionMesh", kSubdivisionMesh},
    PrimitiveSignature{"Points", {}},
};

}  // namespace

std::span<const PrimitiveSignature> primitive_signatures() { return kSignatures; }

const PrimitiveSignature* find_primitive_signature(std::string_view request) {
  for (const PrimitiveSignature& s : kSignatures)
    if (s.request == request) return &s;
  return nullptr;
}

}  // namespace darc
