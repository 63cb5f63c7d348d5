// rbdc's runtime against Pinocchio 3 on URDF files (issue 23: every robot Pinocchio loads is accepted and
// its M, c, g, τ agree to 1e-12). Not part of the build: it needs a Pinocchio source snapshot kept outside
// the repository; bench/peer/runtime_vs_pinocchio.sh compiles and runs it (results/bench/peer_runtime.md).
//
// Each file is loaded by both, floating and fixed base, mimic joints independent (Pinocchio's default).
// Random states are mapped to Pinocchio's conventions (docs/conventions.md): q = (p, xyzw, joints) from
// (p, wxyz, joints); v-indexed rows and columns permuted (its free flyer is (v, ω), its joints matched
// by name, a continuous joint as (cos, sin)); its spatial base acceleration a_P = a − (0, ω × v).
// Printed per quantity: max over the states of max|rbdc − pin| / max(1, max|pin|).
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/joint-configuration.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/multibody/data.hpp>
#include <pinocchio/multibody/model.hpp>
#include <pinocchio/parsers/urdf.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "rbdc/bias_terms.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/forward_dynamics.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "rbdc/urdf_loader.hpp"

namespace {

using rbdc::MatrixX;
using rbdc::VectorX;

constexpr int kStates = 1000;

/// Where rbdc's coordinates sit in Pinocchio's: for each rbdc joint ≥ 1, its Pinocchio q index, q
/// size (2 for a continuous joint: cos, sin) and v index; `v_of` maps every rbdc v index.
struct IndexMap {
  std::vector<int> q_at, q_size, v_of;
};

IndexMap map_indices(const rbdc::Model& m, const pinocchio::Model& pin) {
  IndexMap map;
  map.v_of.assign(m.nv, -1);
  if (m.floating_base) {
    for (int k = 0; k < 3; ++k) map.v_of[k] = 3 + k, map.v_of[3 + k] = k;  // (ω, v) → (v, ω)
  }
  map.q_at.assign(m.joints.size(), -1);
  map.q_size.assign(m.joints.size(), 0);
  for (std::size_t i = 1; i < m.joints.size(); ++i) {
    const rbdc::Joint& j = m.joints[i];
    if (!pin.existJointName(j.name)) throw std::runtime_error("Pinocchio has no joint " + j.name);
    const auto id = pin.getJointId(j.name);
    map.q_at[i] = pin.joints[id].idx_q();
    map.q_size[i] = pin.joints[id].nq();
    map.v_of[j.v_index] = pin.joints[id].idx_v();
  }
  return map;
}

VectorX to_pin_v(const IndexMap& map, const VectorX& x) {
  VectorX y(x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) y[map.v_of[k]] = x[k];
  return y;
}

VectorX from_pin_v(const IndexMap& map, const VectorX& y) {
  VectorX x(y.size());
  for (Eigen::Index k = 0; k < y.size(); ++k) x[k] = y[map.v_of[k]];
  return x;
}

MatrixX from_pin_m(const IndexMap& map, const MatrixX& Y) {
  MatrixX X(Y.rows(), Y.cols());
  for (Eigen::Index r = 0; r < Y.rows(); ++r) {
    for (Eigen::Index c = 0; c < Y.cols(); ++c) X(r, c) = Y(map.v_of[r], map.v_of[c]);
  }
  return X;
}

VectorX to_pin_q(const rbdc::Model& m, const IndexMap& map, const VectorX& q, int pin_nq) {
  VectorX y = VectorX::Zero(pin_nq);
  if (m.floating_base) {
    y.head<3>() = q.head<3>();
    y.segment<3>(3) = q.segment<3>(4);  // x, y, z
    y[6] = q[3];                        // w
  }
  for (std::size_t i = 1; i < m.joints.size(); ++i) {
    const double qi = q[m.joints[i].q_index];
    if (map.q_size[i] == 2) {
      y[map.q_at[i]] = std::cos(qi), y[map.q_at[i] + 1] = std::sin(qi);
    } else {
      y[map.q_at[i]] = qi;
    }
  }
  return y;
}

/// max|x − reference| / max(1, max|reference|)
double difference(const MatrixX& x, const MatrixX& reference) {
  return (x - reference).cwiseAbs().maxCoeff() / std::max(1.0, reference.cwiseAbs().maxCoeff());
}

/// The file's text with `<limit effort="1" velocity="1"/>` added to every revolute or prismatic joint
/// without a limit: urdfdom (so Pinocchio) refuses such a joint, rbdc loads it unlimited with a
/// warning. Limits play no part in M, c, g, τ.
std::string with_limits(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str(), out;
  const std::regex joint(R"(<joint\b[^>]*type\s*=\s*["'](revolute|prismatic)["'][^>]*>)");
  std::size_t done = 0;
  for (std::sregex_iterator it(text.begin(), text.end(), joint), end; it != end; ++it) {
    const std::size_t open_end = static_cast<std::size_t>(it->position() + it->length());
    const std::size_t close = text.find("</joint>", open_end);
    out += text.substr(done, open_end - done);
    if (text.substr(open_end, close - open_end).find("<limit") == std::string::npos) {
      out += "<limit effort=\"1\" velocity=\"1\"/>";
    }
    done = open_end;
  }
  return out + text.substr(done);
}

