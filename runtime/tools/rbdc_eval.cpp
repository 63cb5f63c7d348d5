// rbdc-eval: the runtime's M, c, g, feet positions and feet Jacobian at one state, as JSON keyed by
// velocity-coordinate names (a floating base's first six are root_wx … root_vz), numbers with 17
// significant digits. With --a it also prints inverse_dynamics(q, v, a) as "tau"; with --derivatives
// the analytic derivatives of rbdc/derivatives.hpp (at --a, --tau, --f). Used by `rbdc eval` to
// compare the runtime with other libraries. Bad input exits with code 2.
#include <iomanip>
#include <iostream>
#include <iterator>
#include <utility>
#include <sstream>
#include <string>
#include <vector>

#include "rbdc/body_wrenches_file.hpp"
#include "rbdc/derivatives.hpp"
#include "rbdc/rbdc.hpp"
#include "tool_options.hpp"

namespace {

using rbdc::MatrixX;
using rbdc::Model;
using rbdc::VectorX;

/// "v1,v2,…" → numbers; refuses empty items and trailing garbage, naming the option.
std::vector<double> parse_list(const std::string& option, const std::string& text) {
  std::vector<double> values;
  std::stringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    size_t used = 0;
    double x = 0;
    try {
      x = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size()) {
      throw std::invalid_argument(option + ": '" + item + "' is not a number");
    }
    values.push_back(x);
  }
  return values;
}

/// The vector given by `option` (or `fallback` when absent), checked for length and finiteness.
VectorX state_vector(const std::string& option, const std::vector<double>* given, Eigen::Index size,
                     const VectorX& fallback) {
  if (given == nullptr) return fallback;
  if (static_cast<Eigen::Index>(given->size()) != size) {
    throw std::invalid_argument(option + " has " + std::to_string(given->size()) +
                                " values, the model needs " + std::to_string(size));
  }
  const VectorX x = Eigen::Map<const VectorX>(given->data(), size);
  if (!rbdc::check_finite(x)) throw std::invalid_argument(option + " has a NaN or Inf value");
  return x;
}

std::vector<std::string> velocity_names(const Model& model) {
  std::vector<std::string> names;
  if (model.floating_base) names = {"root_wx", "root_wy", "root_wz", "root_vx", "root_vy", "root_vz"};
  for (int i = 1; i < model.nb; ++i) names.push_back(model.joints[static_cast<size_t>(i)].name);
  return names;
}

void write_strings(std::ostream& out, const std::vector<std::string>& names) {
  out << "[";
  for (size_t k = 0; k < names.size(); ++k) out << (k ? ", " : "") << std::quoted(names[k]);
  out << "]";
}

template <class Vector>
void write_vector(std::ostream& out, const Vector& x) {
  out << "[";
  for (Eigen::Index k = 0; k < x.size(); ++k) out << (k ? ", " : "") << x[k];
  out << "]";
}

template <class Matrix>
void write_rows(std::ostream& out, const Matrix& m, const char* indent) {
  out << "[";
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    out << (r ? ",\n" : "\n") << indent << "  ";
    write_vector(out, m.row(r));
  }
  out << "\n" << indent << "]";
}

using NamedMatrix = std::pair<const char*, const MatrixX*>;

/// ",\n  "key": {"name": rows, …}": matrices under their names, as row lists.
template <size_t N>
void write_matrices(std::ostream& out, const char* key, const NamedMatrix (&matrices)[N]) {
  out << ",\n  " << std::quoted(key) << ": {";
  for (size_t k = 0; k < N; ++k) {
    out << (k ? ",\n    " : "\n    ") << std::quoted(matrices[k].first) << ": ";
    write_rows(out, *matrices[k].second, "    ");
  }
  out << "\n  }";
}

/// "derivatives": every output of rbdc/derivatives.hpp under its own name, as row lists.
void write_derivatives(std::ostream& out, const Model& model, rbdc::Data& data, const VectorX& q,
                       const VectorX& v, const VectorX& a, const VectorX& tau, const rbdc::Matrix3X& f) {
  rbdc::DerivativeData d(model);
  rbdc::inverse_dynamics_derivatives(model, data, d, q, v, a);
  const MatrixX dtau_dq = d.dtau_dq, dtau_dv = d.dtau_dv;  // forward dynamics redoes them at its a
  rbdc::bias_derivatives(model, data, d, q, v);
  rbdc::gravity_derivatives(model, data, d, q);
  rbdc::forward_dynamics_derivatives(model, data, d, q, v, tau, f);
  rbdc::feet_velocity_derivatives(model, data, d, q, v);
  const NamedMatrix outputs[] = {
      {"dtau_dq", &dtau_dq}, {"dtau_dv", &dtau_dv},     {"dbias_dq", &d.dbias_dq},
      {"dbias_dv", &d.dbias_dv}, {"dg_dq", &d.dg_dq},     {"da_dq", &d.da_dq},
      {"da_dv", &d.da_dv},   {"da_dtau", &d.da_dtau}, {"da_df", &d.da_df},
      {"dpdot_dq", &d.dpdot_dq}, {"dtau_e_dq", &d.dtau_e_dq}};
  write_matrices(out, "derivatives", outputs);
}

