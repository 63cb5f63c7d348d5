// Compiles generated MJCF into an mjModel and maps rbdc entities onto it (see mjcf_writer.hpp).
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "rbdc/mjcf/mjcf_writer.hpp"

namespace rbdc::mjcf {

MjModelPtr load_mjmodel(const Model& model, const MjcfOptions& options) {
  const std::string xml = write_mjcf(model, options);
  // mjVFS holds fixed-size name tables (megabytes): keep it off the stack.
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* file_name = "rbdc_model.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), file_name, static_cast<int>(xml.size())) != 0)
    throw std::runtime_error("load_mjmodel: MuJoCo's virtual file system refused the MJCF of '" +
                             model.name + "'");
  const int file = mj_findFileVFS(vfs.get(), file_name);
  std::memcpy(vfs->filedata[file], xml.data(), xml.size());
  char error[1000] = "";
  mjModel* m = mj_loadXML(file_name, vfs.get(), error, sizeof(error));
  mj_deleteVFS(vfs.get());
  if (m == nullptr)
    throw std::runtime_error("load_mjmodel: MuJoCo refused the MJCF of '" + model.name +
                             "': " + error);
  return MjModelPtr(m);
}

namespace {

int find(const mjModel* m, mjtObj type, const std::string& name, const char* what) {
  const int id = mj_name2id(m, type, name.c_str());
  if (id < 0)
    throw std::runtime_error(std::string("index_mjmodel: the mjModel has no ") + what + " '" +
                             name + "'");
  return id;
}

}  // namespace

MujocoIndex index_mjmodel(const Model& model, const mjModel* m) {
  MujocoIndex index;
  for (int i = 0; i < model.nb; ++i) {
    index.body.push_back(find(m, mjOBJ_BODY, model.bodies[i].name, "body"));
    const bool has_joint = i > 0 || model.floating_base;
    const int joint = has_joint ? find(m, mjOBJ_JOINT, model.joints[i].name, "joint") : -1;
    index.qpos.push_back(joint < 0 ? -1 : m->jnt_qposadr[joint]);
    index.dof.push_back(joint < 0 ? -1 : m->jnt_dofadr[joint]);
    index.actuator.push_back(i > 0 ? mj_name2id(m, mjOBJ_ACTUATOR, model.joints[i].name.c_str())
                                   : -1);
  }
  for (const Foot& foot : model.feet) index.foot_geom.push_back(find(m, mjOBJ_GEOM, foot.name, "geom"));
  return index;
}

std::vector<InertiaChange> adopt_mujoco_inertias(Model& model, const mjModel* m) {
  const MujocoIndex index = index_mjmodel(model, m);
  std::vector<InertiaChange> changes;
  model.inertia.resize(model.nb);
  for (int i = 0; i < model.nb; ++i) {
    const int b = index.body[i];
    Body& body = model.bodies[i];
    // MuJoCo keeps principal moments in a frame (body_ipos, body_iquat): I = R diag Rᵀ.
    const mjtNum* q = m->body_iquat + 4 * b;
    const Matrix3 R = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
    const Vector3 principal(m->body_inertia[3 * b], m->body_inertia[3 * b + 1],
                            m->body_inertia[3 * b + 2]);
    const Matrix3 after = R * principal.asDiagonal() * R.transpose();
    const double change = (after - body.inertia_com).norm() / body.inertia_com.norm();
    if (change > 1e-6) changes.push_back({body.name, body.inertia_com, after, change});
    body.mass = m->body_mass[b];
    body.com = Vector3(m->body_ipos[3 * b], m->body_ipos[3 * b + 1], m->body_ipos[3 * b + 2]);
    body.inertia_com = after;
    model.inertia[i] = spatial_inertia(body.mass, body.com, body.inertia_com);
  }
  return changes;
}

}  // namespace rbdc::mjcf
