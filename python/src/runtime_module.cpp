// rbdc._runtime: the reference runtime (runtime/) behind rbdc.Model (python/rbdc/model.py). Each
// algorithm is a row of a table (name, arguments with their shapes, the call); the numpy boundary,
// batches and threads are rbdc_py/batch_call.hpp's, with one Data per thread. docs/python.md.
#include <pybind11/stl.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "rbdc/rbdc.hpp"
#include "rbdc/topology_file.hpp"
#include "rbdc/urdf_loader.hpp"
#include "rbdc_py/batch_call.hpp"

namespace {

namespace py = pybind11;
using rbdc::MatrixX;
using rbdc::Model;
using rbdc::VectorX;

/// One thread's workspace: the runtime's Data and DerivativeData, and the foot forces as the
/// Matrix3X the algorithms take.
struct Workspace {
  rbdc::Data data;
  rbdc::DerivativeData derivatives;
  rbdc::Matrix3X f;
  explicit Workspace(const Model& model)
      : data(model), derivatives(model), f(3, static_cast<Eigen::Index>(model.feet.size())) {}
};

using Run = std::function<void(const Model&, Workspace&, const double* const* in, double* const* out)>;

struct Algorithm {
  rbdc_py::FunctionSpec spec;
  std::vector<const char*> docs;  ///< inputs then outputs
  const char* doc;
  Run run;
};

Eigen::Map<const VectorX> vec(const double* x, int n) { return Eigen::Map<const VectorX>(x, n); }
Eigen::Map<MatrixX> mat(double* x, Eigen::Index rows, Eigen::Index cols) { return Eigen::Map<MatrixX>(x, rows, cols); }
const rbdc::Matrix3X& forces(Workspace& w, const double* f) {
  w.f = Eigen::Map<const rbdc::Matrix3X>(f, 3, w.f.cols());
  return w.f;
}

/// The table of the runtime's algorithms for one model (dimensions are the model's).
std::map<std::string, Algorithm> algorithms(const Model& model) {
  const int nq = model.nq, nv = model.nv, nj = model.num_joints(), nf = static_cast<int>(model.feet.size());
  const int quaternion = model.floating_base ? 3 : -1;
  const rbdc_py::ArgSpec q{"q", nq, 1, quaternion}, v{"v", nv, 1}, a{"a", nv, 1}, tau{"tau", nj, 1}, f{"f", 3, nf, -1, true};
  const char *dq = "configuration (position, quaternion w x y z, joints) or joint positions",
             *dv = "velocity (trunk ω, v in trunk coordinates, joints) or joint velocities",
             *da = "acceleration, ordered like v", *dtau = "joint torques / forces",
             *df = "foot forces, world frame, one column per foot";
  auto out = [](const char* name, int rows, int cols) { return rbdc_py::ArgSpec{name, rows, cols, -1, cols != 1}; };
  auto feet = [](const char* name, int n_feet) { return rbdc_py::ArgSpec{name, 3, n_feet, -1, true}; };
  std::map<std::string, Algorithm> table;
  auto add = [&](const char* name, std::vector<rbdc_py::ArgSpec> in, std::vector<rbdc_py::ArgSpec> outs,
                 std::vector<const char*> docs, const char* doc, Run run) {
    table[name] = Algorithm{rbdc_py::FunctionSpec{name, std::move(in), std::move(outs)}, std::move(docs), doc, std::move(run)};
  };
  add("feet_positions", {q}, {feet("p", nf)}, {dq, "foot positions, world frame"}, "Feet positions (paper 000 Eq. 18).",
      [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        mat(o[0], 3, w.f.cols()) = rbdc::feet_positions(m, w.data, vec(in[0], m.nq));
      });
  add("feet_velocities", {q, v}, {feet("pdot", nf)}, {dq, dv, "foot velocities, world frame"},
      "Feet linear velocities (paper 000 Eq. 37).", [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        mat(o[0], 3, w.f.cols()) = rbdc::feet_velocities(m, w.data, vec(in[0], m.nq), vec(in[1], m.nv));
      });
  add("feet_bias_accelerations", {q, v}, {feet("pddot", nf)}, {dq, dv, "J̇ v per foot, world frame"},
      "Feet accelerations at a = 0 (J̇ v).", [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        mat(o[0], 3, w.f.cols()) = rbdc::feet_bias_accelerations(m, w.data, vec(in[0], m.nq), vec(in[1], m.nv));
      });
  add("feet_jacobian", {q}, {out("J", 3 * nf, nv)}, {dq, "stacked 3 x nv foot Jacobians, world frame"},
      "Feet Jacobian (paper 000 Alg. 6).", [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        mat(o[0], 3 * w.f.cols(), m.nv) = rbdc::feet_jacobian(m, w.data, vec(in[0], m.nq));
      });
  add("quadratic_velocity_terms", {q, v}, {out("c", nv, 1)}, {dq, dv, "quadratic velocity terms"},
      "Quadratic velocity terms c (paper 000 Alg. 2).", [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        mat(o[0], m.nv, 1) = rbdc::quadratic_velocity_terms(m, w.data, vec(in[0], m.nq), vec(in[1], m.nv));
      });
  add("gravity_terms", {q}, {out("g", nv, 1)}, {dq, "gravity terms"}, "Gravity terms g (paper 000 Alg. 3).",
      [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        mat(o[0], m.nv, 1) = rbdc::gravity_terms(m, w.data, vec(in[0], m.nq));
      });
  add("feet_force_terms", {q, f}, {out("tau_e", nv, 1)}, {dq, df, "Jᵀ f"}, "Foot force terms τ_e = Jᵀ f (paper 000 Alg. 4).",
      [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        mat(o[0], m.nv, 1) = rbdc::feet_force_terms(m, w.data, vec(in[0], m.nq), forces(w, in[1]));
      });
  add("inverse_dynamics", {q, v, a}, {out("tau", nv, 1)}, {dq, dv, da, "generalised forces M a + c + g"},
      "Inverse dynamics M a + c + g (RNEA, paper 000 Algs. 2-3).",
      [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        mat(o[0], m.nv, 1) = rbdc::inverse_dynamics(m, w.data, vec(in[0], m.nq), vec(in[1], m.nv), vec(in[2], m.nv));
      });
  add("mass_matrix", {q}, {out("M", nv, nv)}, {dq, "joint-space inertia matrix"}, "Mass matrix M (CRBA, paper 000 Alg. 5).",
      [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        mat(o[0], m.nv, m.nv) = rbdc::mass_matrix(m, w.data, vec(in[0], m.nq));
      });
  add("forward_dynamics", {q, v, tau, f}, {out("a", nv, 1)}, {dq, dv, dtau, df, "acceleration M⁻¹(Sᵀτ + Jᵀf − c − g)"},
      "Forward dynamics (paper 000 Eq. 43).", [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        mat(o[0], m.nv, 1) = rbdc::forward_dynamics(m, w.data, vec(in[0], m.nq), vec(in[1], m.nv),
                                                    vec(in[2], m.num_joints()), forces(w, in[3]));
      });
  add("inverse_dynamics_derivatives", {q, v, a}, {out("dtau_dq", nv, nv), out("dtau_dv", nv, nv)},
      {dq, dv, da, "∂τ/∂q on the manifold", "∂τ/∂v"}, "Derivatives of inverse dynamics (∂τ/∂a is M).",
      [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        rbdc::inverse_dynamics_derivatives(m, w.data, w.derivatives, vec(in[0], m.nq), vec(in[1], m.nv), vec(in[2], m.nv));
        mat(o[0], m.nv, m.nv) = w.derivatives.dtau_dq;
        mat(o[1], m.nv, m.nv) = w.derivatives.dtau_dv;
      });
  add("bias_derivatives", {q, v}, {out("dbias_dq", nv, nv), out("dbias_dv", nv, nv)}, {dq, dv, "∂(c + g)/∂q", "∂(c + g)/∂v"},
      "Derivatives of the bias c + g.", [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        rbdc::bias_derivatives(m, w.data, w.derivatives, vec(in[0], m.nq), vec(in[1], m.nv));
        mat(o[0], m.nv, m.nv) = w.derivatives.dbias_dq;
        mat(o[1], m.nv, m.nv) = w.derivatives.dbias_dv;
      });
  add("gravity_derivatives", {q}, {out("dg_dq", nv, nv)}, {dq, "∂g/∂q"}, "Derivative of the gravity terms.",
      [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        rbdc::gravity_derivatives(m, w.data, w.derivatives, vec(in[0], m.nq));
        mat(o[0], m.nv, m.nv) = w.derivatives.dg_dq;
      });
  add("forward_dynamics_derivatives", {q, v, tau, f},
      {out("da_dq", nv, nv), out("da_dv", nv, nv), out("da_dtau", nv, nj), out("da_df", nv, 3 * nf)},
      {dq, dv, dtau, df, "∂a/∂q", "∂a/∂v", "∂a/∂τ = M⁻¹Sᵀ", "∂a/∂f = M⁻¹Jᵀ (column 3k + c: foot k, axis c)"},
      "Derivatives of forward dynamics.", [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        rbdc::forward_dynamics_derivatives(m, w.data, w.derivatives, vec(in[0], m.nq), vec(in[1], m.nv),
                                           vec(in[2], m.num_joints()), forces(w, in[3]));
        const auto& d = w.derivatives;
        mat(o[0], m.nv, m.nv) = d.da_dq;
        mat(o[1], m.nv, m.nv) = d.da_dv;
        mat(o[2], m.nv, m.num_joints()) = d.da_dtau;
        mat(o[3], m.nv, d.da_df.cols()) = d.da_df;
      });
  add("feet_velocity_derivatives", {q, v}, {out("dpdot_dq", 3 * nf, nv)}, {dq, dv, "∂(foot velocities)/∂q"},
      "Derivative of the feet velocities.", [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        rbdc::feet_velocity_derivatives(m, w.data, w.derivatives, vec(in[0], m.nq), vec(in[1], m.nv));
        mat(o[0], w.derivatives.dpdot_dq.rows(), m.nv) = w.derivatives.dpdot_dq;
      });
  add("feet_force_term_derivatives", {q, f}, {out("dtau_e_dq", nv, nv)}, {dq, df, "∂(Jᵀf)/∂q at fixed f"},
      "Derivative of the foot force terms.", [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
        rbdc::feet_force_term_derivatives(m, w.data, w.derivatives, vec(in[0], m.nq), forces(w, in[1]));
        mat(o[0], m.nv, m.nv) = w.derivatives.dtau_e_dq;
      });
  if (model.floating_base) {
    add("osc_open_chain", {q, v, f}, {out("Lambda", 6, 6), out("JbarT", 6, nj), out("b", 6, 1)},
        {dq, dv, df, "operational-space inertia Λ", "J̄ᵀ", "bias b"}, "Trunk operational-space quantities (paper 001 Table 1).",
        [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
          const auto& r = rbdc::osc_open_chain(m, w.data, vec(in[0], m.nq), vec(in[1], m.nv), forces(w, in[2]));
          mat(o[0], 6, 6) = r.Lambda;
          mat(o[1], 6, m.num_joints()) = r.JbarT;
          mat(o[2], 6, 1) = r.b;
        });
    add("osc_closed_chain", {q, v, rbdc_py::ArgSpec{"ground_mass", 1, 1}},
        {out("Lambda", 6, 6), out("JbarT", 6, nj), out("b", 6, 1)},
        {dq, dv, "ground inertia of the big-ground-inertia approximation", "Λ", "J̄ᵀ", "b"},
        "Trunk operational-space quantities with every foot in contact (paper 001 Table 2).",
        [](const Model& m, Workspace& w, const double* const* in, double* const* o) {
          std::vector<int> feet(m.feet.size());
          for (size_t k = 0; k < feet.size(); ++k) feet[k] = static_cast<int>(k);
          const auto& r = rbdc::osc_closed_chain(m, w.data, vec(in[0], m.nq), vec(in[1], m.nv), feet, *in[2]);
          mat(o[0], 6, 6) = r.Lambda;
          mat(o[1], 6, m.num_joints()) = r.JbarT;
          mat(o[2], 6, 1) = r.b;
        });
  }
  add("integrate", {q, rbdc_py::ArgSpec{"delta", nv, 1}}, {out("q_next", nq, 1)}, {dq, "tangent step, ordered like v", "q ⊕ δ"},
      "q ⊕ δ on the configuration manifold (docs/conventions.md).",
      [](const Model& m, Workspace&, const double* const* in, double* const* o) {
        Eigen::Map<VectorX> next(o[0], m.nq);
        rbdc::integrate(m, vec(in[0], m.nq), vec(in[1], m.nv), next);
      });
  return table;
}

/// A loaded model with its algorithm table; a batch kernel per algorithm, with Data per thread.
struct PyModel {
  std::shared_ptr<const Model> model;
  std::map<std::string, Algorithm> table;

