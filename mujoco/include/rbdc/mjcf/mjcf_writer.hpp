// MJCF (MuJoCo XML) from an rbdc::Model: the same bodies, frames, masses and inertias, a free joint at
// a floating root, one motor per 1-DoF joint, a sphere at every foot and a ground plane. Used by the
// MuJoCo comparison (paper 000 Section 6.3) and the MuJoCo benchmarks, so both time the same robot.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "rbdc/model.hpp"

namespace rbdc::mjcf {

/// Scene settings. Defaults follow paper 000 Table I (MuJoCo column) with our foot radius.
struct MjcfOptions {
  double timestep = 1e-4;                 ///< s
  std::string integrator = "implicit";    ///< MuJoCo 2.2 names: Euler | RK4 | implicit
  double foot_radius = 0.02;              ///< m, sphere centred at each foot point
  double friction = 1.6;                  ///< sliding friction coefficient (Table I)
  double contact_stiffness = 1.6e3;       ///< N/m, emitted as solref = (-stiffness, -damping)
  double contact_damping = 100.0;         ///< N/(m/s)
  Vector3 ground_normal{0, 0, 1};         ///< world frame; the plane passes through the origin
  bool balance_inertia = true;            ///< compiler balanceinertia (needed for MIT's thigh)
  bool motors = true;                     ///< one motor (gear 1, no limits) per 1-DoF joint
};

/// The MJCF text. Body and joint names are the model's; foot spheres are named after the feet.
/// A joint's armature (reflected rotor inertia) becomes its MJCF armature. Throws
/// std::invalid_argument for a model MuJoCo cannot express (an unnamed body, geared rotors).
std::string write_mjcf(const Model& model, const MjcfOptions& options = {});

struct MjModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
using MjModelPtr = std::unique_ptr<mjModel, MjModelDeleter>;

struct MjDataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using MjDataPtr = std::unique_ptr<mjData, MjDataDeleter>;

/// Compiles write_mjcf(model, options) through MuJoCo's in-memory file system.
/// Throws std::runtime_error carrying MuJoCo's compiler message when it refuses the model.
MjModelPtr load_mjmodel(const Model& model, const MjcfOptions& options = {});

/// Where each rbdc entity lives in the compiled mjModel (looked up by name).
struct MujocoIndex {
  std::vector<int> body;       ///< mjModel body id of rbdc body i
  std::vector<int> qpos;       ///< qpos address of joint i (free joint: 7 entries, 1-DoF: 1)
  std::vector<int> dof;        ///< dof address of joint i (-1 for a fixed root)
  std::vector<int> actuator;   ///< actuator id of joint i (-1 for the root or without motors)
  std::vector<int> foot_geom;  ///< geom id of foot k's sphere
};
MujocoIndex index_mjmodel(const Model& model, const mjModel* m);

/// How far MuJoCo moved one body's inertia (balanceinertia), about the COM in body axes.
struct InertiaChange {
  std::string body;
  Matrix3 before, after;
  double relative_change;  ///< ‖after − before‖_F / ‖before‖_F
};

/// Copies the masses, COMs and inertias MuJoCo compiled back into `model` (rebuilding its spatial
/// inertias) so that our side of a comparison simulates exactly MuJoCo's robot.
/// Returns the bodies whose inertia changed by more than 1e-6 relative (MuJoCo re-diagonalises
/// every inertia, which alone moves entries by ~1e-9).
std::vector<InertiaChange> adopt_mujoco_inertias(Model& model, const mjModel* m);

}  // namespace rbdc::mjcf