/// "forward_dynamics" (docs/runtime.md, "rbdc-eval"): q̈ = M⁻¹(Sᵀτ + τ_e − c − g) with τ_e from the
/// world foot forces f and the body wrenches, and for a floating base the trunk's acceleration in
/// trunk coordinates, classical (= q̈[0:6]) and spatial (Featherstone's, a₀ = q̈[0:6] − (0, ω_B × v_B)).
void write_forward_dynamics(std::ostream& out, const Model& model, rbdc::Data& data, const VectorX& q,
                            const VectorX& v, const VectorX& tau, const rbdc::Matrix3X& f,
                            const std::vector<rbdc::Vector6>& body_wrenches) {
  VectorX qdd = rbdc::forward_dynamics(model, data, q, v, tau, f);  // factors M in data.M_llt
  // The body wrenches enter linearly: q̈ += M⁻¹ τ_e(wrenches) (Alg. 4)
  qdd += data.M_llt.solve(rbdc::external_wrench_terms(model, data, q, body_wrenches));
  out << ",\n  \"forward_dynamics\": {\n    \"qdd\": ";
  write_vector(out, qdd);
  if (model.floating_base) {
    rbdc::Vector6 spatial = qdd.head<6>();
    spatial.tail<3>() -= v.head<3>().cross(v.segment<3>(3));
    out << ",\n    \"trunk_classical_acceleration\": ";
    write_vector(out, qdd.head<6>());
    out << ",\n    \"trunk_spatial_acceleration\": ";
    write_vector(out, spatial);
  }
  out << "\n  }";
}

/// The frames named in `list` ("all" or "A,B,…"), as model indices; an unknown name throws
/// std::invalid_argument naming it (frame_index).
std::vector<int> selected_frames(const Model& model, const std::string& list) {
  std::vector<int> frames;
  if (list == "all") {
    for (size_t k = 0; k < model.frames.size(); ++k) frames.push_back(static_cast<int>(k));
    return frames;
  }
  std::stringstream items(list);
  std::string name;
  while (std::getline(items, name, ',')) frames.push_back(rbdc::frame_index(model, name));
  return frames;
}

/// "frames" (docs/runtime.md, "rbdc-eval"): per selected frame its placement, velocities,
/// Jacobians and J̇v (rbdc/frames.hpp), keyed by frame name.
void write_frames(std::ostream& out, const Model& model, rbdc::Data& data, const VectorX& q,
                  const VectorX& v, const std::vector<int>& frames) {
  rbdc::frame_placements(model, data, q);
  rbdc::frame_velocities(model, data, q, v);
  rbdc::frame_jacobians(model, data, q);
  rbdc::frame_bias_accelerations(model, data, q, v);
  out << ",\n  \"frames\": {";
  for (size_t n = 0; n < frames.size(); ++n) {
    const size_t k = static_cast<size_t>(frames[n]);
    const Eigen::Index col = frames[n];
    out << (n ? ",\n    " : "\n    ") << std::quoted(model.frames[k].name) << ": {\n      \"position\": ";
    write_vector(out, data.frame_position.col(col));
    out << ",\n      \"world_R_frame\": ";
    write_rows(out, data.world_R_frame[k], "      ");
    out << ",\n      \"velocity_local\": ";
    write_vector(out, data.frame_velocity_local.col(col));
    out << ",\n      \"velocity_world\": ";
    write_vector(out, data.frame_velocity_world.col(col));
    out << ",\n      \"jacobian_local\": ";
    write_rows(out, data.frame_jacobian_local[k], "      ");
    out << ",\n      \"jacobian_world\": ";
    write_rows(out, data.frame_jacobian_world[k], "      ");
    out << ",\n      \"bias_spatial\": ";
    write_vector(out, data.frame_bias_spatial.col(col));
    out << ",\n      \"bias_classical\": ";
    write_vector(out, data.frame_bias_classical.col(col));
    out << "\n    }";
  }
  out << "\n  }";
}

