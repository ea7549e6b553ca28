// What the functions of the C binding (ri.h; c_binding_*.cpp) share: the context a thread's
// calls go to, the guard every call passes through, and the conversion of C values (variadic
// token/value lists, bare value pointers, floats) into the values an RiTarget takes.
//
// The RI C binding has a current context by design (RiBegin/RiContext): it is this thread's,
// held in one thread_local pointer, the only state outside a context.
#pragma once

#include "ri/ri.h"
#include "ri/ri_session.h"
#include "ri/value_counts.h"

#include <cstdarg>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace darc {

// A context of the C binding: the session and what the C interface adds to it.
struct CBindingContext {
  RtErrorHandler handler = RiErrorPrint;
  std::set<std::string, std::less<>> tokens;  // RiDeclare's returned names, alive until RiEnd
  std::unique_ptr<RiSession> session;
  // Calls in progress (a procedural's subdivide function, an error handler, calls back): RiEnd
  // is refused meanwhile, the session being in use.
  int calls_in_progress = 0;
};

// This thread's current context (null outside RiBegin/RiEnd).
CBindingContext*& current_c_context();

// Runs `call` with the current session and the position of this call, unless there is no
// context (reported on stderr) or it has stopped at an error under RiErrorAbort. A RibError or
// any other exception is reported as an error of `request` at the call's position: nothing
// leaves through the C interface.
void with_session(const char* request, const std::function<void(RiSession&, const SourceLoc&)>& call);

// The double a float argument stands for: the decimal number it prints as (shortest round
// trip), which is what RIB text holding that number reads as. So a float given to the binding
// builds the same scene as the RIB the binding writes for it.
double decimal_double(float value);

// Token/value pairs of a variadic call, read up to the RI_NULL token.
struct TokenValues {
  std::vector<RtToken> tokens;
  std::vector<RtPointer> values;
  RtInt size() const { return RtInt(tokens.size()); }
};
TokenValues collect_token_values(va_list args);

// The parameter list of a call: each token typed by its inline declaration, RiDeclare or the
// standard declarations, with as many values as its storage class has in the request
// (`counts`). An undeclared token is an error (its values cannot be counted) and is left out.
ParamList c_param_list(RiSession& session, const char* request, const ValueCounts& counts, RtInt n,
                       const RtToken tokens[], const RtPointer values[], const SourceLoc& loc);

// A request of a name and a parameter list (Surface, Projection, Hider, Camera, ...), whose
// parameters have one value each: the call passed to the target's `method`.
void name_and_params(const char* request, RtToken name, RtInt n, RtToken tokens[], RtPointer values[],
                     void (RiTarget::*method)(const std::string&, const ParamList&, const SourceLoc&));

}  // namespace darc

// The variadic form of a ...V function: collects the pairs after `last` and calls `call`, which
// names them `tv` (TokenValues).
#define DARC_RI_WITH_TOKEN_VALUES(last, call)            \
  do {                                                   \
    va_list ri_args_;                                    \
    va_start(ri_args_, last);                            \
    darc::TokenValues tv = darc::collect_token_values(ri_args_); \
    va_end(ri_args_);                                    \
    call;                                                \
  } while (0)
