#include "ri/c_binding.h"

#include <fmt/format.h>

#include <charconv>
#include <cstdio>
#include <exception>

namespace darc {

CBindingContext*& current_c_context() {
  thread_local CBindingContext* current = nullptr;
  return current;
}

namespace {

// An error of the call; the error handler itself may fail (out of memory): then stderr.
void report_error(RiSession& session, const SourceLoc& loc, const char* request, const char* message) {
  try {
    session.diagnostics().error(loc, request, message);
  } catch (...) {
    std::fprintf(stderr, "darc: error: Ri%s: %s\n", request, message);
  }
}

}  // namespace

void with_session(const char* request, const std::function<void(RiSession&, const SourceLoc&)>& call) {
  CBindingContext* context = current_c_context();
  if (!context || !context->session) {
    std::fprintf(stderr, "darc: error: Ri%s called outside RiBegin/RiEnd: ignored\n", request);
    return;
  }
  RiSession& session = *context->session;
  if (session.stopped()) return;
  ++context->calls_in_progress;
  SourceLoc loc;
  try {
    loc = session.next_call();
    call(session, loc);
  } catch (const std::exception& e) {  // RibError: a request the target refused
    report_error(session, loc, request, e.what());
  } catch (...) {
    report_error(session, loc, request, "an exception that is not a std::exception");
  }
  --context->calls_in_progress;
}

void name_and_params(const char* request, RtToken name, RtInt n, RtToken tokens[], RtPointer values[],
                     void (RiTarget::*method)(const std::string&, const ParamList&, const SourceLoc&)) {
  with_session(request, [&](RiSession& s, const SourceLoc& loc) {
    const ParamList params = c_param_list(s, request, single_values(), n, tokens, values, loc);
    (s.target().*method)(name ? name : "", params, loc);
  });
}

double decimal_double(float value) {
  char text[64];
  const auto printed = std::to_chars(text, text + sizeof text, value);
  double out = value;
  std::from_chars(text, printed.ptr, out);
  return out;
}

TokenValues collect_token_values(va_list args) {
  TokenValues tv;
  // A list that never reaches RI_NULL cannot be told from one that does: the RI contract.
  for (;;) {
    RtToken token = va_arg(args, RtToken);
    if (token == RI_NULL) break;
    tv.tokens.push_back(token);
    tv.values.push_back(va_arg(args, RtPointer));
  }
  return tv;
}

ParamList c_param_list(RiSession& session, const char* request, const ValueCounts& counts, RtInt n,
                       const RtToken tokens[], const RtPointer values[], const SourceLoc& loc) {
  ParamList list;
  for (RtInt i = 0; i < n; ++i) {
    if (!tokens || !tokens[i]) continue;
    Param param;
    param.loc = loc;
    std::optional<ParamDecl> decl = parse_inline_decl(tokens[i], param.name);
    if (!decl) decl = session.declared_type(param.name);
    if (!decl) {
      session.diagnostics().error(
          loc, request,
          fmt::format("parameter \"{}\" is not declared (RiDeclare it or give an inline declaration): left out, "
                      "its values cannot be counted",
                      param.name));
      continue;
    }
    if (!values || !values[i]) {
      session.diagnostics().error(loc, request, fmt::format("parameter \"{}\" has no values: left out", param.name));
      continue;
    }
    param.decl = *decl;
    const size_t elements = counts.of(decl->storage);
    if (decl->is_string()) {
      const auto* strings = static_cast<const RtString*>(values[i]);
      const size_t count = elements * size_t(decl->array_size);
      param.strings.reserve(count);
      for (size_t k = 0; k < count; ++k) param.strings.emplace_back(strings[k] ? strings[k] : "");
    } else {
      const size_t count = elements * size_t(decl->components());
      param.floats.resize(count);
      if (decl->type == ParamType::Integer) {
        const auto* ints = static_cast<const RtInt*>(values[i]);
        for (size_t k = 0; k < count; ++k) param.floats[k] = float(ints[k]);
      } else {
        const auto* floats = static_cast<const RtFloat*>(values[i]);
        std::copy(floats, floats + count, param.floats.begin());
      }
    }
    list.params.push_back(std::move(param));
  }
  return list;
}

}  // namespace darc