  struct Kernel {
    const Model* model;
    const Run* run;
    struct Worker {
      const Model* model;
      const Run* run;
      std::unique_ptr<Workspace> workspace;
      void operator()(const double* const* in, double* const* out) { (*run)(*model, *workspace, in, out); }
    };
    Worker worker() const { return Worker{model, run, std::make_unique<Workspace>(*model)}; }
  };

  py::object call(const std::string& name, const py::tuple& inputs, py::handle out, int threads) const {
    const auto found = table.find(name);
    if (found == table.end()) throw py::value_error("rbdc: the runtime has no algorithm '" + name + "'");
    const Algorithm& algorithm = found->second;
    if (inputs.size() != algorithm.spec.inputs.size())
      throw py::type_error("rbdc: " + name + " takes " + std::to_string(algorithm.spec.inputs.size()) + " inputs");
    std::vector<py::handle> values(inputs.begin(), inputs.end());
    const Kernel kernel{model.get(), &algorithm.run};
    const rbdc_py::Runner runner{&rbdc_py::run_kernel<Kernel, double, rbdc_py::NoPack, 1>, nullptr, &kernel,
                                 &rbdc_py::run_one<Kernel>};
    return rbdc_py::call(algorithm.spec, runner, values.data(), out, threads);
  }
};

rbdc::MimicMode mimic_mode(const std::string& mimic) {
  if (mimic == "couple") return rbdc::MimicMode::Couple;
  if (mimic == "lock") return rbdc::MimicMode::Lock;
  if (mimic == "independent") return rbdc::MimicMode::Independent;
  throw py::value_error("rbdc: mimic must be 'couple', 'lock' or 'independent', not '" + mimic + "'");
}

/// Loads a URDF (or a standalone topology file) as the command-line tools do; returns the model
/// and the loader's warnings ("<file>:<line>: <element>: <problem>").
py::tuple load(const std::string& path, bool floating_base, const std::string& topology, const std::string& mimic,
               const std::string& root, const std::map<std::string, double>& locked) {
  std::vector<std::string> warnings;
  rbdc::UrdfOptions options;
  options.floating_base = floating_base;
  options.topology_file = topology;
  options.mimic = mimic_mode(mimic);
  options.root_link = root;
  options.locked_joints = locked;
  auto model = std::make_shared<Model>(rbdc::is_topology_path(path) ? rbdc::load_topology(path, &warnings)
                                                                     : rbdc::load_urdf(path, options, &warnings));
  PyModel result{model, algorithms(*model)};
  return py::make_tuple(std::move(result), warnings);
}

std::vector<std::string> names_of(const std::vector<rbdc::Joint>& joints) {
  std::vector<std::string> names;
  for (const auto& j : joints) names.push_back(j.name);
  return names;
}

}  // namespace

