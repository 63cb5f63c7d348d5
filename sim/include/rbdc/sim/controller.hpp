// The one interface of every controller (control/: the PD trot of paper 000, the operational-space
// and Raibert trots of paper 001): state in, joint torques out, a name and its parameters. The run
// loop of run.hpp and the MuJoCo bridge (mujoco/) drive any of them.
#pragma once

#include <string>
#include <vector>

#include "rbdc/data.hpp"

namespace rbdc::sim {

/// What a controller sees at one update; q, v in the docs/conventions.md layout.
struct ControllerInput {
  double t;                      ///< s, time of the state
  double dt;                     ///< s, until the next update (the torques are held that long)
  const VectorX& q;              ///< nq
  const VectorX& v;              ///< nv
  const Matrix3X& foot_forces;   ///< 3 × n_feet, world, ground on robot; empty unless requested
};

/// One tunable scalar and its current value.
struct Parameter {
  std::string name;
  double value;
};

class Controller {
 public:
  virtual ~Controller() = default;
  /// Short name for logs and file names ("pd-trot", "osc", "osc-open", "raibert").
  virtual std::string name() const = 0;
  /// The tunable scalars with their values, in a fixed order.
  virtual std::vector<Parameter> parameters() const = 0;
  /// Configuration (nq) to start from, at rest.
  virtual VectorX initial_configuration() const = 0;
  /// Whether update() reads input.foot_forces (measuring them costs the plant a contact pass).
  virtual bool uses_foot_forces() const { return false; }
  /// Joint torques (nv − 6); the reference stays valid until the next call.
  virtual const VectorX& update(const ControllerInput& input) = 0;
};

}  // namespace rbdc::sim
