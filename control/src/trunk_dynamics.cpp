#include "rbdc/control/trunk_dynamics.hpp"

#include <cmath>
#include <limits>

#include "mini_cheetah/full.hpp"
#include "mini_cheetah/limb_lanes.hpp"
#include "mini_cheetah/stance_osc_lf_rh.hpp"
#include "mini_cheetah/stance_osc_rf_lh.hpp"

namespace rbdc::control {

static_assert(rbdc_gen::mini_cheetah::full::n_joints == kJoints &&
              rbdc_gen::mini_cheetah::full::n_feet == kFeet &&
              rbdc_gen::mini_cheetah::full::nq == kNq && rbdc_gen::mini_cheetah::full::nv == kNv,
              "control/ is sized for the generated Mini Cheetah");

const char* to_string(StancePair pair) { return pair == StancePair::LfRh ? "LF+RH" : "RF+LH"; }

double mini_cheetah_ground_mass() {
  constexpr double smallest_body_mass = 0.064;  // kg, the shank (robots/mini_cheetah.urdf)
  return smallest_body_mass / std::sqrt(std::numeric_limits<double>::epsilon());
}

void closed_chain_dynamics(const double* q, const double* v, StancePair pair, double ground_mass,
                           TrunkTaskDynamics& out) {
  if (pair == StancePair::LfRh)
    rbdc_gen::mini_cheetah::stance_osc_lf_rh::osc_closed_chain<double>(
        q, v, &ground_mass, out.Lambda.data(), out.JbarT.data(), out.b.data());
  else
    rbdc_gen::mini_cheetah::stance_osc_rf_lh::osc_closed_chain<double>(
        q, v, &ground_mass, out.Lambda.data(), out.JbarT.data(), out.b.data());
}

void open_chain_dynamics(const double* q, const double* v, const FeetForces& f, TrunkTaskDynamics& out) {
  rbdc_gen::mini_cheetah::limb_lanes::osc_open_chain_lanes<double>(q, v, f.data(), out.Lambda.data(),
                                                                   out.JbarT.data(), out.b.data());
}

}  // namespace rbdc::control
