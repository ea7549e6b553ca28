#include "parser/extended_regex.h"

#include <fmt/format.h>

#include <limits>
#include <utility>

namespace darc {

namespace {

// Longest pattern compiled: conditions compare pass names and object names, a few dozen bytes;
// the cap bounds the program (about three instructions per pattern byte).
constexpr size_t kMaxPatternBytes = 1000;
// Deepest nesting of parentheses: the parser and the code generator recurse once per level.
constexpr int kMaxNesting = 64;

// The parsed pattern, before code generation. Concatenations and alternations keep their parts
// in one list, so recursion depth follows the parenthesis nesting only.
struct Node {
  enum class Kind { Empty, Byte, Any, Class, LineBegin, LineEnd, Concat, Alternate, Star, Plus, Optional };
  Kind kind = Kind::Empty;
  unsigned char byte = 0;
  int class_index = 0;
  std::vector<int> parts{};  // Concat, Alternate: the parts; Star, Plus, Optional: the one repeated
};

class ParseFailure {
 public:
  explicit ParseFailure(std::string m) : message(std::move(m)) {}
  std::string message;
};

}  // namespace

class RegexCompiler {
 public:
  RegexCompiler(std::string_view pattern, ExtendedRegex& out) : pattern_(pattern), out_(out) {}

  void compile() {
    const int root = parse_alternation(0);
    if (pos_ < pattern_.size()) throw ParseFailure(fmt::format("unmatched ')' at byte {}", pos_ + 1));
    emit(root);
    out_.program_.push_back({ExtendedRegex::Op::Match});
  }

 private:
  using Kind = Node::Kind;

  int add(Node n) {
    nodes_.push_back(std::move(n));
    return static_cast<int>(nodes_.size() - 1);
  }

  bool at_end() const { return pos_ >= pattern_.size(); }

  int parse_alternation(int depth) {
    if (depth > kMaxNesting) throw ParseFailure(fmt::format("parentheses nested deeper than {}", kMaxNesting));
    Node alt{Kind::Alternate};
    alt.parts.push_back(parse_concatenation(depth));
    while (!at_end() && pattern_[pos_] == '|') {
      ++pos_;
      alt.parts.push_back(parse_concatenation(depth));
    }
    return alt.parts.size() == 1 ? alt.parts[0] : add(std::move(alt));
  }

  int parse_concatenation(int depth) {
    Node cat{Kind::Concat};
    while (!at_end() && pattern_[pos_] != '|' && pattern_[pos_] != ')') cat.parts.push_back(parse_repetition(depth));
    if (cat.parts.empty()) return add(Node{Kind::Empty});
    return cat.parts.size() == 1 ? cat.parts[0] : add(std::move(cat));
  }

  static bool is_quantifier(Kind k) { return k == Kind::Star || k == Kind::Plus || k == Kind::Optional; }

  int parse_repetition(int depth) {
    int atom = parse_atom(depth);
    while (!at_end()) {
      const char c = pattern_[pos_];
      Kind k;
      if (c == '*')
        k = Kind::Star;
      else if (c == '+')
        k = Kind::Plus;
      else if (c == '?')
        k = Kind::Optional;
      else if (c == '{')
        throw ParseFailure("bounded repetition {m,n} is not supported");
      else
        break;
      ++pos_;
      if (is_quantifier(nodes_[size_t(atom)].kind)) {
        // A quantified quantifier (a**, a+?, ...) is one quantifier: ++ stays +, ?? stays ?,
        // anything else is *. Folding keeps the nesting flat whatever the input.
        Kind& inner = nodes_[size_t(atom)].kind;
        if (inner != k) inner = Kind::Star;
        continue;
      }
      Node q{k};
      q.parts.push_back(atom);
      atom = add(std::move(q));
    }
    return atom;
  }

