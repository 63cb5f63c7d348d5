// `rbdc-model --check` (`rbdc check`): a lint report of one robot file — every warning and the
// refusal, if any, with file:line, then the resulting topology (PRED, SUCC, λ, DoF, mass).
#pragma once

#include <ostream>

#include "tool_options.hpp"

namespace rbdc::tools {

/// Loads the robot as `opts` says and writes the report to `out`. Returns 0 when the robot loads
/// (warnings or not), 2 when it is refused.
int write_check_report(const LoadOptions& opts, std::ostream& out);

}  // namespace rbdc::tools
