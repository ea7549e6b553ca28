#include "parser/rib_parser.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>

#include "parser/error_handler.h"
#include "parser/lexer.h"
#include "parser/request_table.h"

namespace darc {

namespace {

namespace fs = std::filesystem;

// ReadArchive nesting limit: far deeper than any real scene, and stops runaway recursion
// through distinct files (a cycle through the same file is caught separately).
constexpr size_t kMaxArchiveDepth = 64;

std::string canonical_name(const std::string& path) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::path(path), ec);
  return ec ? path : p.string();
}

bool is_readable_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

// Splits a search path "a:b:&:@" replacing "&" by the previous path's directories and "@" by
// the default ones.
std::vector<std::string> expand_search_path(const std::string& spec, const std::vector<std::string>& previous,
                                            const std::vector<std::string>& defaults) {
  std::vector<std::string> dirs;
  size_t begin = 0;
  while (begin <= spec.size()) {
    size_t end = spec.find(':', begin);
    if (end == std::string::npos) end = spec.size();
    const std::string dir = spec.substr(begin, end - begin);
    if (dir == "&") {
      dirs.insert(dirs.end(), previous.begin(), previous.end());
    } else if (dir == "@") {
      dirs.insert(dirs.end(), defaults.begin(), defaults.end());
    } else if (!dir.empty()) {
      dirs.push_back(dir);
    }
    begin = end + 1;
  }
  return dirs;
}

// The search path given by every string of `param`.
std::vector<std::string> search_path(const Param& param, const std::vector<std::string>& previous,
                                     const std::vector<std::string>& defaults) {
  std::vector<std::string> dirs;
  for (const std::string& spec : param.strings) {
    const std::vector<std::string> part = expand_search_path(spec, previous, defaults);
    dirs.insert(dirs.end(), part.begin(), part.end());
  }
  return dirs;
}

}  // namespace

bool RibParser::parse_file(const std::string& path) {
  const int errors_before = diag_.error_count();
  std::string text;
  std::string reason;
  if (!read_rib_text(path, text, reason)) {
    diag_.error(SourceLoc{std::make_shared<const std::string>(path), 0, 0}, "",
                fmt::format("cannot open \"{}\": {}", path, reason));
    return false;
  }
  parse_text(std::move(text), path == "-" ? std::string("<stdin>") : path);
  return diag_.error_count() == errors_before;
}

bool RibParser::parse_string(std::string_view text, const std::string& name) {
  const int errors_before = diag_.error_count();
  parse_text(std::string(text), name);
  return diag_.error_count() == errors_before;
}

void RibParser::parse_text(std::string text, const std::string& name) {
  Lexer lexer(std::move(text), std::make_shared<const std::string>(name));
  include_stack_.push_back(canonical_name(name));
  parse_requests(lexer);
  include_stack_.pop_back();
}

void RibParser::parse_requests(Lexer& lexer) {
  RequestReader args(lexer, declared_, diag_);
  while (true) {
    if (diag_.aborted()) return;  // ErrorHandler "abort": nothing after the first error is read
    const Token& token = lexer.peek();
    if (token.kind == TokenKind::End) return;
    if (token.kind == TokenKind::Error) {
      diag_.error(lexer.loc(token), "", token.text);
      lexer.next();
      continue;
    }
    if (token.kind != TokenKind::Word) {
      diag_.error(lexer.loc(token), "", fmt::format("expected a request name, found {}", describe(token)));
      skip_to_next_request(lexer);
      continue;
    }
    const Token name = lexer.next();
    const SourceLoc loc = lexer.loc(name);
    try {
      dispatch(name.text, args, loc);
    } catch (const RibSyntaxError& e) {
      diag_.error(e.loc, name.text, e.what());
      skip_to_next_request(lexer);
    } catch (const RibError& e) {
      diag_.error(loc, name.text, e.what());
      skip_to_next_request(lexer);
    }
  }
}

void RibParser::skip_to_next_request(Lexer& lexer) {
  while (true) {
    const Token& t = lexer.peek();
    if (t.kind == TokenKind::Word || t.kind == TokenKind::End) return;
    // Lexical errors in skipped text are still errors (a binary byte, an unterminated string).
    if (t.kind == TokenKind::Error) diag_.error(lexer.loc(t), "", t.text);
    lexer.next();
  }
}

