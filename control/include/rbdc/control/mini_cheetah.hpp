// Fixed sizes of the controlled robot: the Mini Cheetah of generated/mini_cheetah (12 joints,
// 4 feet, legs LF RF LH RH of ab/ad, hip, knee) and the two trot stance pairs.
#pragma once

#include <array>

#include <Eigen/Core>

#include "rbdc/spatial.hpp"

namespace rbdc::control {

inline constexpr int kJoints = 12;
inline constexpr int kFeet = 4;
inline constexpr int kNq = 19;
inline constexpr int kNv = 18;

using JointTorques = Eigen::Matrix<double, kJoints, 1>;
using FeetForces = Eigen::Matrix<double, 3, kFeet>;  ///< one world-frame column per foot
using TaskJacobianT = Eigen::Matrix<double, 6, kJoints>;

/// Feet in model order (docs/conventions.md): LF 0, RF 1, LH 2, RH 3; leg k owns joints 3k … 3k+2.
enum class StancePair { LfRh, RfLh };
/// The two feet of a diagonal pair, in model order.
inline std::array<int, 2> stance_feet(StancePair pair) {
  return pair == StancePair::LfRh ? std::array<int, 2>{0, 3} : std::array<int, 2>{1, 2};
}
inline std::array<int, 2> swing_feet(StancePair pair) {
  return pair == StancePair::LfRh ? std::array<int, 2>{1, 2} : std::array<int, 2>{0, 3};
}
inline StancePair other(StancePair pair) {
  return pair == StancePair::LfRh ? StancePair::RfLh : StancePair::LfRh;
}
const char* to_string(StancePair pair);

/// Trunk operational-space dynamics Λ ẍ_t + b = J̄ᵀ τ (+ f_t), paper 001 Eq. 28 / Eq. 48, in trunk
/// coordinates with ẍ_t = (ω̇_B, R_W^0 p̈_W) (docs/conventions.md, runtime/include/rbdc/osc.hpp).
struct TrunkTaskDynamics {
  Matrix6 Lambda = Matrix6::Identity();
  TaskJacobianT JbarT = TaskJacobianT::Zero();
  Vector6 b = Vector6::Zero();
};

}  // namespace rbdc::control
