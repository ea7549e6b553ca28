#include "parser/inline_archives.h"

namespace darc {

const InlineArchive* InlineArchiveStore::find(std::string_view name) const {
  const auto it = archives_.find(name);
  return it == archives_.end() ? nullptr : &it->second;
}

ArchiveBodyScan scan_archive_body(Lexer& lexer) {
  ArchiveBodyScan scan;
  const Token first = lexer.peek();
  int depth = 0;
  while (true) {
    Token t = lexer.next();
    if (t.kind == TokenKind::End) return scan;
    if (t.kind == TokenKind::Error) {
      if (!scan.lexical_error) scan.lexical_error = std::move(t);
      continue;
    }
    if (t.kind != TokenKind::Word) continue;
    if (t.text == "ArchiveBegin") {
      ++depth;
    } else if (t.text == "ArchiveEnd") {
      if (depth == 0) {
        scan.closed = true;
        scan.body = lexer.span(first, t.offset);
        return scan;
      }
      --depth;
    }
  }
}

}  // namespace darc
