// The predeclared RI parameter names: the standard primitive variables (RI spec §5 intro) and
// the parameters of the standard surface and light shaders (RI spec appendix A), and the
// lights' "shadowname", so that `"P" [...]` or `"intensity" [3000]` need no Declare.
#pragma once

#include <optional>
#include <string_view>

#include "parser/param_list.h"

namespace darc {

// The standard declaration of `name`, or nullopt if it is not a standard name.
std::optional<ParamDecl> standard_declaration(std::string_view name);

}  // namespace darc