/// "centroidal" (rbdc/centroidal.hpp) and "M_inverse" (rbdc/crba.hpp).
void write_centroidal(std::ostream& out, const Model& model, rbdc::Data& data, const VectorX& q,
                      const VectorX& v) {
  rbdc::center_of_mass(model, data, q, v);
  const rbdc::Vector3 com = data.com, com_velocity = data.com_velocity;
  rbdc::center_of_mass_jacobian(model, data, q);
  rbdc::centroidal_momentum_matrix(model, data, q);
  rbdc::centroidal_bias(model, data, q, v);
  out << ",\n  \"centroidal\": {\n    \"com\": ";
  write_vector(out, com);
  out << ",\n    \"com_velocity\": ";
  write_vector(out, com_velocity);
  out << ",\n    \"com_jacobian\": ";
  write_rows(out, data.com_jacobian, "    ");
  out << ",\n    \"momentum_matrix\": ";
  write_rows(out, data.A_G, "    ");
  out << ",\n    \"bias\": ";
  write_vector(out, data.centroidal_bias);
  out << "\n  },\n  \"M_inverse\": ";
  if (model.singular_mass_matrix.empty()) {
    write_rows(out, rbdc::mass_matrix_inverse(model, data, q), "  ");
  } else {
    out << "null";  // M is singular (docs/model.md, "Singular mass matrix")
  }
}

/// Foot names "LF,RH,…" → indices into model.feet; an unknown name is refused with the feet listed.
std::vector<int> contact_feet(const Model& model, const std::string& names) {
  std::vector<int> feet;
  std::stringstream items(names);
  std::string item;
  while (std::getline(items, item, ',')) {
    int index = -1;
    for (size_t k = 0; k < model.feet.size(); ++k) {
      if (model.feet[k].name == item) index = static_cast<int>(k);
    }
    if (index < 0) {
      std::string known;
      for (const rbdc::Foot& foot : model.feet) known += (known.empty() ? "" : ", ") + foot.name;
      throw std::invalid_argument("--contacts: '" + item + "' is not a foot of '" + model.name +
                                  "' (feet: " + known + ")");
    }
    feet.push_back(index);
  }
  return feet;
}