PYBIND11_MODULE(_runtime, m) {
  m.doc() = "rbdc's reference runtime (runtime/), used by rbdc.Model";
  py::register_exception<rbdc::ModelError>(m, "ModelError", PyExc_ValueError);
  m.def("load", &load, py::arg("path"), py::arg("floating_base"), py::arg("topology"), py::arg("mimic"),
        py::arg("root"), py::arg("locked"));
  py::class_<PyModel>(m, "Model")
      .def_property_readonly("name", [](const PyModel& p) { return p.model->name; })
      .def_property_readonly("floating_base", [](const PyModel& p) { return p.model->floating_base; })
      .def_property_readonly("nq", [](const PyModel& p) { return p.model->nq; })
      .def_property_readonly("nv", [](const PyModel& p) { return p.model->nv; })
      .def_property_readonly("nb", [](const PyModel& p) { return p.model->nb; })
      .def_property_readonly("n_joints", [](const PyModel& p) { return p.model->num_joints(); })
      .def_property_readonly("n_feet", [](const PyModel& p) { return p.model->feet.size(); })
      .def_property_readonly("joint_names", [](const PyModel& p) { return names_of(p.model->joints); })
      .def_property_readonly("body_names", [](const PyModel& p) {
        std::vector<std::string> names;
        for (const auto& b : p.model->bodies) names.push_back(b.name);
        return names;
      })
      .def_property_readonly("foot_names", [](const PyModel& p) {
        std::vector<std::string> names;
        for (const auto& foot : p.model->feet) names.push_back(foot.name);
        return names;
      })
      .def_property_readonly("gravity", [](const PyModel& p) {
        return py::array_t<double>(3, p.model->gravity.data());
      })
      .def_property_readonly("default_ground_mass", [](const PyModel& p) { return rbdc::default_ground_mass(*p.model); })
      .def("algorithms", [](const PyModel& p) {
        py::list rows;  // (name, inputs, outputs, doc); inputs and outputs as (name, shape doc)
        for (const auto& [name, algorithm] : p.table) {
          py::list inputs, outputs;
          size_t k = 0;
          for (const auto& a : algorithm.spec.inputs) inputs.append(py::make_tuple(a.name, a.rows, a.cols, algorithm.docs[k++]));
          for (const auto& a : algorithm.spec.outputs) outputs.append(py::make_tuple(a.name, a.rows, a.cols, algorithm.docs[k++]));
          rows.append(py::make_tuple(name, inputs, outputs, algorithm.doc));
        }
        return rows;
      })
      .def("call", &PyModel::call, py::arg("name"), py::arg("inputs"), py::arg("out"), py::arg("threads"));
}
