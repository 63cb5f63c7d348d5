// CSV time series of a run: t, x, y, z, roll, pitch, yaw, joint angles, joint velocities, then per
// foot its contact activation and world contact force. Used for both our simulator and MuJoCo.
#pragma once

#include <string>
#include <vector>

#include "rbdc/model.hpp"
#include "rbdc/result_file.hpp"
#include "rbdc/sim/contact.hpp"

namespace rbdc::sim {

class TrajectoryCsv {
 public:
  /// Starts `path` (a ResultFile: the previous file stays until finish()) with the header; throws
  /// std::runtime_error if it cannot be written.
  TrajectoryCsv(const std::string& path, const Model& model);
  /// One row: q, v in docs/conventions.md layout, contacts in foot order.
  void write(double t, const VectorX& q, const VectorX& v, const std::vector<FootContact>& contacts);
  /// Replaces `path` by what was written; a run that stops before leaves the previous file.
  void finish() { file_.commit(); }

 private:
  ResultFile file_;
  std::ostream& out_;
  int n_joints_;
};

}  // namespace rbdc::sim