  int parse_atom(int depth) {
    const char c = pattern_[pos_++];
    switch (c) {
      case '(': {
        const int inner = parse_alternation(depth + 1);
        if (at_end() || pattern_[pos_] != ')') throw ParseFailure("unmatched '('");
        ++pos_;
        return inner;
      }
      case '[':
        return parse_class();
      case '.':
        return add(Node{Kind::Any});
      case '^':
        return add(Node{Kind::LineBegin});
      case '$':
        return add(Node{Kind::LineEnd});
      case '*':
      case '+':
      case '?':
        throw ParseFailure(fmt::format("'{}' at byte {} has nothing to repeat", c, pos_));
      case '{':
        throw ParseFailure("bounded repetition {m,n} is not supported");
      case '\\':
        if (at_end()) throw ParseFailure("the pattern ends with '\\'");
        if (pattern_[pos_] >= '1' && pattern_[pos_] <= '9') throw ParseFailure("back-references are not supported");
        return add(Node{Kind::Byte, static_cast<unsigned char>(pattern_[pos_++])});
      default:
        return add(Node{Kind::Byte, static_cast<unsigned char>(c)});
    }
  }

  // After '[': a set of bytes, "]" first and "-" first or last taken literally.
  int parse_class() {
    std::bitset<256> set;
    bool negated = false;
    if (!at_end() && pattern_[pos_] == '^') {
      negated = true;
      ++pos_;
    }
    bool first = true;
    while (true) {
      if (at_end()) throw ParseFailure("unmatched '['");
      unsigned char c = static_cast<unsigned char>(pattern_[pos_]);
      if (c == ']' && !first) break;
      if (c == '[' && pos_ + 1 < pattern_.size() &&
          (pattern_[pos_ + 1] == ':' || pattern_[pos_ + 1] == '=' || pattern_[pos_ + 1] == '.'))
        throw ParseFailure("POSIX character classes ([:alpha:], ...) are not supported");
      ++pos_;
      if (c == '\\' && !at_end()) c = static_cast<unsigned char>(pattern_[pos_++]);
      first = false;
      if (pos_ + 1 < pattern_.size() && pattern_[pos_] == '-' && pattern_[pos_ + 1] != ']') {
        unsigned char hi = static_cast<unsigned char>(pattern_[pos_ + 1]);
        pos_ += 2;
        if (hi == '\\' && !at_end()) hi = static_cast<unsigned char>(pattern_[pos_++]);
        if (hi < c) throw ParseFailure(fmt::format("invalid range {}-{} in a bracket expression", char(c), char(hi)));
        for (int b = c; b <= hi; ++b) set.set(size_t(b));
      } else {
        set.set(c);
      }
    }
    ++pos_;  // ']'
    if (negated) set.flip();
    out_.classes_.push_back(set);
    Node n{Kind::Class};
    n.class_index = static_cast<int>(out_.classes_.size() - 1);
    return add(std::move(n));
  }

  using Op = ExtendedRegex::Op;
  int here() const { return static_cast<int>(out_.program_.size()); }
  int put(ExtendedRegex::Instruction in) {
    out_.program_.push_back(in);
    return here() - 1;
  }

