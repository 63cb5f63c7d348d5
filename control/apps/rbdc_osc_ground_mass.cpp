// rbdc-osc-ground-mass [--configurations N]: paper 001 Fig. 7 and the study beside it, on the Mini
// Cheetah with the trot pair LF + RH pinned (the other two legs in swing), as the paper does.
//  - mid_stance: the relative errors of the closed-chain recursion's Λ̃_t, J̃_tᵀ and b̃_t (Table 2,
//    big-ground-inertia approximation) against the exact constrained closed form (Eqs. 16-26), for
//    ground masses 1e-4 … 1e8 × the total mass, at one mid-stance configuration of a trot;
//  - study: for N random configurations within a trot's joint ranges (default 500, the paper's
//    count), the ground masses of minimum Λ̃ and b̃ error relative to Eq. 58's m_min/√ε.
// Both on the runtime in double (the closed form's own error, ~1e-15, is far below the minima).
// Velocities keep the pinned feet at rest (J_c v = 0), which the recursion assumes. Prints one JSON
// object; results/scripts/plot_osc_ground_mass.py draws it.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <random>
#include <string>
#include <vector>

#include "rbdc/jacobian.hpp"
#include "rbdc/osc.hpp"
#include "rbdc/sim/robot.hpp"

using namespace rbdc;

namespace {

const std::vector<int> kTrotPair = {0, 3};  // LF, RH (model.feet order LF, RF, LH, RH)

struct Errors {
  double Lambda, JbarT, b;
};

// Solves the stance legs' joint rates so that the pinned feet do not move: J_c v = 0.
void pin_feet(const Model& model, Data& data, const VectorX& q, VectorX& v) {
  const MatrixX& J = feet_jacobian(model, data, q);
  std::vector<int> stance;  // v indices of the joints carrying the pinned feet
  MatrixX J_c(3 * kTrotPair.size(), model.nv);
  for (size_t i = 0; i < kTrotPair.size(); ++i) {
    J_c.middleRows<3>(3 * static_cast<int>(i)) = J.middleRows<3>(3 * kTrotPair[i]);
    for (int j : model.support[static_cast<size_t>(model.feet[static_cast<size_t>(kTrotPair[i])].body)])
      if (j > 0) stance.push_back(model.joints[static_cast<size_t>(j)].v_index);
  }
  MatrixX A(J_c.rows(), stance.size());
  for (size_t c = 0; c < stance.size(); ++c) {
    A.col(static_cast<int>(c)) = J_c.col(stance[c]);
    v[stance[c]] = 0;
  }
  const VectorX rates = A.fullPivLu().solve(-J_c * v);
  for (size_t c = 0; c < stance.size(); ++c) v[stance[c]] = rates[static_cast<int>(c)];
}

class ErrorCurve {
 public:
  explicit ErrorCurve(const Model& model) : model_(model), data_(model), reference_(model) {}
  /// Sets the configuration; the exact constrained quantities are computed once.
  void at(const VectorX& q, const VectorX& v) {
    q_ = q;
    v_ = v;
    exact_ = osc_closed_form_constrained(model_, data_, reference_, q_, v_, kTrotPair);
  }
  Errors operator()(double ground_mass) {
    const OscQuantities& x = osc_closed_chain(model_, data_, q_, v_, kTrotPair, ground_mass);
    return {(x.Lambda - exact_.Lambda).norm() / exact_.Lambda.norm(),
            (x.JbarT - exact_.JbarT).norm() / exact_.JbarT.norm(), (x.b - exact_.b).norm() / exact_.b.norm()};
  }

 private:
  const Model& model_;
  Data data_;
  OscReferenceData reference_;
  OscQuantities exact_;
  VectorX q_, v_;
};

// q with the trunk at the origin, tilted by (roll, pitch), and the joints (abad, hip, knee) per leg.
VectorX configuration(const Model& model, double roll, double pitch, const std::vector<double>& joints) {
  VectorX q = VectorX::Zero(model.nq);
  const Eigen::Quaterniond tilt = Eigen::AngleAxisd(pitch, Vector3::UnitY()) * Eigen::AngleAxisd(roll, Vector3::UnitX());
  q.segment<4>(3) << tilt.w(), tilt.x(), tilt.y(), tilt.z();
  for (size_t i = 0; i < joints.size(); ++i) q[7 + static_cast<int>(i)] = joints[i];
  return q;
}

void print_array(const char* name, const std::vector<double>& x, bool last = false) {
  std::printf("  \"%s\": [", name);
  for (size_t i = 0; i < x.size(); ++i) std::printf("%s%.6e", i ? ", " : "", x[i]);
  std::printf("]%s\n", last ? "" : ",");
}

}  // namespace

