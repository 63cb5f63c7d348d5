// rbdc's coordinates mapped to Pinocchio 3's (docs/conventions.md), shared by the peer programs
// runtime_vs_pinocchio.cpp and generated_vs_pinocchio (pinocchio_side.cpp). Not part of the build:
// it needs a Pinocchio source snapshot kept outside the repository (bench/peer/README.md).
//
// Pinocchio's q = (p, xyzw, joints) where rbdc's is (p, wxyz, joints); its free flyer's v is (v, ω)
// where rbdc's is (ω, v); its joints are matched by name, a continuous joint stored as (cos, sin);
// its base acceleration is the spatial one, a_P = a − (0, ω × v) (see `drift`).
#pragma once

#include <pinocchio/multibody/model.hpp>
#include <pinocchio/parsers/urdf.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "rbdc/model.hpp"

namespace peer {

using rbdc::MatrixX;
using rbdc::VectorX;

/// Where rbdc's coordinates sit in Pinocchio's: for each rbdc joint ≥ 1, its Pinocchio q index, q
/// size (2 for a continuous joint: cos, sin) and v index; `v_of` maps every rbdc v index.
struct IndexMap {
  std::vector<int> q_at, q_size, v_of;
};

inline IndexMap map_indices(const rbdc::Model& m, const pinocchio::Model& pin) {
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

/// A v-indexed vector (v, a, τ) in Pinocchio's order.
inline VectorX to_pin_v(const IndexMap& map, const VectorX& x) {
  VectorX y(x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) y[map.v_of[k]] = x[k];
  return y;
}

inline VectorX from_pin_v(const IndexMap& map, const VectorX& y) {
  VectorX x(y.size());
  for (Eigen::Index k = 0; k < y.size(); ++k) x[k] = y[map.v_of[k]];
  return x;
}

/// An nv × nv matrix, rows and columns both v-indexed (M, ∂/∂q and ∂/∂v on the tangent), in rbdc's order.
inline MatrixX from_pin_m(const IndexMap& map, const MatrixX& Y) {
  MatrixX X(Y.rows(), Y.cols());
  for (Eigen::Index r = 0; r < Y.rows(); ++r) {
    for (Eigen::Index c = 0; c < Y.cols(); ++c) X(r, c) = Y(map.v_of[r], map.v_of[c]);
  }
  return X;
}

inline VectorX to_pin_q(const rbdc::Model& m, const IndexMap& map, const VectorX& q, int pin_nq) {
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

/// (0, ω × v_B, 0) in rbdc's order: rbdc's trunk acceleration is the classical one, Pinocchio's the
/// spatial one, so a_P = a − drift and τ_rbdc(q, v, a) = τ_P(q, v, a − drift). Zero for a fixed base.
inline VectorX drift(const rbdc::Model& m, const VectorX& v) {
  VectorX d = VectorX::Zero(m.nv);
  if (m.floating_base) d.segment<3>(3) = v.head<3>().cross(v.segment<3>(3));
  return d;
}

/// max|x − reference| / max(1, max|reference|)
inline double difference(const MatrixX& x, const MatrixX& reference) {
  return (x - reference).cwiseAbs().maxCoeff() / std::max(1.0, reference.cwiseAbs().maxCoeff());
}

/// The file's text with `<limit effort="1" velocity="1"/>` added to every revolute or prismatic joint
/// without a limit: urdfdom (so Pinocchio) refuses such a joint, rbdc loads it unlimited with a
/// warning. Limits play no part in the dynamics compared.
inline std::string with_limits(const std::string& path) {
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
inline pinocchio::Model pinocchio_model(const std::string& path, bool floating, std::string* note) {
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

}  // namespace peer
