#include "parser/conditional_blocks.h"

#include <fmt/format.h>

#include "parser/diagnostics.h"

namespace darc {

void ConditionalBlocks::if_begin(const SourceLoc& loc, const Condition& condition) {
  const bool enclosing = active();
  const bool taken = enclosing && condition();
  blocks_.push_back(Block{loc, enclosing, taken, false, taken});
}

ConditionalBlocks::Block& ConditionalBlocks::innermost(const char* request) {
  if (blocks_.empty()) throw RibError(fmt::format("{} without IfBegin", request));
  Block& b = blocks_.back();
  if (b.in_else && std::string_view(request) != "IfEnd")
    throw RibError(fmt::format("{} after Else (the IfBegin at {})", request, b.loc.str()));
  return b;
}

void ConditionalBlocks::else_if(const Condition& condition) {
  Block& b = innermost("ElseIf");
  if (!b.enclosing_active || b.branch_taken) {
    b.active = false;
    return;
  }
  b.active = condition();
  b.branch_taken = b.active;
}

void ConditionalBlocks::else_branch() {
  Block& b = innermost("Else");
  b.in_else = true;
  b.active = b.enclosing_active && !b.branch_taken;
  b.branch_taken = true;
}

void ConditionalBlocks::if_end() {
  innermost("IfEnd");
  blocks_.pop_back();
}

std::vector<SourceLoc> ConditionalBlocks::open_blocks() const {
  std::vector<SourceLoc> out;
  for (const Block& b : blocks_) out.push_back(b.loc);
  return out;
}

}  // namespace darc
