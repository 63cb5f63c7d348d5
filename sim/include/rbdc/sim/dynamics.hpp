// The few dynamics calls the simulator needs, behind one small interface so that the runtime
// (any robot, read from URDF) and generated code (one robot, compiled in) are interchangeable.
// Coordinates follow docs/conventions.md: q = (p_W, quaternion wxyz, joints), v = (ω_B, v_B, q̇),
// a = (ω̇_B, R_W^0 p̈_W, q̈); foot quantities are 3 × n_feet, column-major, world frame.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rbdc/data.hpp"

namespace rbdc::sim {

class TreeLtdl;

/// What one contact evaluation needs at (q, v, τ) besides M's factor (contact_solver.hpp); world
/// frame, foot k in column k or rows 3k…3k+2.
struct StepTerms {
  Matrix3X p_feet, v_feet;  ///< foot points and their linear velocities
  Matrix3X omega_feet;      ///< angular velocities of the feet's bodies
  MatrixX J, Jw;            ///< linear rows of the foot points, angular rows of their bodies (3·n_feet × nv)
  VectorX a_free;           ///< a₀ = M⁻¹(Sᵀτ − c − g), the acceleration without foot forces
  /// Sizes every member (no allocation when the sizes are already right).
  void resize(int nv, int n_feet) {
    for (Matrix3X* m : {&p_feet, &v_feet, &omega_feet}) m->resize(3, n_feet);
    J.resize(3 * n_feet, nv);
    Jw.resize(3 * n_feet, nv);
    a_free.resize(nv);
  }
};

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
  /// Joint-space inertia M (nv × nv, full symmetric).
  virtual void mass_matrix(const double* q, MatrixX& M) = 0;
  /// The contact step's terms (resized to fit) and M = Lᵀ D L over dof_parents() into `factor`
  /// (sized for them): one pass of generated code (scene `simulation`), or the runtime's calls.
  virtual void step_terms(const double* q, const double* v, const double* tau, StepTerms& terms,
                          TreeLtdl& factor) = 0;
  /// λ over degrees of freedom (tree_ltdl.hpp): the sparsity of M's factor.
  virtual const std::vector<int>& dof_parents() const = 0;
  virtual std::string name() const = 0;
};

/// Dynamics from the runtime's reference algorithms on `model` (copied).
std::unique_ptr<DynamicsModel> make_runtime_dynamics(const Model& model);

/// Dynamics from generated/mini_cheetah/full.hpp and simulation.hpp (every build has them).
std::unique_ptr<DynamicsModel> make_generated_dynamics();

/// Dynamics from generated/mini_cheetah_rotors/full.hpp and simulation.hpp: the Mini Cheetah with MIT's twelve rotors as
/// bodies (robots/mini_cheetah_rotors.topology.yaml; rbdc-sim --rotors full).
std::unique_ptr<DynamicsModel> make_generated_rotor_dynamics();

}  // namespace rbdc::sim