/// "contact_dynamics", "impulse_dynamics" and, with derivatives, "contact_dynamics_derivatives"
/// (docs/runtime.md, "Contact dynamics") for the contact set.
void write_contact_dynamics(std::ostream& out, const Model& model, rbdc::Data& data,
                            rbdc::ContactDynamicsData& contact, const VectorX& q, const VectorX& v,
                            const VectorX& tau, double restitution, bool derivatives) {
  rbdc::contact_dynamics(model, data, contact, q, v, tau);
  out << ",\n  \"contact_dynamics\": {\n    \"qdd\": ";
  write_vector(out, contact.a);
  out << ",\n    \"lambda\": ";
  write_vector(out, contact.lambda);
  out << ",\n    \"damping\": " << contact.mu << "\n  }";
  rbdc::impulse_dynamics(model, data, contact, q, v, restitution);
  out << ",\n  \"impulse_dynamics\": {\n    \"v_plus\": ";
  write_vector(out, contact.v_plus);
  out << ",\n    \"impulse\": ";
  write_vector(out, contact.impulse);
  out << "\n  }";
  if (!derivatives) return;
  rbdc::DerivativeData d(model);
  rbdc::contact_dynamics_derivatives(model, data, d, contact, q, v, tau);
  const NamedMatrix outputs[] = {
      {"da_dq", &contact.da_dq},           {"da_dv", &contact.da_dv},
      {"da_dtau", &contact.da_dtau},       {"dlambda_dq", &contact.dlambda_dq},
      {"dlambda_dv", &contact.dlambda_dv}, {"dlambda_dtau", &contact.dlambda_dtau}};
  write_matrices(out, "contact_dynamics_derivatives", outputs);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rbdc::tools;
  return run_tool([&] {
    LoadOptions opts;
    std::vector<double> q_values, v_values, a_values, tau_values, f_values;
    bool has_q = false, has_v = false, has_a = false, has_tau = false, has_f = false;
    bool derivatives = false;
    std::string body_wrenches_file, frame_list, contacts;
    bool has_contacts = false;
    std::vector<double> restitution_values, kd_values;
    bool has_restitution = false, has_kd = false;
    const ExtraOption state_options = [&](int n, char** args, int& i) {
      const std::string arg = args[i];
      if (arg == "--derivatives") return derivatives = true;
      if (arg == "--frames") {
        if (i + 1 >= n) throw std::invalid_argument("--frames expects 'all' or comma-separated frame names");
        frame_list = args[++i];
        return true;
      }
      if (arg == "--body-wrenches") {
        if (i + 1 >= n) throw std::invalid_argument("--body-wrenches expects a JSON file");
        body_wrenches_file = args[++i];
        return true;
      }
      if (arg == "--contacts") {
        if (i + 1 >= n) throw std::invalid_argument("--contacts expects comma-separated foot names");
        contacts = args[++i];
        return has_contacts = true;
      }
      const std::pair<const char*, std::pair<std::vector<double>*, bool*>> vectors[] = {
          {"--q", {&q_values, &has_q}},       {"--v", {&v_values, &has_v}},
          {"--a", {&a_values, &has_a}},       {"--tau", {&tau_values, &has_tau}},
          {"--f", {&f_values, &has_f}},       {"--restitution", {&restitution_values, &has_restitution}},
          {"--kd", {&kd_values, &has_kd}}};
      for (const auto& [name, target] : vectors) {
        if (arg != name) continue;
        if (i + 1 >= n) throw std::invalid_argument(arg + " expects comma-separated numbers");
        *target.first = parse_list(arg, args[++i]);
        *target.second = true;
        return true;
      }
      return false;
    };
    if (!parse_load_options(argc, argv, opts, state_options)) {
      std::cout << "usage: rbdc-eval ROBOT [options] [--q Q0,Q1,…] [--v V0,V1,…] [--a A0,A1,…]\n"
                   "                 [--tau T0,…] [--f F0x,F0y,F0z,F1x,…] [--body-wrenches FILE.json]\n"
                   "                 [--derivatives] [--frames all|NAME,…] [--contacts FOOT,…]\n"
                   "                 [--restitution E] [--kd KD]\n"
                   "Prints the runtime's M, c, g, feet positions and feet Jacobian (and with --a the\n"
                   "inverse dynamics tau) at one state as JSON. Defaults: q neutral (identity\n"
                   "quaternion), v, a, tau and the world foot forces f (foot-major) zero.\n"
                   "With --tau or --body-wrenches it adds \"forward_dynamics\": qdd (nv) and, for a\n"
                   "floating base, the trunk's classical and spatial accelerations in trunk\n"
                   "coordinates. FILE.json: {\"BODY\": [nx, ny, nz, fx, fy, fz], …}, each wrench\n"
                   "(moment; force) at the body origin in body coordinates (docs/runtime.md).\n"
                   "--derivatives adds \"derivatives\": dtau_dq, dtau_dv (at a), dbias_dq, dbias_dv,\n"
                   "dg_dq, da_dq, da_dv, da_dtau, da_df (at tau, f), dpdot_dq, dtau_e_dq (at f), with\n"
                   "respect to q on the manifold (docs/conventions.md).\n"
                   "Always printed too: the feet's J̇v (\"feet\": \"bias_accelerations\"), \"centroidal\"\n"
                   "(com, com_velocity, com_jacobian, momentum_matrix A_G, bias Ȧ_G v) and \"M_inverse\".\n"
                   "--frames adds \"frames\": for each named frame (all: every frame of the model) its\n"
                   "position, world_R_frame, velocity_local/_world, jacobian_local/_world (6 x nv),\n"
                   "bias_spatial (local) and bias_classical (world-aligned); an unknown name exits 2.\n"
                   "--contacts LF,RH,… (foot names; a repeated foot is a redundant contact) adds\n"
                   "\"contact_dynamics\": qdd, lambda (world contact forces, contact-major), damping (the μ\n"
                   "of the Delassus solve), with the Baumgarte velocity gain --kd (default 0), and\n"
                   "\"impulse_dynamics\": v_plus, impulse at v with restitution --restitution E in [0, 1]\n"
                   "(default 0); with --derivatives also \"contact_dynamics_derivatives\": da_dq, da_dv,\n"
                   "da_dtau, dlambda_dq, dlambda_dv, dlambda_dtau (docs/runtime.md, \"Contact dynamics\").\n\n"
                << kLoadOptionsHelp;
      return 0;
    }
    const Model model = load_model(opts);
    if (!model.couplings.empty()) {  // its output is keyed by tree coordinates (one per joint)
      throw std::invalid_argument(opts.input + ": " + std::to_string(model.couplings.size()) +
                                  " mimic joints are coupled; rbdc-eval reports one coordinate per joint: "
                                  "use --independent-mimic or --lock-mimic");
    }
    VectorX neutral = VectorX::Zero(model.nq);
    if (model.floating_base) neutral[3] = 1;  // quaternion (w, x, y, z) = identity
    const VectorX q = state_vector("--q", has_q ? &q_values : nullptr, model.nq, neutral);
    const VectorX v = state_vector("--v", has_v ? &v_values : nullptr, model.nv, VectorX::Zero(model.nv));
    const VectorX a = state_vector("--a", has_a ? &a_values : nullptr, model.nv, VectorX::Zero(model.nv));
    const VectorX tau = state_vector("--tau", has_tau ? &tau_values : nullptr, model.num_joints(),
                                     VectorX::Zero(model.num_joints()));
    const Eigen::Index n_forces = 3 * static_cast<Eigen::Index>(model.feet.size());
    const VectorX f = state_vector("--f", has_f ? &f_values : nullptr, n_forces, VectorX::Zero(n_forces));

    const double restitution = state_vector("--restitution", has_restitution ? &restitution_values : nullptr,
                                            1, VectorX::Zero(1))[0];
    const double kd = state_vector("--kd", has_kd ? &kd_values : nullptr, 1, VectorX::Zero(1))[0];
    if (!(restitution >= 0 && restitution <= 1)) {
      throw std::invalid_argument("--restitution " + std::to_string(restitution) + " is not in [0, 1]");
    }
    if ((has_restitution || has_kd) && !has_contacts) {
      throw std::invalid_argument("--restitution and --kd need --contacts");
    }
    // resolved before any output, so that a bad name leaves stdout empty
    rbdc::ContactDynamicsData contact(model, has_contacts ? contact_feet(model, contacts) : std::vector<int>{},
                                      rbdc::BaumgarteGains{0.0, kd});
    std::vector<rbdc::Vector6> body_wrenches(static_cast<size_t>(model.nb), rbdc::Vector6::Zero());
    if (!body_wrenches_file.empty()) body_wrenches = rbdc::read_body_wrenches(body_wrenches_file, model);

    rbdc::Data data(model);
    const MatrixX M = rbdc::mass_matrix(model, data, q);
    const VectorX c = rbdc::quadratic_velocity_terms(model, data, q, v);
    const VectorX g = rbdc::gravity_terms(model, data, q);
    const rbdc::Matrix3X feet = rbdc::feet_positions(model, data, q);
    const MatrixX J = rbdc::feet_jacobian(model, data, q);
    const rbdc::Matrix3X feet_bias = rbdc::feet_bias_accelerations(model, data, q, v);
    const std::vector<int> frames = frame_list.empty() ? std::vector<int>{} : selected_frames(model, frame_list);
    std::vector<std::string> feet_names;
    for (const rbdc::Foot& f : model.feet) feet_names.push_back(f.name);

    std::ostream& out = std::cout;
    out << std::setprecision(17);
    out << "{\n  \"joint_names\": ";
    write_strings(out, velocity_names(model));
    out << ",\n  \"nq\": " << model.nq << ",\n  \"nv\": " << model.nv << ",\n  \"M\": ";
    write_rows(out, M, "  ");
    out << ",\n  \"c\": ";
    write_vector(out, c);
    out << ",\n  \"g\": ";
    write_vector(out, g);
    if (has_a) {
      out << ",\n  \"tau\": ";
      write_vector(out, rbdc::inverse_dynamics(model, data, q, v, a));
    }
    out << ",\n  \"feet\": {\n    \"names\": ";
    write_strings(out, feet_names);
    out << ",\n    \"positions\": ";
    write_rows(out, feet.transpose(), "    ");
    out << ",\n    \"jacobian\": ";
    write_rows(out, J, "    ");
    out << ",\n    \"bias_accelerations\": ";
    write_rows(out, feet_bias.transpose(), "    ");
    out << "\n  }";
    write_centroidal(out, model, data, q, v);
    if (!frame_list.empty()) write_frames(out, model, data, q, v, frames);
    if (has_tau || !body_wrenches_file.empty()) {
      write_forward_dynamics(out, model, data, q, v, tau,
                             Eigen::Map<const rbdc::Matrix3X>(f.data(), 3, n_forces / 3), body_wrenches);
    }
    if (derivatives) {
      write_derivatives(out, model, data, q, v, a, tau,
                        Eigen::Map<const rbdc::Matrix3X>(f.data(), 3, n_forces / 3));
    }
    if (has_contacts) {
      write_contact_dynamics(out, model, data, contact, q, v, tau, restitution, derivatives);
    }
    out << "\n}\n";
    return 0;
  });
}
