// Every request name of the RenderMan Interface that a RIB file may hold: the RI Spec 3.2
// requests, those the RI Spec 3.3/3.4 and PRMan 12-18 added, and those of RenderMan 19-24 (RIS)
// RIB. darc implements some of them (request_table.h, RibParser); for the others this table
// lets the parser say "not supported" instead of "unknown", which reads like a typo.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace darc {

// Where a request name comes from (the first document or release that has it).
enum class RequestOrigin {
  RiSpec32,      // RenderMan Interface Specification 3.2 (2000)
  RiSpec34,      // RI Spec 3.3/3.4 and PRMan 12-18 extensions (2005-2013)
  RenderManRis,  // RenderMan 19-24 RIB (RIS: Bxdf, Pattern, Light, ...)
};

// What a request does, as far as a frame's content is concerned.
enum class RequestKind {
  Geometry,  // makes primitives (Cylinder, SubdivisionMesh, Procedural2, ...)
  Other,     // options, attributes, shaders, blocks, textures, ...
};

struct KnownRequest {
  std::string_view name;
  RequestOrigin origin;
  RequestKind kind;
};

// The entry for `name` (case-sensitive, as RIB is), or nullopt when no RenderMan document has it.
std::optional<KnownRequest> find_known_request(std::string_view name);

// The whole table, in document order (for tests and documentation).
std::span<const KnownRequest> known_requests();

// "RI Spec 3.2", "RI Spec 3.4 / PRMan", "RenderMan 19+ RIB": for messages.
std::string_view describe(RequestOrigin origin);

}  // namespace darc
