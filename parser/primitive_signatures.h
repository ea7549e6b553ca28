// The fixed arguments of each geometry request that reaches RiTarget::primitive, in order (RI
// Spec 3.2 ch. 5, RI 3.4 for SubdivisionMesh): what the parser reads, what RibWriter writes
// back, and the positions a PrimitiveRequest's typed lists hold.
#pragma once

#include <span>
#include <string_view>

namespace darc {

enum class PrimitiveArgType {
  Number,        // -> PrimitiveRequest::numbers; consecutive ones may be bracketed together
  Integer,       // -> numbers, checked integral
  String,        // -> strings
  IntegerArray,  // -> integer_arrays
  NumberArray,   // -> number_arrays
  StringArray,   // -> string_arrays
};

struct PrimitiveArgSpec {
  PrimitiveArgType type;
  const char* name;  // for messages: "expected <name>"
  // May be left out when the parameter list follows (SubdivisionMesh's tags): read only when
  // the next token opens an array.
  bool optional = false;
};

struct PrimitiveSignature {
  std::string_view request;
  std::span<const PrimitiveArgSpec> args;
};

// Every request that goes through RiTarget::primitive.
std::span<const PrimitiveSignature> primitive_signatures();

// The signature of `request`, or nullptr when it does not go through RiTarget::primitive.
const PrimitiveSignature* find_primitive_signature(std::string_view request);

}  // namespace darc
