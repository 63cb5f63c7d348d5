// The few dynamics calls the simulator needs, behind one small interface so that the runtime
// (any robot, read from URDF) and generated code (one robot, compiled in) are interchangeable.
// Coordinates follow docs/conventions.md: q = (p_W, quaternion wxyz, joints), v = (ω_B, v_B, q̇),
// a = (ω̇_B, R_W^0 p̈_W, q̈); foot quantities are 3 × n_feet, column-major, world frame.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rbdc/model.hpp"

namespace rbdc::sim {

class TreeLtdl;

class DynamicsModel {
 public:
  virtual ~DynamicsModel() = default;
  virtual int nq() const = 0;
  virtual int nv() const = 0;
  virtual int n_feet() const = 0;
  /// Foot positions and velocities (each 3 × n_feet, world frame).
  virtual void feet_state(const double* q, const double* v, double* p_feet, double* v_feet) = 0;
  /// a = M⁻¹(Sᵀτ + Jᵀf − c − g) (Eq. 30); τ has nv − 6 entries, f is 3 × n_feet.
  virtual void forward_dynamics(const double* q, const double* v, const double* tau,
                                const double* f_feet, double* a) = 0;
  /// Joint-space inertia M (nv × nv, full) and the feet Jacobian J (3·n_feet × nv, world, foot
  /// points): the contact solver (contact_solver.hpp) needs M⁻¹Jᵀ.
  virtual void mass_matrix(const double* q, MatrixX& M) = 0;
  /// M = Lᵀ D L over dof_parents() into `factor` (sized for them), for the contact solver.
  virtual void mass_matrix_factor(const double* q, TreeLtdl& factor) = 0;
  /// c + g (nv): the inverse dynamics at a = 0 without foot forces.
  virtual void bias_forces(const double* q, const double* v, double* h) = 0;
  virtual void feet_jacobian(const double* q, MatrixX& J) = 0;
  /// Angular rows of the foot bodies (3·n_feet × nv, world), feet_angular.hpp.
  virtual void feet_angular_jacobian(const double* q, MatrixX& Jw) = 0;
  /// λ over degrees of freedom (tree_ltdl.hpp): the sparsity of M's factor.
  virtual const std::vector<int>& dof_parents() const = 0;
  virtual std::string name() const = 0;
};

/// Dynamics from the runtime's reference algorithms on `model` (copied).
std::unique_ptr<DynamicsModel> make_runtime_dynamics(const Model& model);

/// Dynamics from generated/mini_cheetah/full.hpp (every build has them).
std::unique_ptr<DynamicsModel> make_generated_dynamics();

/// Dynamics from generated/mini_cheetah_rotors/full.hpp: the Mini Cheetah with MIT's twelve rotors as
/// bodies (robots/mini_cheetah_rotors.topology.yaml; rbdc-sim --rotors full).
std::unique_ptr<DynamicsModel> make_generated_rotor_dynamics();

}  // namespace rbdc::sim
