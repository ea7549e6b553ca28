// How many diagnostics of one severity are shown, as compilers cap their error output: at most
// kMaxShownPerKind messages of each kind and kMaxShownInTotal in all; the rest are counted and
// summed up in one line at the end. A file with one bad request repeated a million times then
// prints a screenful, not a million lines. Only showing is capped: Diagnostics counts exactly.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>

namespace darc {

// Messages of one kind shown at most: enough to see whether they sit at one place or spread
// over the file (and to fix a handful by hand), few enough to leave the screen to other kinds.
constexpr int kMaxShownPerKind = 20;
// Messages of one severity shown at most in a run: ten kinds at their cap, about four screens;
// past that nobody reads on, and a render farm's log stays small.
constexpr int kMaxShownInTotal = 200;

// The kind of a message: the request name and the text with every number replaced by '#' and
// every double-quoted value by "" (the values are what varies between repeats of one mistake),
// e.g. `Basis: unknown basis ""` for both `unknown basis "bsline"` and `unknown basis "bezir"`,
// and `Sides: Sides must be # or #, found #` for every bad Sides. Different requests or
// wordings stay different kinds.
std::string message_kind(const std::string& request, const std::string& message);

// The shown/suppressed decision for the messages of one severity.
class MessageBudget {
 public:
  // Whether a message of `kind` may still be shown; a message that may not is counted as
  // suppressed.
  bool admit(const std::string& kind);
  std::int64_t suppressed() const { return suppressed_; }

 private:
  // Shown messages per kind. A kind is only added while the total cap has room, so this holds
  // at most kMaxShownInTotal entries however many distinct messages a file produces.
  std::unordered_map<std::string, int> shown_per_kind_;
  int shown_ = 0;
  std::int64_t suppressed_ = 0;
};

}  // namespace darc