int main(int argc, char** argv) {
  int configurations = 500;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--configurations") == 0 && i + 1 < argc) {
      configurations = std::stoi(argv[++i]);
    } else {
      std::fputs("usage: rbdc-osc-ground-mass [--configurations N]\n", stderr);
      return 2;
    }
  }
  try {
    const Model model = sim::load_robot(sim::default_urdf());
    Data data(model);
    double total_mass = 0;
    for (const Body& b : model.bodies) total_mass += b.mass;
    const double heuristic = default_ground_mass(model);  // Eq. 58
    std::vector<double> ratios;  // ground mass / total mass, 8 per decade
    for (int k = -32; k <= 64; ++k) ratios.push_back(std::pow(10.0, k / 8.0));
    ErrorCurve curve(model);

    // Mid-stance: LF and RH under their hips (MIT's standing angles), RF and LH folded in mid-swing;
    // trotting forward at 1 m/s with the swing legs moving forward.
    VectorX q = configuration(model, 0.0, 0.0, {0, -0.8, 1.6, 0, -1.2, 2.2, 0, -1.2, 2.2, 0, -0.8, 1.6});
    VectorX v = VectorX::Zero(model.nv);
    v[3] = 1.0;
    for (int leg : {1, 2}) v[6 + 3 * leg + 1] = -4.0, v[6 + 3 * leg + 2] = 2.0;
    pin_feet(model, data, q, v);
    curve.at(q, v);
    std::vector<double> e_Lambda, e_JbarT, e_b;
    for (double r : ratios) {
      const Errors e = curve(r * total_mass);
      e_Lambda.push_back(e.Lambda);
      e_JbarT.push_back(e.JbarT);
      e_b.push_back(e.b);
    }

    // The study: argmin over the same grid, per configuration.
    std::mt19937_64 rng(59);
    std::uniform_real_distribution<double> unit(-1, 1), hip(-1.3, -0.3), knee(0.8, 2.4);
    std::vector<double> argmin_Lambda, argmin_b, penalty;
    for (int n = 0; n < configurations; ++n) {
      std::vector<double> joints;
      for (int leg = 0; leg < 4; ++leg) joints.insert(joints.end(), {0.3 * unit(rng), hip(rng), knee(rng)});
      const VectorX qn = configuration(model, 0.2 * unit(rng), 0.2 * unit(rng), joints);
      VectorX vn(model.nv);
      for (int k = 0; k < model.nv; ++k) vn[k] = unit(rng);
      pin_feet(model, data, qn, vn);
      curve.at(qn, vn);
      double best_Lambda = 1e300, best_b = 1e300, at_Lambda = 0, at_b = 0;
      for (double r : ratios) {
        const Errors e = curve(r * total_mass);
        if (e.Lambda < best_Lambda) best_Lambda = e.Lambda, at_Lambda = r * total_mass;
        if (e.b < best_b) best_b = e.b, at_b = r * total_mass;
      }
      argmin_Lambda.push_back(at_Lambda / heuristic);
      argmin_b.push_back(at_b / heuristic);
      const Errors h = curve(heuristic);
      penalty.push_back(std::max(h.Lambda / best_Lambda, h.b / best_b));
    }
    std::printf("{\n  \"robot\": \"%s\",\n  \"contacts\": [\"LF\", \"RH\"],\n", model.name.c_str());
    std::printf("  \"total_mass\": %.6f,\n  \"heuristic_ground_mass\": %.6e,\n", total_mass, heuristic);
    std::printf("  \"configurations\": %d,\n", configurations);
    print_array("mid_stance_q", std::vector<double>(q.data(), q.data() + q.size()));
    print_array("ratios", ratios);
    print_array("error_Lambda", e_Lambda);
    print_array("error_JbarT", e_JbarT);
    print_array("error_b", e_b);
    print_array("study_argmin_Lambda_over_heuristic", argmin_Lambda);
    print_array("study_argmin_b_over_heuristic", argmin_b);
    print_array("study_error_at_heuristic_over_minimum", penalty, true);
    std::printf("}\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rbdc-osc-ground-mass: %s\n", e.what());
    return 1;
  }
  return 0;
}