void RibParser::dispatch(const std::string& request, RequestReader& args, const SourceLoc& loc) {
  if (request == "ReadArchive") return read_archive(args, loc);
  if (request == "Declare") return declare(args, loc);
  if (request == "Option") return option(args, loc);
  if (request == "ErrorHandler") return error_handler(args, loc);
  if (request == "Procedural" || request == "Procedural2") return procedural(args, request, loc);
  if (RequestHandler handler = find_request_handler(request)) {
    RequestContext context{args, target_, loc, request};
    return handler(context);
  }
  if (is_unsupported_request(request)) {
    diag_.warning_once("unsupported request " + request, loc, request,
                       fmt::format("unsupported request \"{}\": skipped", request));
  } else {
    diag_.warning_once("unknown request " + request, loc, request,
                       fmt::format("unknown request \"{}\": skipped", request));
  }
  // Skip the arguments; lexical errors among them are still reported.
  std::vector<double> numbers;
  std::vector<std::string> strings;
  args.flatten_rest(numbers, strings);
}

void RibParser::declare(RequestReader& args, const SourceLoc& loc) {
  const std::string name = args.string("the parameter name");
  const std::string text = args.string("the declaration");
  args.expect_request_end("Declare");
  const std::optional<ParamDecl> decl = parse_param_decl(text);
  if (!decl) throw RibError(fmt::format("invalid declaration \"{}\" for \"{}\"", text, name));
  declared_[name] = *decl;
  target_.declare(name, to_string(*decl), loc);
}

void RibParser::option(RequestReader& args, const SourceLoc& loc) {
  const std::string category = args.string("the option category");
  const ParamList params = args.param_list("Option");
  if (category == "searchpath") {
    if (const Param* archive = params.find("archive")) archive_path_ = search_path(*archive, archive_path_, {});
    if (const Param* procedural = params.find("procedural")) {
      // Relative folders are taken from the file that names them, so that a scene and its
      // generators move together.
      const fs::path base = include_stack_.empty() ? fs::path() : fs::path(include_stack_.back()).parent_path();
      std::vector<std::string> dirs = search_path(*procedural, procedural_path_, procedural_folders_);
      for (std::string& dir : dirs)
        if (fs::path(dir).is_relative()) dir = (base / dir).string();
      procedural_path_ = std::move(dirs);
    }
  }
  target_.option(category, params, loc);
}

void RibParser::error_handler(RequestReader& args, const SourceLoc& loc) {
  const std::string name = args.string("the handler name");
  args.expect_request_end("ErrorHandler");
  // The target sees it as a request without effect on the image (RibWriter writes it back).
  target_.ignored_request("ErrorHandler", {}, {name}, loc);
  const std::optional<ErrorHandler> handler = error_handler_named(name);
  if (!handler) {
    diag_.warning(loc, "ErrorHandler",
                  fmt::format("unknown handler \"{}\" (expected ignore, print or abort): keeping \"{}\"", name,
                              to_string(diag_.handler())));
    return;
  }
  if (!diag_.set_handler(*handler))
    diag_.warning_once("ErrorHandler fixed", loc, "ErrorHandler",
                       fmt::format("ErrorHandler \"{}\" ignored: the command line fixed the handler to \"{}\"", name,
                                   to_string(diag_.handler())));
}

std::string RibParser::resolve_archive(const std::string& name) const {
  const fs::path given(name);
  if (given.is_absolute()) return name;
  if (!include_stack_.empty()) {
    const fs::path beside = fs::path(include_stack_.back()).parent_path() / given;
    if (is_readable_file(beside)) return beside.string();
  }
  for (const std::string& dir : archive_path_) {
    const fs::path candidate = fs::path(dir) / given;
    if (is_readable_file(candidate)) return candidate.string();
  }
  return name;
}

void RibParser::read_archive(RequestReader& args, const SourceLoc& loc) {
  const std::string name = args.string("the archive name");
  args.expect_request_end("ReadArchive");
  include_archive(name, loc);
}

void RibParser::include_archive(const std::string& name, const SourceLoc& loc) {
  if (!archive_files_allowed_)
    throw RibSyntaxError(loc, fmt::format("cannot open archive \"{}\": file access is disabled", name));
  const std::string path = resolve_archive(name);
  std::string text;
  std::string reason;
  if (!is_readable_file(path) || !read_rib_text(path, text, reason)) {
    throw RibSyntaxError(loc, fmt::format("cannot open archive \"{}\"", name));
  }
  const std::string canonical = canonical_name(path);
  if (std::find(include_stack_.begin(), include_stack_.end(), canonical) != include_stack_.end()) {
    throw RibSyntaxError(loc, fmt::format("archive \"{}\" includes itself (cycle through {})", name, canonical));
  }
  if (include_stack_.size() >= kMaxArchiveDepth) {
    throw RibSyntaxError(loc, fmt::format("archive \"{}\" is nested deeper than {} levels", name, kMaxArchiveDepth));
  }
  parse_text(std::move(text), path);
}

}  // namespace darc
