// rbdc-info: human-readable summary of a robot model (topology arrays of paper 000 Eqs. 1-3, κ, μ,
// ν, feet φ). Each section is one function taking the model (and the state), so further sections
// are added by writing a function and calling it from main.
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "print_dynamics.hpp"
#include "tool_options.hpp"

namespace {

using rbdc::Model;

std::string list(const std::vector<int>& v, size_t from = 0) {
  std::ostringstream s;
  s << "{";
  for (size_t k = from; k < v.size(); ++k) s << (k == from ? "" : ", ") << v[k];
  s << "}";
  return s.str();
}

const char* type_name(rbdc::JointType t) {
  switch (t) {
    case rbdc::JointType::Floating: return "floating";
    case rbdc::JointType::Fixed: return "fixed";
    case rbdc::JointType::Revolute: return "revolute";
    case rbdc::JointType::Prismatic: return "prismatic";
  }
  return "?";
}

void print_summary(const Model& m, std::ostream& out) {
  double mass = 0, rotor_mass = 0;
  for (const rbdc::Body& b : m.bodies) mass += b.mass;
  for (const rbdc::Joint& j : m.joints) rotor_mass += j.rotor.mass;
  out << "robot " << m.name << ": nb = " << m.nb << ", nq = " << m.nq << ", nv = " << m.nv << ", "
      << (m.floating_base ? "floating base" : "fixed base") << ", total mass " << mass + rotor_mass << " kg";
  if (m.has_rotors) out << " (links " << mass << " kg, rotors " << rotor_mass << " kg)";
  out << "\n";
  for (const rbdc::Joint& j : m.joints) {  // docs/model.md, "Actuators"
    if (j.rotor.gear_ratio > 0) {
      const rbdc::Rotor& r = j.rotor;
      out << "rotor: joint " << j.name << ", gear ratio " << r.gear_ratio << ", mass " << r.mass
          << " kg, spin inertia " << r.axis.dot(r.inertia * r.axis) << " kg·m², reflected "
          << r.gear_ratio * r.gear_ratio * r.axis.dot(r.inertia * r.axis) << " kg·m², at ("
          << r.translation.transpose() << ") on its parent\n";
    }
    if (j.armature > 0) out << "armature: joint " << j.name << " " << j.armature << "\n";
  }
  for (const rbdc::Coupling& c : m.couplings) {  // the sections below are in tree coordinates
    out << "coupling: joint " << c.follower << " = " << c.multiplier << " * joint " << c.leader << " + "
        << c.offset << " (docs/model.md, \"Mimic joints\")\n";
  }
}

void print_bodies(const Model& m, std::ostream& out) {
  out << "bodies (i, name, λ(i), joint, type, axis, mass, com):\n";
  for (int i = 0; i < m.nb; ++i) {
    const rbdc::Body& b = m.bodies[static_cast<size_t>(i)];
    const rbdc::Joint& j = m.joints[static_cast<size_t>(i)];
    out << "  " << std::setw(2) << i << "  " << std::left << std::setw(18) << b.name << std::right
        << std::setw(3) << m.parent[static_cast<size_t>(i)] << "  " << std::left << std::setw(20)
        << j.name << std::setw(10) << type_name(j.type) << std::right << " ("
        << j.axis.transpose() << ")  " << b.mass << "  (" << b.com.transpose() << ")\n";
  }
}

void print_topology(const Model& m, std::ostream& out) {
  out << "PRED   = " << list(m.pred, 1) << "\n"
      << "SUCC   = " << list(m.succ, 1) << "\n"
      << "lambda = " << list(m.parent, 1) << "\n";
  const auto sets = [&](const char* name, const std::vector<std::vector<int>>& s) {
    for (int i = 0; i < m.nb; ++i) out << name << "(" << i << ") = " << list(s[static_cast<size_t>(i)]) << "\n";
  };
  sets("kappa", m.support);
  sets("mu", m.children);
  sets("nu", m.subtree);
}

void print_feet(const Model& m, std::ostream& out) {
  out << "feet (k, name, phi(k), offset):\n";
  for (size_t k = 0; k < m.feet.size(); ++k) {
    const rbdc::Foot& f = m.feet[k];
    out << "  " << k << "  " << f.name << "  " << f.body << " ("
        << m.bodies[static_cast<size_t>(f.body)].name << ")  (" << f.offset.transpose() << ")\n";
  }
}

void print_state(const rbdc::VectorX& q, std::ostream& out) {
  out << "q = (" << q.transpose() << ")\n";
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rbdc::tools;
  return run_tool([&] {
    LoadOptions opts;
    std::vector<double> q_values;
    const ExtraOption q_option = [&](int n, char** args, int& i) {
      if (std::string(args[i]) != "--q") return false;
      for (char* end = nullptr; i + 1 < n; ++i) {  // numbers up to the next non-number
        const double x = std::strtod(args[i + 1], &end);
        if (end == args[i + 1] || *end != '\0') break;
        q_values.push_back(x);
      }
      return true;
    };
    if (!parse_load_options(argc, argv, opts, q_option)) {
      std::cout << "usage: rbdc-info ROBOT [options] [--q Q0 Q1 …]\n"
                   "Prints a summary of the robot model: sizes, mass, topology arrays, κ, μ, ν, feet.\n\n"
                << kLoadOptionsHelp << "  --q Q0 Q1 …         configuration (nq numbers; default: the documented\n"
                   "                      standing state of docs/runtime.md)\n";
      return 0;
    }
    const Model model = load_model(opts);
    rbdc::VectorX q = documented_configuration(model);
    if (!q_values.empty()) {
      if (static_cast<int>(q_values.size()) != model.nq) {
        throw std::invalid_argument("--q has " + std::to_string(q_values.size()) + " numbers, the model needs nq = " +
                                    std::to_string(model.nq));
      }
      q = Eigen::Map<const rbdc::VectorX>(q_values.data(), model.nq);
    }
    std::ostream& out = std::cout;
    print_summary(model, out);
    print_bodies(model, out);
    print_topology(model, out);
    print_feet(model, out);
    print_state(q, out);
    print_dynamics(model, q, documented_velocity(model), out);
    return 0;
  });
}
