#include "parser/error_handler.h"

namespace darc {

std::optional<ErrorHandler> error_handler_named(std::string_view name) {
  if (name == "ignore") return ErrorHandler::Ignore;
  if (name == "print") return ErrorHandler::Print;
  if (name == "abort") return ErrorHandler::Abort;
  return std::nullopt;
}

const char* to_string(ErrorHandler handler) {
  switch (handler) {
    case ErrorHandler::Ignore:
      return "ignore";
    case ErrorHandler::Print:
      return "print";
    case ErrorHandler::Abort:
      return "abort";
  }
  return "print";
}

}  // namespace darc
