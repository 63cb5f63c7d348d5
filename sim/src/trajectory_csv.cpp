#include "rbdc/sim/trajectory_csv.hpp"

#include "rbdc/sim/orientation.hpp"

namespace rbdc::sim {

TrajectoryCsv::TrajectoryCsv(const std::string& path, const Model& model)
    : file_(path), out_(file_.stream()), n_joints_(model.nv - 6) {
  out_.precision(9);
  out_ << "t,x,y,z,roll,pitch,yaw";
  for (int i = 1; i < model.nb; ++i) out_ << ",q_" << model.joints[i].name;
  for (int i = 1; i < model.nb; ++i) out_ << ",dq_" << model.joints[i].name;
  for (const Foot& foot : model.feet)
    out_ << ',' << foot.name << "_contact," << foot.name << "_fx," << foot.name << "_fy,"
         << foot.name << "_fz";
  out_ << '\n';
}

void TrajectoryCsv::write(double t, const VectorX& q, const VectorX& v,
                          const std::vector<FootContact>& contacts) {
  const Vector3 xi = zyx_from_rotation(rotation_from_quaternion(q.segment<4>(3)));
  out_ << t << ',' << q[0] << ',' << q[1] << ',' << q[2] << ',' << xi[2] << ',' << xi[1] << ','
       << xi[0];
  for (int j = 0; j < n_joints_; ++j) out_ << ',' << q[7 + j];
  for (int j = 0; j < n_joints_; ++j) out_ << ',' << v[6 + j];
  for (const FootContact& c : contacts)
    out_ << ',' << (c.active ? 1 : 0) << ',' << c.force_W.x() << ',' << c.force_W.y() << ','
         << c.force_W.z();
  out_ << '\n';
}

}  // namespace rbdc::sim