  // Thompson's construction, one instruction list per node kind.
  void emit(int index) {
    const Node& n = nodes_[size_t(index)];
    auto& program = out_.program_;
    switch (n.kind) {
      case Kind::Empty:
        return;
      case Kind::Byte:
        put({Op::Byte, n.byte});
        return;
      case Kind::Any:
        put({Op::Any});
        return;
      case Kind::Class:
        put({Op::Class, 0, n.class_index});
        return;
      case Kind::LineBegin:
        put({Op::LineBegin});
        return;
      case Kind::LineEnd:
        put({Op::LineEnd});
        return;
      case Kind::Concat:
        for (int part : n.parts) emit(part);
        return;
      case Kind::Alternate: {
        // split L1, next; L1: part; jump end; next: split L2, ... ; last part; end:
        std::vector<int> jumps;
        for (size_t i = 0; i + 1 < n.parts.size(); ++i) {
          const int split = put({Op::Split});
          program[size_t(split)].x = here();
          emit(n.parts[i]);
          jumps.push_back(put({Op::Jump}));
          program[size_t(split)].y = here();
        }
        emit(n.parts.back());
        for (int j : jumps) program[size_t(j)].x = here();
        return;
      }
      case Kind::Star: {
        const int split = put({Op::Split});
        program[size_t(split)].x = here();
        emit(n.parts[0]);
        put({Op::Jump, 0, split});
        program[size_t(split)].y = here();
        return;
      }
      case Kind::Plus: {
        const int start = here();
        emit(n.parts[0]);
        const int split = put({Op::Split, 0, start});
        program[size_t(split)].y = here();
        return;
      }
      case Kind::Optional: {
        const int split = put({Op::Split});
        program[size_t(split)].x = here();
        emit(n.parts[0]);
        program[size_t(split)].y = here();
        return;
      }
    }
  }

  std::string_view pattern_;
  size_t pos_ = 0;
  std::vector<Node> nodes_;
  ExtendedRegex& out_;
};

std::optional<ExtendedRegex> ExtendedRegex::compile(std::string_view pattern, std::string& error) {
  if (pattern.size() > kMaxPatternBytes) {
    error = fmt::format("the pattern is longer than {} bytes", kMaxPatternBytes);
    return std::nullopt;
  }
  ExtendedRegex regex;
  try {
    RegexCompiler(pattern, regex).compile();
  } catch (const ParseFailure& f) {
    error = f.message;
    return std::nullopt;
  }
  return regex;
}

namespace {

// Adds the thread at `pc` to `list`, following jumps, splits and anchors at once (they consume
// no byte). `mark[pc] == pos` when pc is already in the list for this position, which also ends
// empty loops such as (a*)*.
void add_thread(const std::vector<ExtendedRegex::Instruction>& program, std::vector<int>& list, int pc, size_t pos,
                size_t size, std::vector<size_t>& mark, std::vector<int>& stack, bool& matched) {
  using Op = ExtendedRegex::Op;
  stack.clear();
  stack.push_back(pc);
  while (!stack.empty()) {
    const int at = stack.back();
    stack.pop_back();
    if (mark[size_t(at)] == pos) continue;
    mark[size_t(at)] = pos;
    const ExtendedRegex::Instruction& in = program[size_t(at)];
    switch (in.op) {
      case Op::Jump:
        stack.push_back(in.x);
        break;
      case Op::Split:
        stack.push_back(in.y);
        stack.push_back(in.x);
        break;
      case Op::LineBegin:
        if (pos == 0) stack.push_back(at + 1);
        break;
      case Op::LineEnd:
        if (pos == size) stack.push_back(at + 1);
        break;
      case Op::Match:
        matched = true;
        break;
      default:
        list.push_back(at);
        break;
    }
  }
}

}  // namespace

bool ExtendedRegex::search(std::string_view subject) const {
  std::vector<int> current, next, stack;
  std::vector<size_t> mark(program_.size(), std::numeric_limits<size_t>::max());
  bool matched = false;
  for (size_t pos = 0;; ++pos) {
    // Unanchored: a new thread starts at every position.
    add_thread(program_, current, 0, pos, subject.size(), mark, stack, matched);
    if (matched) return true;
    if (pos == subject.size()) return false;
    const unsigned char c = static_cast<unsigned char>(subject[pos]);
    next.clear();
    for (int pc : current) {
      const Instruction& in = program_[size_t(pc)];
      const bool step = (in.op == Op::Byte && in.byte == c) || in.op == Op::Any ||
                        (in.op == Op::Class && classes_[size_t(in.x)].test(c));
      if (step) add_thread(program_, next, pc + 1, pos + 1, subject.size(), mark, stack, matched);
      if (matched) return true;
    }
    std::swap(current, next);
  }
}

}  // namespace darc
