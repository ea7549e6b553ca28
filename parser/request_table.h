// The dispatch table from RIB request names to the functions that read their arguments and
// call the RiTarget. Requests that need the parser's own state (Declare; Option, Attribute and
// FrameBegin, which conditions refer to; ReadArchive, ArchiveBegin, IfBegin, ...) are
// handled by RibParser itself and are not in this table; known_requests.h lists the requests
// darc does not implement.
#pragma once

#include <string>
#include <string_view>

#include "parser/request_reader.h"
#include "parser/ri_target.h"

namespace darc {

struct RequestContext {
  RequestReader& args;
  RiTarget& target;
  const SourceLoc& loc;  // of the request name
  const std::string& name;
};

using RequestHandler = void (*)(RequestContext&);

// The handler of `name`, or nullptr when the table does not know it.
RequestHandler find_request_handler(std::string_view name);

}  // namespace darc
