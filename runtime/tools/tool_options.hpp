// Options shared by the rbdc command-line tools: the robot file and how to load it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "rbdc/model.hpp"
#include "rbdc/urdf_loader.hpp"

namespace rbdc::tools {

/// Usage text for the loading options, to append to a tool's own --help.
extern const char* const kLoadOptionsHelp;

struct LoadOptions {
  std::string input;  ///< ROBOT.urdf, or a standalone topology .yaml/.yml
  UrdfOptions urdf;
  std::vector<ActuatorSpec> armature;  ///< --armature NAME=VALUE, added after loading
};

/// A tool-specific option handler: given argv and the index of the option, consumes it (advancing
/// the index past its arguments) and returns true, or returns false if it does not know it.
using ExtraOption = std::function<bool(int argc, char** argv, int& i)>;

/// Parses the loading options and the input; unknown options go to `extra`. Throws
/// std::invalid_argument with a message on bad usage. Returns false when --help was given.
bool parse_load_options(int argc, char** argv, LoadOptions& out, const ExtraOption& extra);

/// Loads the model (URDF or standalone topology) and prints warnings to stderr as "warning: …".
Model load_model(const LoadOptions& opts);

/// Runs `body`, turning errors into "error: <message>" on stderr and exit code 2.
int run_tool(const std::function<int()>& body);

}  // namespace rbdc::tools
