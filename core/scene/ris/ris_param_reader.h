// Reads the parameters of a RenderMan 21+ request (Bxdf, Light) with RenderMan's defaults,
// keeping track of which ones were read so that the rest can be reported as dropped, and
// resolving "reference" parameters through the Pattern table.
#pragma once

#include <fmt/format.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/scene/ris/ris_patterns.h"
#include "core/math/vec.h"
#include "parser/param_list.h"

namespace darc {

class RisParamReader {
 public:
  RisParamReader(const ParamList& params, const RisPatterns* patterns) : params_(params), patterns_(patterns) {}

  bool has(const std::string& name) const { return params_.find(name) != nullptr; }

  float number(const std::string& name, float fallback) {
    const Param* p = take(name);
    if (!p) return fallback;
    if (p->decl.reference) {
      unevaluated_.push_back(fmt::format("\"{}\" (a pattern output: darc has no pattern network)", name));
      return fallback;
    }
    return !p->decl.is_string() && !p->floats.empty() ? p->floats[0] : fallback;
  }

  Vec3f color(const std::string& name, Vec3f fallback) {
    const Param* p = take(name);
    if (!p) return fallback;
    if (p->decl.reference) return referenced_color(*p, fallback);
    return !p->decl.is_string() && p->floats.size() >= 3 ? Vec3f{p->floats[0], p->floats[1], p->floats[2]} : fallback;
  }

  // The string `name` holds, or empty when it is absent or not a string.
  std::string text(const std::string& name) {
    const Param* p = take(name);
    return p && p->decl.is_string() && !p->decl.reference && !p->strings.empty() ? p->strings[0] : std::string();
  }

  // The PxrTexture that colour parameter `name` is connected to, if it is (the parameter is then
  // read); nullopt otherwise, leaving it to color().
  std::optional<RisTexture> texture(const std::string& name) {
    const Param* p = params_.find(name);
    if (!p || !p->decl.reference || p->strings.empty() || !patterns_) return std::nullopt;
    const auto it = patterns_->find(pattern_handle(p->strings[0]));
    if (it == patterns_->end()) return std::nullopt;
    auto t = texture_pattern(it->second, *patterns_);
    if (t) take(name);
    return t;
  }

  // The colour of `name`, or nullopt when it is absent or its pattern is not evaluated.
  std::optional<Vec3f> optional_color(const std::string& name) {
    if (!has(name)) return std::nullopt;
    const size_t before = unevaluated_.size();
    const Vec3f c = color(name, {});
    if (unevaluated_.size() != before) return std::nullopt;
    return c;
  }

  // The colour of the first parameter connected to a pattern darc evaluates, if any (a hair
  // Bxdf whose colour comes only through its specular inputs). Does not mark it used.
  std::optional<Vec3f> any_pattern_color() const {
    if (!patterns_) return std::nullopt;
    for (const Param& p : params_.params) {
      if (!p.decl.reference || p.decl.type != ParamType::Color || p.strings.empty()) continue;
      const auto it = patterns_->find(pattern_handle(p.strings[0]));
      if (it == patterns_->end()) continue;
      if (auto c = constant_pattern_color(it->second)) return c;
    }
    return std::nullopt;
  }

  // The given parameters that were not read, in the request's order.
  std::vector<std::string> unread() const {
    std::vector<std::string> out;
    for (const Param& p : params_.params)
      if (!read_.count(p.name)) out.push_back(p.name);
    return out;
  }
  const std::vector<std::string>& unevaluated() const { return unevaluated_; }

 private:
  const Param* take(const std::string& name) {
    const Param* p = params_.find(name);
    if (p) read_.insert(name);
    return p;
  }

  Vec3f referenced_color(const Param& p, Vec3f fallback) {
    const std::string reference = p.strings.empty() ? std::string() : p.strings[0];
    const std::string handle = pattern_handle(reference);
    const auto it = patterns_ ? patterns_->find(handle) : RisPatterns::const_iterator{};
    if (!patterns_ || it == patterns_->end()) {
      unevaluated_.push_back(fmt::format("\"{}\" (no Pattern \"{}\")", p.name, handle));
      return fallback;
    }
    if (auto c = constant_pattern_color(it->second)) return *c;
    unevaluated_.push_back(
        fmt::format("\"{}\" (Pattern \"{}\" is a {}, which darc does not evaluate)", p.name, handle, it->second.name));
    return fallback;
  }

  const ParamList& params_;
  const RisPatterns* patterns_;
  std::set<std::string> read_;
  std::vector<std::string> unevaluated_;
};

}  // namespace darc
