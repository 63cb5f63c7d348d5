// Body wrenches file (rbdc/body_wrenches_file.hpp); JSON read through yaml-cpp (JSON is YAML).
#include "rbdc/body_wrenches_file.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>

#include "rbdc/model_builder.hpp"

namespace rbdc {

std::vector<Vector6> read_body_wrenches(const std::string& path, const Model& model) {
  const auto fail = [&](const YAML::Node& at, const std::string& problem) {
    const int line = at.Mark().line;
    throw ModelError(path + (line >= 0 ? ":" + std::to_string(line + 1) : "") + ": " + problem);
  };
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw ModelError(path + ": cannot open file");
  } catch (const YAML::ParserException& e) {
    throw ModelError(path + ":" + std::to_string(e.mark.line + 1) + ": malformed JSON: " + e.msg);
  }
  if (!root.IsMap()) throw ModelError(path + ": expected an object {\"body\": [nx, ny, nz, fx, fy, fz]}");
  std::vector<Vector6> wrenches(static_cast<size_t>(model.nb), Vector6::Zero());
  std::vector<bool> given(static_cast<size_t>(model.nb), false);
  for (const auto& entry : root) {
    // a key that is not a name (a list or a mapping, as YAML allows: found by fuzz_body_wrenches)
    if (!entry.first.IsScalar()) fail(entry.first, "expected a body name as the key");
    const std::string name = entry.first.as<std::string>();
    int body = -1;
    for (int i = 0; i < model.nb; ++i) {
      if (model.bodies[static_cast<size_t>(i)].name == name) body = i;
    }
    if (body < 0) fail(entry.first, "no body named '" + name + "'");
    if (given[static_cast<size_t>(body)]) fail(entry.first, "body '" + name + "' is given twice");
    given[static_cast<size_t>(body)] = true;
    const YAML::Node& w = entry.second;
    if (!w.IsSequence() || w.size() != 6) fail(w, "body '" + name + "': expected 6 numbers (moment; force)");
    for (size_t k = 0; k < 6; ++k) {
      double x = 0;
      try {
        x = w[k].as<double>();
      } catch (const YAML::Exception&) {
        fail(w[k], "body '" + name + "': '" + w[k].Scalar() + "' is not a number");
      }
      if (!std::isfinite(x)) fail(w[k], "body '" + name + "': NaN or Inf");
      wrenches[static_cast<size_t>(body)][static_cast<Eigen::Index>(k)] = x;
    }
  }
  return wrenches;
}

}  // namespace rbdc
