// The numbers of requests darc accepts without effect (Shutter, ShadingRate, Bound, ...): other
// renderers use them, so a value the RI Spec 3.2 rules out still means a broken file, but nothing
// in darc's image depends on it. Such a value (or a wrong count of numbers) gets a warning, never
// an error (docs/parameters.md).
#pragma once

#include <string>
#include <vector>

#include "parser/diagnostics.h"

namespace darc {

// Warns at `loc` about each number of `request` outside its RI range.
void check_unused_request_values(const std::string& request, const std::vector<double>& numbers, Diagnostics& diag,
                                 const SourceLoc& loc);

}  // namespace darc
