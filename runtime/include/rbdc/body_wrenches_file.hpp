// External wrenches per body from a JSON (or YAML) file, for rbdc-eval --body-wrenches:
//   {"trunk": [nx, ny, nz, fx, fy, fz], "LF_knee": [...], ...}
// Each is (moment; force) applied to the body, taken at the body origin and in body coordinates, as
// external_wrench_terms takes them (rbdc/bias_terms.hpp); bodies not named get none.
#pragma once

#include <string>
#include <vector>

#include "rbdc/model.hpp"

namespace rbdc {

/// nb wrenches, body order. Throws ModelError naming the file (and line) for a missing file,
/// malformed JSON, an unknown body, a body given twice, a list that is not 6 numbers, NaN or Inf.
std::vector<Vector6> read_body_wrenches(const std::string& path, const Model& model);

}  // namespace rbdc
