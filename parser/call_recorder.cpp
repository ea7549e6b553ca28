#include "parser/call_recorder.h"

namespace darc {

// Each call captures its arguments by value (a reference parameter captured by copy copies the
// object); the replayed call passes the captured copies.
#define DARC_RI_REQUEST(Rib, method, reading, shape, args)                                          \
  DARC_RI_IF_GENERIC_##reading(void CallRecorder::method(DARC_RI_PARAMS(args) const SourceLoc& loc) { \
    keep(#Rib, loc, [=](RiTarget& t) { t.method(DARC_RI_NAMES(args) loc); });                       \
  })
#define DARC_RI_REQUEST_PL(Rib, method, reading, shape, args)                                       \
  DARC_RI_IF_GENERIC_##reading(                                                                     \
      void CallRecorder::method(DARC_RI_PARAMS(args) const ParamList& params, const SourceLoc& loc) { \
        keep(#Rib, loc, [=](RiTarget& t) { t.method(DARC_RI_NAMES(args) params, loc); });           \
      })
#include "parser/ri_requests.def"
#undef DARC_RI_REQUEST
#undef DARC_RI_REQUEST_PL

// The special rows: kept under the name of the request they stand for.

void CallRecorder::ignored_request(const std::string& request, const std::vector<double>& numbers,
                                   const std::vector<std::string>& strings, const SourceLoc& loc) {
  keep(request, loc, [=](RiTarget& t) { t.ignored_request(request, numbers, strings, loc); });
}

void CallRecorder::primitive(const PrimitiveRequest& request, const ParamList& params, const SourceLoc& loc) {
  keep(request.name, loc, [=](RiTarget& t) { t.primitive(request, params, loc); });
}

void CallRecorder::skipped_primitive(const std::string& request, const SourceLoc& loc) {
  keep(request, loc, [=](RiTarget& t) { t.skipped_primitive(request, loc); });
}

}  // namespace darc