/// Pinocchio's model of the file; `note` says when the file had to be given limits first.
pinocchio::Model pinocchio_model(const std::string& path, bool floating, std::string* note) {
  pinocchio::Model pin;
  try {
    if (floating) pinocchio::urdf::buildModel(path, pinocchio::JointModelFreeFlyer(), pin);
    else pinocchio::urdf::buildModel(path, pin);
    return pin;
  } catch (const std::invalid_argument&) {
    *note = "Pinocchio refuses the file (a joint without <limit>): loaded with limits added";
  }
  pin = pinocchio::Model();
  const std::string xml = with_limits(path);
  if (floating) pinocchio::urdf::buildModelFromXML(xml, pinocchio::JointModelFreeFlyer(), pin);
  else pinocchio::urdf::buildModelFromXML(xml, pin);
  return pin;
}

struct Worst {
  double M = 0, c = 0, g = 0, tau = 0, a = 0;
  std::string pinocchio_input = "the file";
};

Worst compare(const std::string& path, bool floating) {
  rbdc::UrdfOptions options;
  options.floating_base = floating;
  options.mimic = rbdc::MimicMode::Independent;
  std::vector<std::string> warnings;
  const rbdc::Model m = rbdc::load_urdf(path, options, &warnings);
  std::string note;
  const pinocchio::Model pin = pinocchio_model(path, floating, &note);
  if (pin.nv != m.nv) throw std::runtime_error("nv differs: Pinocchio " + std::to_string(pin.nv));
  std::printf("%s, %s base: nv %d, %zu rbdc warnings%s%s\n", path.c_str(), floating ? "floating" : "fixed", m.nv,
              warnings.size(), note.empty() ? "" : "; ", note.c_str());
  const IndexMap map = map_indices(m, pin);
  rbdc::Data data(m);
  pinocchio::Data pd(pin);
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::normal_distribution<double> normal;
  const rbdc::Matrix3X no_forces = rbdc::Matrix3X::Zero(3, static_cast<Eigen::Index>(m.feet.size()));
  Worst worst;
  if (!note.empty()) worst.pinocchio_input = "limits added";
  for (int s = 0; s < kStates; ++s) {
    VectorX q = VectorX::NullaryExpr(m.nq, [&] { return uniform(rng); });
    if (floating) q.segment<4>(3) = Eigen::Vector4d(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
    const VectorX v = VectorX::NullaryExpr(m.nv, [&] { return uniform(rng); });
    const VectorX a = VectorX::NullaryExpr(m.nv, [&] { return uniform(rng); });
    const VectorX tau = VectorX::NullaryExpr(m.num_joints(), [&] { return uniform(rng); });
    // rbdc's trunk acceleration is classical, Pinocchio's spatial: a_P = a − (0, ω × v).
    VectorX drift = VectorX::Zero(m.nv);
    if (floating) drift.segment<3>(3) = v.head<3>().cross(v.segment<3>(3));
    const VectorX qp = to_pin_q(m, map, q, pin.nq), vp = to_pin_v(map, v);

    MatrixX Mp = pinocchio::crba(pin, pd, qp);
    Mp.triangularView<Eigen::StrictlyLower>() = Mp.transpose();
    worst.M = std::max(worst.M, difference(rbdc::mass_matrix(m, data, q), from_pin_m(map, Mp)));
    const VectorX gp = from_pin_v(map, pinocchio::computeGeneralizedGravity(pin, pd, qp));
    worst.g = std::max(worst.g, difference(rbdc::gravity_terms(m, data, q), gp));
    const VectorX cgp = from_pin_v(map, pinocchio::rnea(pin, pd, qp, vp, to_pin_v(map, -drift)));
    worst.c = std::max(worst.c, difference(rbdc::quadratic_velocity_terms(m, data, q, v), cgp - gp));
    const VectorX taup = from_pin_v(map, pinocchio::rnea(pin, pd, qp, vp, to_pin_v(map, a - drift)));
    worst.tau = std::max(worst.tau, difference(rbdc::inverse_dynamics(m, data, q, v, a), taup));
    VectorX applied = VectorX::Zero(m.nv);
    applied.tail(m.num_joints()) = tau;
    const VectorX ap = from_pin_v(map, pinocchio::aba(pin, pd, qp, vp, to_pin_v(map, applied))) + drift;
    worst.a = std::max(worst.a, difference(rbdc::forward_dynamics(m, data, q, v, tau, no_forces), ap));
  }
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: runtime_vs_pinocchio FILE.urdf...\n";
    return 2;
  }
  std::vector<std::string> rows;
  double overall = 0;
  for (int k = 1; k < argc; ++k) {
    for (const bool floating : {true, false}) {
      const Worst w = compare(argv[k], floating);
      char row[512];
      std::snprintf(row, sizeof row, "| %s | %s | %s | %.1e | %.1e | %.1e | %.1e | %.1e |", argv[k],
                    floating ? "floating" : "fixed", w.pinocchio_input.c_str(), w.M, w.c, w.g, w.tau, w.a);
      rows.emplace_back(row);
      overall = std::max({overall, w.M, w.c, w.g, w.tau, w.a});
    }
  }
  std::printf("\n%d random states per row; max|rbdc − pin| / max(1, max|pin|)\n\n", kStates);
  std::printf("| robot | base | Pinocchio reads | M | c | g | τ = ID | a = FD |\n|---|---|---|---|---|---|---|---|\n");
  for (const std::string& row : rows) std::printf("%s\n", row.c_str());
  std::printf("\nworst %.1e\n", overall);
  return overall <= 1e-12 ? 0 : 1;
}
