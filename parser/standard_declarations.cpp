#include "parser/standard_declarations.h"

#include <array>
#include <utility>

namespace darc {

namespace {

using SC = StorageClass;
using PT = ParamType;

struct StandardDeclaration {
  std::string_view name;
  ParamDecl decl;
};

// Primitive variables, then standard shader and light parameters (uniform by default).
constexpr std::array kStandardDeclarations = {
    StandardDeclaration{"P", {SC::Vertex, PT::Point, 1}},
    StandardDeclaration{"Pw", {SC::Vertex, PT::HPoint, 1}},
    StandardDeclaration{"Pz", {SC::Vertex, PT::Float, 1}},
    StandardDeclaration{"N", {SC::Varying, PT::Normal, 1}},
    StandardDeclaration{"Np", {SC::Uniform, PT::Normal, 1}},
    StandardDeclaration{"Cs", {SC::Varying, PT::Color, 1}},
    StandardDeclaration{"Os", {SC::Varying, PT::Color, 1}},
    StandardDeclaration{"s", {SC::Varying, PT::Float, 1}},
    StandardDeclaration{"t", {SC::Varying, PT::Float, 1}},
    StandardDeclaration{"st", {SC::Varying, PT::Float, 2}},
    StandardDeclaration{"width", {SC::Varying, PT::Float, 1}},
    StandardDeclaration{"constantwidth", {SC::Constant, PT::Float, 1}},
    StandardDeclaration{"fov", {SC::Uniform, PT::Float, 1}},
    StandardDeclaration{"Ka", {SC::Uniform, PT::Float, 1}},
    StandardDeclaration{"Kd", {SC::Uniform, PT::Float, 1}},
    StandardDeclaration{"Ks", {SC::Uniform, PT::Float, 1}},
    StandardDeclaration{"Kr", {SC::Uniform, PT::Float, 1}},
    StandardDeclaration{"Kt", {SC::Uniform, PT::Float, 1}},
    StandardDeclaration{"roughness", {SC::Uniform, PT::Float, 1}},
    StandardDeclaration{"eta", {SC::Uniform, PT::Float, 1}},
    StandardDeclaration{"intensity", {SC::Uniform, PT::Float, 1}},
    StandardDeclaration{"coneangle", {SC::Uniform, PT::Float, 1}},
    StandardDeclaration{"conedeltaangle", {SC::Uniform, PT::Float, 1}},
    StandardDeclaration{"beamdistribution", {SC::Uniform, PT::Float, 1}},
    StandardDeclaration{"lightcolor", {SC::Uniform, PT::Color, 1}},
    StandardDeclaration{"specularcolor", {SC::Uniform, PT::Color, 1}},
    StandardDeclaration{"from", {SC::Uniform, PT::Point, 1}},
    StandardDeclaration{"to", {SC::Uniform, PT::Point, 1}},
    StandardDeclaration{"texturename", {SC::Uniform, PT::String, 1}},
    // Not in appendix A, but how every renderer's light shaders ask for shadows (shadowspot,
    // BMRT's "raytrace"); the scene builder reads it from any light.
    StandardDeclaration{"shadowname", {SC::Uniform, PT::String, 1}},
};

}  // namespace

std::optional<ParamDecl> standard_declaration(std::string_view name) {
  for (const StandardDeclaration& entry : kStandardDeclarations) {
    if (entry.name == name) return entry.decl;
  }
  return std::nullopt;
}

}  // namespace darc
