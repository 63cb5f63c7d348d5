// The immutable robot model: topology arrays (paper 000 Eq. 1-3, κ, μ, ν, φ), joint models,
// constant joint placements and spatial inertias. Built and validated only by ModelBuilder
// (model_builder.hpp); see docs/conventions.md for frames and ordering.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "rbdc/spatial.hpp"

namespace rbdc {

enum class JointType { Floating, Fixed, Revolute, Prismatic };

/// Joint i's geared motor rotor (docs/model.md, "Actuators"), treated as in Featherstone's RBDA
/// (geared motors), Jain ch. 12 and Cheetah-Software: a rigid body carried by the parent λ(i) at a
/// constant placement X_rot, spinning at gear_ratio · q̇_i about `axis`, so its motion subspace is
/// S_rot = gear_ratio · (axis; 0). Its mass is symmetric about the axis (the builder checks), so its
/// spatial inertia in rotor coordinates does not depend on its angle.
struct Rotor {
  double gear_ratio = 0;                   ///< > 0; 0 means joint i has no rotor
  double mass = 0;                         ///< COM at the rotor origin, on the axis
  Matrix3 inertia = Matrix3::Zero();       ///< about the rotor origin, rotor axes
  Matrix3 rotation = Matrix3::Identity();  ///< parent → rotor coordinates
  Vector3 translation = Vector3::Zero();   ///< rotor origin in parent coordinates
  Vector3 axis = Vector3::Zero();          ///< unit spin axis, rotor coordinates
};

/// Joint i connects body λ(i) to body i. Joint 0 is the root joint (Floating or Fixed).
struct Joint {
  std::string name;
  JointType type = JointType::Revolute;
  Vector3 axis = Vector3::Zero();   ///< unit axis in the joint (= child body) frame
  Matrix3 rotation = Matrix3::Identity();  ///< E_T: parent → joint coordinates at q = 0
  Vector3 translation = Vector3::Zero();   ///< r_T: joint origin in parent coordinates
  double lower = -std::numeric_limits<double>::infinity();  ///< limits; ±inf when none
  double upper = std::numeric_limits<double>::infinity();
  int q_index = 0;  ///< first entry of this joint in q
  int v_index = 0;  ///< first entry of this joint in v
  double armature = 0;  ///< reflected rotor inertia added to M_ii only (kg·m² or kg), ≥ 0
  Rotor rotor;          ///< the joint's motor rotor, if rotor.gear_ratio > 0
};

struct Body {
  std::string name;
  double mass = 0;
  Vector3 com = Vector3::Zero();              ///< body coordinates
  Matrix3 inertia_com = Matrix3::Zero();      ///< about the COM, body axes
};

/// A mimic coupling (URDF <mimic>): q_follower = multiplier · q_leader + offset, joint indices.
/// The follower keeps its place in the tree but not its own coordinate (docs/model.md, "Mimic
/// joints"; rbdc/coupling.hpp maps between the tree's and the independent coordinates).
struct Coupling {
  int follower = 0;
  int leader = 0;
  double multiplier = 1;
  double offset = 0;
};

/// A foot is a point on a body (Eq. 16): φ(k) = body.
struct Foot {
  std::string name;
  int body = 0;
  Vector3 offset = Vector3::Zero();
};

/// An operational frame (docs/model.md, "Frames"): body `body` plus a constant pose, as Pinocchio's
/// frames. The URDF loader makes one per link (also the links that fixed-joint merging folds into a
/// body: tool0, *_foot, camera and IMU frames keep their names and poses); topology files add more.
/// X_body^F = motion_transform(rotation, translation) (Eq. 5), like a joint's placement.
struct Frame {
  std::string name;
  int body = 0;
  Matrix3 rotation = Matrix3::Identity();  ///< E: body → frame coordinates (R_body^F)
  Vector3 translation = Vector3::Zero();   ///< frame origin in body coordinates
};

struct Model {
  std::string name;
  bool floating_base = true;
  int nb = 0;  ///< number of bodies, root included
  int nq = 0;
  int nv = 0;
  Vector3 gravity{0, 0, -9.81};  ///< world frame

  // Topology over joints 1 … nb-1, stored at index i (index 0 holds -1 / 0): paper 000 Eq. 1-3.
  std::vector<int> pred, succ, parent;
  std::vector<std::vector<int>> support;   ///< κ(i): joints between body i and the root (i incl.)
  std::vector<std::vector<int>> children;  ///< μ(i)
  std::vector<std::vector<int>> subtree;   ///< ν(i), i included

  std::vector<Body> bodies;
  std::vector<Joint> joints;
  std::vector<Foot> feet;
  std::vector<Frame> frames;        ///< by body; within one, the source's order
  std::vector<Coupling> couplings;  ///< ascending followers; leaders are never followers

  // Derived constants, filled by ModelBuilder.
  std::vector<Matrix6> X_tree;   ///< X_T(i) = motion_transform(rotation, translation)
  std::vector<Matrix6> inertia;  ///< spatial inertia of body i at its origin
  std::vector<Vector6> motion_subspace;  ///< S_i for 1-DoF joints (zero for the root)
  // Rotors (docs/model.md, "Actuators"): nb entries each when has_rotors, else empty.
  bool has_rotors = false;
  bool has_armature = false;
  std::vector<Matrix6> X_rotor;          ///< X_λ(i)^rot(i): parent → rotor coordinates
  std::vector<Matrix6> rotor_inertia;    ///< rotor spatial inertia at its origin, rotor coordinates
  std::vector<Vector6> rotor_subspace;   ///< S_rot(i) = gear_ratio · (axis; 0), zero without rotor

  /// Why M is singular by the rule of docs/model.md (rbdc::mass_matrix_singularity), "" when it is
  /// positive definite. Set by the builder and by with_actuator_mode; a non-empty reason makes the
  /// functions that need M⁻¹ (forward dynamics, its derivatives, OSC) throw std::invalid_argument.
  std::string singular_mass_matrix;

  int num_joints() const { return nb - 1; }  ///< 1-DoF joints (actuated)
  int root_dofs() const { return floating_base ? 6 : 0; }
};

}  // namespace rbdc
