// Emits MJCF text from an rbdc::Model (see mjcf_writer.hpp).
#include "rbdc/mjcf/mjcf_writer.hpp"

#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace rbdc::mjcf {
namespace {

// 17 significant digits: the compiled mjModel then holds exactly our doubles.
std::string numbers(std::initializer_list<double> values) {
  std::ostringstream out;
  out << std::setprecision(17);
  const char* separator = "";
  for (double v : values) {
    out << separator << v;
    separator = " ";
  }
  return out.str();
}

std::string vec(const Vector3& v) { return numbers({v.x(), v.y(), v.z()}); }

// MuJoCo's body quat is the child frame's orientation in the parent (active rotation); E_T is the
// parent → child coordinate rotation, so the body rotation is E_Tᵀ.
std::string body_quat(const Matrix3& E_T) {
  const Eigen::Quaterniond q(E_T.transpose());
  return numbers({q.w(), q.x(), q.y(), q.z()});
}

std::string full_inertia(const Matrix3& I) {
  return numbers({I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2)});
}

const char* joint_type(JointType type) {
  switch (type) {
    case JointType::Revolute: return "hinge";
    case JointType::Prismatic: return "slide";
    default: return nullptr;
  }
}

class Writer {
 public:
  Writer(const Model& model, const MjcfOptions& options) : model_(model), options_(options) {}

  std::string run() {
    check();
    out_ << "<mujoco model=\"" << model_.name << "\">\n"
         << "  <compiler angle=\"radian\" inertiafromgeom=\"false\" balanceinertia=\""
         << (options_.balance_inertia ? "true" : "false") << "\"/>\n"
         << "  <option timestep=\"" << numbers({options_.timestep}) << "\" integrator=\""
         << options_.integrator << "\" cone=\"elliptic\" gravity=\"" << vec(model_.gravity)
         << "\"/>\n"
         << "  <worldbody>\n"
         << "    <geom name=\"ground\" type=\"plane\" size=\"0 0 1\" zaxis=\""
         << vec(options_.ground_normal.normalized())
         << "\" contype=\"0\" conaffinity=\"1\" condim=\"3\"" << contact_attributes() << "/>\n";
    body(0, 2);
    out_ << "  </worldbody>\n";
    if (options_.motors && model_.nb > 1) motors();
    out_ << "</mujoco>\n";
    return out_.str();
  }

 private:
  void check() const {
    if (model_.nb < 1 || static_cast<int>(model_.bodies.size()) != model_.nb ||
        static_cast<int>(model_.joints.size()) != model_.nb)
      throw std::invalid_argument("write_mjcf: model '" + model_.name +
                                  "' has inconsistent body/joint arrays (nb = " +
                                  std::to_string(model_.nb) + ")");
    for (int i = 0; i < model_.nb; ++i) {
      if (model_.bodies[i].name.empty())
        throw std::invalid_argument("write_mjcf: body " + std::to_string(i) + " of model '" +
                                    model_.name + "' has no name");
      if (i > 0 && joint_type(model_.joints[i].type) == nullptr)
        throw std::invalid_argument("write_mjcf: joint '" + model_.joints[i].name +
                                    "' is neither revolute nor prismatic");
    }
    if (model_.has_rotors)  // MuJoCo has no rotor bodies: its best approximation is the armature
      throw std::invalid_argument("write_mjcf: model '" + model_.name +
                                  "' has geared rotors, which MJCF cannot express; reduce them to "
                                  "armature first (rbdc::with_actuator_mode(model, ActuatorMode::Armature))");
    for (const Foot& foot : model_.feet)
      if (foot.body < 0 || foot.body >= model_.nb)
        throw std::invalid_argument("write_mjcf: foot '" + foot.name + "' is on body " +
                                    std::to_string(foot.body) + ", which does not exist");
  }

  // Table I: friction μ (torsional and rolling left at MuJoCo's defaults) and direct
  // stiffness/damping through a negative solref.
  std::string contact_attributes() const {
    return " friction=\"" + numbers({options_.friction, 0.005, 0.0001}) + "\" solref=\"" +
           numbers({-options_.contact_stiffness, -options_.contact_damping}) + "\"";
  }

  void body(int i, int depth) {
    const std::string pad(2 * depth, ' ');
    const Body& b = model_.bodies[i];
    const Joint& j = model_.joints[i];
    out_ << pad << "<body name=\"" << b.name << "\" pos=\"" << vec(j.translation) << "\" quat=\""
         << body_quat(j.rotation) << "\">\n";
    if (i == 0) {
      if (model_.floating_base) out_ << pad << "  <freejoint name=\"" << j.name << "\"/>\n";
    } else {
      out_ << pad << "  <joint name=\"" << j.name << "\" type=\"" << joint_type(j.type)
           << "\" axis=\"" << vec(j.axis) << "\" limited=\"false\"";
      if (j.armature > 0) out_ << " armature=\"" << numbers({j.armature}) << "\"";  // reflected inertia
      out_ << "/>\n";
    }
    out_ << pad << "  <inertial pos=\"" << vec(b.com) << "\" mass=\"" << numbers({b.mass})
         << "\" fullinertia=\"" << full_inertia(b.inertia_com) << "\"/>\n";
    for (const Foot& foot : model_.feet)
      if (foot.body == i)
        out_ << pad << "  <geom name=\"" << foot.name << "\" type=\"sphere\" size=\""
             << numbers({options_.foot_radius}) << "\" pos=\"" << vec(foot.offset)
             << "\" contype=\"1\" conaffinity=\"0\" condim=\"3\" mass=\"0\""
             << contact_attributes() << "/>\n";
    for (int child = i + 1; child < model_.nb; ++child)
      if (model_.parent[child] == i) body(child, depth + 1);
    out_ << pad << "</body>\n";
  }

  void motors() {
    out_ << "  <actuator>\n";
    for (int i = 1; i < model_.nb; ++i)
      out_ << "    <motor name=\"" << model_.joints[i].name << "\" joint=\"" << model_.joints[i].name
           << "\" gear=\"1\" ctrllimited=\"false\"/>\n";
    out_ << "  </actuator>\n";
  }

  const Model& model_;
  const MjcfOptions& options_;
  std::ostringstream out_;
};

}  // namespace

std::string write_mjcf(const Model& model, const MjcfOptions& options) {
  return Writer(model, options).run();
}

}  // namespace rbdc::mjcf
