// Every URDF in the conformance corpus (RBDC_ROBOT_CORPUS, docs/model.md) loads with the default
// options — a refusal fails the test — with the total mass its file states, the DoF known for the
// public robots, and dynamics that pass identities in the independent coordinates of its mimic
// couplings: M' = GᵀMG symmetric positive definite, forward dynamics undone by the RNEA.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <sstream>

#include "rbdc/coupling.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "rbdc/urdf_loader.hpp"

namespace rbdc {
namespace {

std::vector<std::string> corpus_files() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(RBDC_ROBOT_CORPUS)) {
    if (entry.path().extension() == ".urdf") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// The sum of the file's <mass value="…"/> texts: a route independent of urdfdom and of the lumping.
double mass_in_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::regex mass(R"(<mass\s+value\s*=\s*["']([^"']+)["'])");
  double sum = 0;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), mass); it != std::sregex_iterator(); ++it) {
    sum += std::stod((*it)[1]);
  }
  return sum;
}

/// Independent joint DoF (mimic followers coupled) of the public robots of ../shared/robots.
const std::map<std::string, int> kKnownDofs{{"anymal_b", 12}, {"solo12", 12}, {"mini_cheetah_pybullet", 12},
                                            {"iiwa14", 7},    {"panda", 8},   {"talos", 32}};

class CorpusRobot : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusRobot, LoadsByDefaultWithItsMassAndDofs) {
  const std::string path = GetParam();
  std::vector<std::string> warnings;
  const Model m = load_urdf(path, {}, &warnings);  // a refusal throws: a failure, never a skip
  for (const std::string& w : warnings) std::cout << "warning: " << w << "\n";
  double mass = 0;
  for (const Body& b : m.bodies) mass += b.mass;
  EXPECT_NEAR(mass, mass_in_file(path), 1e-9 * mass);
  const auto known = kKnownDofs.find(std::filesystem::path(path).stem().string());
  if (known != kKnownDofs.end()) {
    EXPECT_EQ(coupled_coordinates(m).num_joints(), known->second);
  }
  UrdfOptions opts;
  opts.mimic = MimicMode::Independent;
  EXPECT_EQ(load_urdf(path, opts).num_joints(), m.num_joints());
  opts.mimic = MimicMode::Lock;
  EXPECT_LE(load_urdf(path, opts).num_joints(), m.num_joints() - static_cast<int>(m.couplings.size()));
}

TEST_P(CorpusRobot, CoupledDynamicsPassTheIdentities) {
  const Model m = load_urdf(GetParam());
  Data data(m);
  const CoupledCoordinates c = coupled_coordinates(m);
  const MatrixX G = coupling_matrix(m);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  VectorX q = VectorX::NullaryExpr(c.nq, [&] { return uniform(rng); });
  if (m.floating_base) q.segment<4>(3).normalize();
  const VectorX v = VectorX::NullaryExpr(c.nv, [&] { return uniform(rng); });
  const VectorX tau = VectorX::NullaryExpr(c.num_joints(), [&] { return 10 * uniform(rng); });
  const VectorX q_tree = expand_configuration(m, q);
  const MatrixX M = G.transpose() * mass_matrix(m, data, q_tree) * G;
  EXPECT_TRUE(M.isApprox(M.transpose(), 1e-14));
  EXPECT_EQ(Eigen::LLT<MatrixX>(M).info(), Eigen::Success) << "M' is not positive definite";
  const Matrix3X no_forces = Matrix3X::Zero(3, static_cast<Eigen::Index>(m.feet.size()));
  const VectorX a = coupled_forward_dynamics(m, data, q, v, tau, no_forces);
  const VectorX projected = G.transpose() * inverse_dynamics(m, data, q_tree, G * v, G * a);
  VectorX applied = VectorX::Zero(c.nv);
  applied.tail(c.num_joints()) = tau;
  const double scale = std::max(1.0, projected.cwiseAbs().maxCoeff());
  EXPECT_LT((projected - applied).cwiseAbs().maxCoeff(), 1e-9 * scale);
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusRobot, ::testing::ValuesIn(corpus_files()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = std::filesystem::path(info.param).stem().string();
                           for (char& ch : name) {
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace rbdc
