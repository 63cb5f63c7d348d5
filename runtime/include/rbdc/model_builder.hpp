// Builds and validates a Model from topology arrays PRED/SUCC plus per-joint parameters
// (paper 000 Eq. 1-2). This is the one place where numbering and validation happen; the URDF
// and topology-file loaders only translate their input into a ModelSpec.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "rbdc/model.hpp"

namespace rbdc {

/// Refusal of bad input: the message names the source, the element and what is wrong.
class ModelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct JointSpec {
  std::string name;
  JointType type = JointType::Revolute;  ///< Revolute or Prismatic
  Vector3 axis = Vector3::UnitZ();
  Matrix3 rotation = Matrix3::Identity();  ///< E_T
  Vector3 translation = Vector3::Zero();   ///< r_T
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
};

/// Joint `joint`'s actuator (docs/model.md, "Actuators"): an armature, a geared rotor, or both.
/// Unset placements default to the joint's own: rotor rotation = the joint's E_T, translation = its
/// r_T (both in the parent body's frame), axis = the joint axis.
struct ActuatorSpec {
  std::string joint;
  std::string where;  ///< "<file>[:line]" for messages
  std::optional<double> armature;
  bool has_rotor = false;
  double gear_ratio = 0;
  double rotor_mass = 0;
  Matrix3 rotor_inertia = Matrix3::Zero();
  std::optional<Matrix3> rotor_rotation;
  std::optional<Vector3> rotor_translation;
  std::optional<Vector3> rotor_axis;
};

struct ModelSpec {
  std::string name;
  std::string source = "<arrays>";  ///< file name used in error messages
  bool floating_base = true;
  Vector3 gravity{0, 0, -9.81};
  std::vector<int> pred, succ;     ///< joints 1 … nb-1 (entry k describes joint k+1), Eq. 1
  std::vector<JointSpec> joints;   ///< joints 1 … nb-1, same order as pred/succ
  std::vector<Body> bodies;        ///< nb bodies in final numbering, body 0 = root
  std::vector<Foot> feet;
  std::vector<Frame> frames;       ///< operational frames (names unique among frames)
  std::vector<Coupling> couplings;  ///< joint indices in the final numbering
  std::vector<ActuatorSpec> actuators;  ///< by joint name; empty: no rotors, no armature
  /// Optional: the line of each body's (first) definition in `source`, for messages (nb entries).
  std::vector<int> body_lines;
};

/// One body's mass properties, checked and repaired (table in docs/model.md): NaN/Inf and negative
/// mass are refused; an asymmetric or indefinite rotational inertia is symmetrised / clipped to its
/// nearest positive semi-definite matrix when the defect is within round-off of its size
/// (kInertiaRepairTolerance), with a warning giving its size, and refused beyond. A massless body
/// with rotational inertia is kept with a warning. Throws ModelError("<where>: <problem>");
/// warnings start with `where`. `Indefinite::Defer` (a link that fixed joints merge with others)
/// turns the indefinite refusal into a warning and keeps the inertia as given: the merged body is
/// checked instead (docs/model.md).
enum class Indefinite { Refuse, Defer };
Body repair_mass_properties(const Body& body, const std::string& where,
                            std::vector<std::string>* warnings, Indefinite indefinite = Indefinite::Refuse);

/// Relative tolerance of the inertia repairs: the defect may reach this times the trace (plus
/// kInertiaRepairFloor kg·m², so that an inertia made only of round-off is repaired, not refused).
constexpr double kInertiaRepairTolerance = 1e-9;
constexpr double kInertiaRepairFloor = 1e-12;

/// Validates the spec, derives λ (Eq. 2), κ, μ, ν, q/v indices and the spatial constants.
/// Throws ModelError on bad input; appends non-fatal findings (e.g. an inertia that breaks the
/// triangle inequality) to `warnings` when given.
Model build_model(const ModelSpec& spec, std::vector<std::string>* warnings = nullptr);

/// Adds actuators to a built model (build_model calls it with spec.actuators; the tools with
/// --armature): checks them (unknown or root joint, armature or rotor given twice, NaN, negative
/// armature, mass or gear ratio ≤ 0, non-physical or not axisymmetric rotor inertia, bad rotation:
/// ModelError naming spec.where and the joint), derives X_rotor, rotor_inertia, rotor_subspace and
/// applies the singular-mass-matrix rule (Model::singular_mass_matrix; an armature can regularise M).
void add_actuators(Model& model, const std::vector<ActuatorSpec>& actuators);

}  // namespace rbdc
