#include "tool_options.hpp"

#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "rbdc/topology_file.hpp"

namespace rbdc::tools {

const char* const kLoadOptionsHelp =
    "  ROBOT               a URDF file, or a standalone topology file (.yaml/.yml)\n"
    "  --topology FILE     topology overlay fixing the numbering and feet (URDF input)\n"
    "  --floating-base     root link on a 6-DoF floating joint (default)\n"
    "  --fixed-base        root link welded to the world\n"
    "  --root LINK         use LINK as the root link (links above it must be massless)\n"
    "  --lock-mimic        lock each mimic joint at its offset (default: couple it to its leader)\n"
    "  --independent-mimic load mimic joints as independent joints (ignore <mimic>)\n"
    "  --lock NAME=VALUE   lock joint NAME at VALUE (rad or m); repeatable\n"
    "  --armature NAME=VALUE  reflected rotor inertia of joint NAME (kg·m² or kg), added to M's\n"
    "                      diagonal only; repeatable (docs/model.md, \"Actuators\")\n"
    "  -h, --help          show this help\n";

namespace {

std::string next_argument(int argc, char** argv, int& i) {
  if (i + 1 >= argc) throw std::invalid_argument(std::string(argv[i]) + " needs an argument");
  return argv[++i];
}

double parse_number(const std::string& text, const std::string& what) {
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0') throw std::invalid_argument(what + ": '" + text + "' is not a number");
  return x;
}

}  // namespace

bool parse_load_options(int argc, char** argv, LoadOptions& out, const ExtraOption& extra) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") return false;
    if (arg == "--topology") {
      out.urdf.topology_file = next_argument(argc, argv, i);
    } else if (arg == "--fixed-base") {
      out.urdf.floating_base = false;
    } else if (arg == "--floating-base") {
      out.urdf.floating_base = true;
    } else if (arg == "--root") {
      out.urdf.root_link = next_argument(argc, argv, i);
    } else if (arg == "--lock-mimic") {
      out.urdf.mimic = MimicMode::Lock;
    } else if (arg == "--independent-mimic") {
      out.urdf.mimic = MimicMode::Independent;
    } else if (arg == "--lock") {
      const std::string spec = next_argument(argc, argv, i);
      const size_t eq = spec.find('=');
      if (eq == std::string::npos || eq == 0) {
        throw std::invalid_argument("--lock expects NAME=VALUE, got '" + spec + "'");
      }
      out.urdf.locked_joints[spec.substr(0, eq)] = parse_number(spec.substr(eq + 1), "--lock " + spec);
    } else if (arg == "--armature") {
      const std::string spec = next_argument(argc, argv, i);
      const size_t eq = spec.find('=');
      if (eq == std::string::npos || eq == 0) {
        throw std::invalid_argument("--armature expects NAME=VALUE, got '" + spec + "'");
      }
      ActuatorSpec a;
      a.joint = spec.substr(0, eq);
      a.where = "--armature " + spec;
      a.armature = parse_number(spec.substr(eq + 1), "--armature " + spec);
      out.armature.push_back(a);
    } else if (extra && extra(argc, argv, i)) {
      continue;
    } else if (arg.size() > 1 && arg[0] == '-') {
      throw std::invalid_argument("unknown option '" + arg + "' (see --help)");
    } else if (out.input.empty()) {
      out.input = arg;
    } else {
      throw std::invalid_argument("more than one robot file: '" + out.input + "' and '" + arg + "'");
    }
  }
  if (out.input.empty()) throw std::invalid_argument("no robot file given (see --help)");
  return true;
}

Model load_model(const LoadOptions& opts) {
  std::vector<std::string> warnings;
  const bool standalone = is_topology_path(opts.input);
  if (standalone && !opts.urdf.topology_file.empty()) {
    throw std::invalid_argument("--topology applies to URDF input, not to a topology file");
  }
  Model model = standalone ? load_topology(opts.input, &warnings)
                           : load_urdf(opts.input, opts.urdf, &warnings);
  for (const std::string& w : warnings) {
    // an --armature that regularises a singular M (docs/model.md) makes its warning moot
    const bool moot = !opts.armature.empty() && w.find(": the mass matrix is singular: ") != std::string::npos;
    if (!moot) std::cerr << "warning: " << w << "\n";
  }
  add_actuators(model, opts.armature);
  if (!opts.armature.empty() && !model.singular_mass_matrix.empty()) {
    std::cerr << "warning: " << opts.input << ": " << model.singular_mass_matrix << "\n";
  }
  return model;
}

int run_tool(const std::function<int()>& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    std::istringstream lines(e.what());  // a refusal may list several bad elements, one per line
    for (std::string line; std::getline(lines, line);) std::cerr << "error: " << line << "\n";
    return 2;
  }
}

}  // namespace rbdc::tools
