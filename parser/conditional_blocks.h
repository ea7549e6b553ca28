// The IfBegin / ElseIf / Else / IfEnd blocks open in one RIB text (a file or an inline
// archive's body): which branch runs, with nesting. A branch runs when every enclosing branch
// runs and its condition is the first true one of its block; conditions of branches that cannot
// run are not evaluated at all.
#pragma once

#include <functional>
#include <vector>

#include "parser/source_loc.h"

namespace darc {

class ConditionalBlocks {
 public:
  // Evaluates the condition of the branch being opened (called only when it could run).
  using Condition = std::function<bool()>;

  // Whether requests run here (no enclosing branch is skipped).
  bool active() const { return blocks_.empty() || blocks_.back().active; }

  void if_begin(const SourceLoc& loc, const Condition& condition);
  // These throw RibError when no IfBegin is open, or after the block's Else.
  void else_if(const Condition& condition);
  void else_branch();
  void if_end();

  // The IfBegin of every block still open, outermost first.
  std::vector<SourceLoc> open_blocks() const;

 private:
  struct Block {
    SourceLoc loc;          // of its IfBegin
    bool enclosing_active;  // the requests around the block run
    bool branch_taken;      // one of its branches ran (or is running)
    bool in_else;           // Else was seen
    bool active;            // the current branch runs
  };
  Block& innermost(const char* request);

  std::vector<Block> blocks_;
};

}  // namespace darc
