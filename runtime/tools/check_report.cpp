#include "check_report.hpp"

#include <sstream>
#include <string>
#include <vector>

#include "rbdc/coupling.hpp"
#include "rbdc/topology_file.hpp"

namespace rbdc::tools {
namespace {

std::string list(const std::vector<int>& v) {
  std::ostringstream s;
  s << "{";
  for (size_t k = 1; k < v.size(); ++k) s << (k == 1 ? "" : ", ") << v[k];  // joints 1 … nb-1
  return s.str() + "}";
}

void write_topology(const Model& m, std::ostream& out) {
  double mass = 0;
  for (const Body& b : m.bodies) mass += b.mass;
  const CoupledCoordinates c = coupled_coordinates(m);
  out << "robot '" << m.name << "': " << (m.floating_base ? "floating" : "fixed") << " base, " << m.nb
      << " bodies, " << c.num_joints() << " joint DoF (" << m.num_joints() << " joints, "
      << m.couplings.size() << " coupled), nq = " << c.nq << ", nv = " << c.nv << ", mass " << mass
      << " kg\n";
  out << "PRED   = " << list(m.pred) << "\nSUCC   = " << list(m.succ) << "\nlambda = " << list(m.parent)
      << "\n";
  for (const Coupling& k : m.couplings) {
    out << "coupling: joint '" << m.joints[static_cast<size_t>(k.follower)].name << "' (" << k.follower
        << ") = " << k.multiplier << " * joint '" << m.joints[static_cast<size_t>(k.leader)].name << "' ("
        << k.leader << ") + " << k.offset << "\n";
  }
  for (size_t k = 0; k < m.feet.size(); ++k) {
    out << "foot " << k << ": '" << m.feet[k].name << "' on body " << m.feet[k].body << "\n";
  }
}

}  // namespace

int write_check_report(const LoadOptions& opts, std::ostream& out) {
  std::vector<std::string> warnings;
  std::string error;
  Model model;
  try {
    if (is_topology_path(opts.input)) {
      if (!opts.urdf.topology_file.empty()) {
        throw ModelError("--topology applies to URDF input, not to a topology file");
      }
      model = load_topology(opts.input, &warnings);
    } else {
      model = load_urdf(opts.input, opts.urdf, &warnings);
    }
  } catch (const ModelError& e) {
    error = e.what();
  }
  for (const std::string& w : warnings) out << "warning: " << w << "\n";
  size_t errors = 0;  // a refusal may list several bad links, one per line
  std::istringstream lines(error);
  for (std::string line; std::getline(lines, line); ++errors) out << "error: " << line << "\n";
  out << opts.input << ": " << warnings.size() << " warning" << (warnings.size() == 1 ? "" : "s") << ", "
      << errors << " error" << (errors == 1 ? "" : "s")
      << (errors > 0 ? " (loading stops at the first refused element; bad links are all listed)" : "")
      << "\n";
  if (!error.empty()) return 2;
  write_topology(model, out);
  return 0;
}

}  // namespace rbdc::tools
