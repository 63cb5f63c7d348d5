// No algorithm call touches the heap. This binary interposes the C allocator (malloc, calloc,
// realloc and the aligned variants) with counting versions: that sees Eigen's buffers (Eigen
// calls malloc directly) as well as operator new (libstdc++ forwards it to malloc), so std
// containers count too. Every call then runs between two reads of the counter with a Data that
// was sized once. Sanitizer builds bring their own allocator, so the test skips there.
#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <cstddef>

#include "rbdc/rbdc.hpp"
#include "test_robots.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define RBDC_COUNT_ALLOCATIONS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RBDC_COUNT_ALLOCATIONS 0
#endif
#endif
#ifndef RBDC_COUNT_ALLOCATIONS
#define RBDC_COUNT_ALLOCATIONS 1
#endif

namespace {
std::atomic<long> allocations{0};
}

#if RBDC_COUNT_ALLOCATIONS
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
void __libc_free(void*);

void* malloc(std::size_t size) noexcept {
  ++allocations;
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
  ++allocations;
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) noexcept {
  ++allocations;
  return __libc_realloc(p, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) noexcept {
  ++allocations;
  return __libc_memalign(alignment, size);
}
void* memalign(std::size_t alignment, std::size_t size) noexcept {
  ++allocations;
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) noexcept {
  ++allocations;
  *out = __libc_memalign(alignment, size);
  return *out ? 0 : ENOMEM;
}
void free(void* p) noexcept { __libc_free(p); }
}
#endif

namespace rbdc {
namespace {

template <class Call>
long allocations_during(Call&& call) {
  const long before = allocations.load();
  call();
  return allocations.load() - before;
}

TEST(Allocations, CounterSeesEigenAndStdAllocations) {
  if (!RBDC_COUNT_ALLOCATIONS) GTEST_SKIP() << "sanitizer build: allocator not interposed";
  EXPECT_GT(allocations_during([] { VectorX x(100); x.setZero(); }), 0);
  EXPECT_GT(allocations_during([] { std::vector<int> v(3); (void)v; }), 0);
}

class Allocations : public ::testing::TestWithParam<int> {
 protected:
  Model model = test::all_robots()[static_cast<size_t>(GetParam())];
};

TEST_P(Allocations, NoAlgorithmCallAllocates) {
  if (!RBDC_COUNT_ALLOCATIONS) GTEST_SKIP() << "sanitizer build: allocator not interposed";
  test::RandomState random(5);
  Data data(model);
  const VectorX q = random.configuration(model);
  const VectorX v = random.vector(model.nv);
  const VectorX a = random.vector(model.nv);
  const VectorX tau = random.vector(model.num_joints());
  const Matrix3X f = random.forces(model);
  const std::vector<Vector6> f_ext(static_cast<size_t>(model.nb), Vector6::Ones());
  const std::vector<Matrix3> world_R_contact(model.feet.size(), Matrix3::Identity());
  std::vector<int> contacts;
  for (int k = 0; k < static_cast<int>(model.feet.size()); ++k) contacts.push_back(k);
  const std::vector<int> some_contacts(contacts.begin(), contacts.begin() + 1);

  EXPECT_EQ(allocations_during([&] { kinematics(model, data, q, v); }), 0);
  EXPECT_EQ(allocations_during([&] { world_transforms(model, data, q); }), 0);
  EXPECT_EQ(allocations_during([&] { feet_positions(model, data, q); }), 0);
  EXPECT_EQ(allocations_during([&] { feet_velocities(model, data, q, v); }), 0);
  EXPECT_EQ(allocations_during([&] { feet_bias_accelerations(model, data, q, v); }), 0);
  EXPECT_EQ(allocations_during([&] { quadratic_velocity_terms(model, data, q, v); }), 0);
  EXPECT_EQ(allocations_during([&] { gravity_terms(model, data, q); }), 0);
  EXPECT_EQ(allocations_during([&] { external_wrench_terms(model, data, q, f_ext); }), 0);
  EXPECT_EQ(allocations_during([&] { feet_force_terms(model, data, q, f); }), 0);
  EXPECT_EQ(allocations_during([&] { inverse_dynamics(model, data, q, v, a); }), 0);
  EXPECT_EQ(allocations_during([&] { mass_matrix(model, data, q); }), 0);
  EXPECT_EQ(allocations_during([&] { feet_jacobian(model, data, q); }), 0);
  EXPECT_EQ(allocations_during([&] { feet_jacobian_contact(model, data, q, world_R_contact); }), 0);
  EXPECT_EQ(allocations_during([&] { forward_dynamics(model, data, q, v, tau, f); }), 0);
  EXPECT_EQ(allocations_during([&] { frame_placements(model, data, q); }), 0);
  EXPECT_EQ(allocations_during([&] { frame_velocities(model, data, q, v); }), 0);
  EXPECT_EQ(allocations_during([&] { frame_jacobians(model, data, q); }), 0);
  EXPECT_EQ(allocations_during([&] { frame_bias_accelerations(model, data, q, v); }), 0);
  EXPECT_EQ(allocations_during([&] { center_of_mass(model, data, q, v); }), 0);
  EXPECT_EQ(allocations_during([&] { center_of_mass_jacobian(model, data, q); }), 0);
  EXPECT_EQ(allocations_during([&] { centroidal_momentum_matrix(model, data, q); }), 0);
  EXPECT_EQ(allocations_during([&] { centroidal_bias(model, data, q, v); }), 0);
  EXPECT_EQ(allocations_during([&] { mass_matrix_inverse(model, data, q); }), 0);
  ContactDynamicsData contact(model, contacts, BaumgarteGains{10.0, 2.0});  // sized outside
  ContactDynamicsData no_contact(model, {});
  const Matrix3X anchors = f;
  EXPECT_EQ(allocations_during([&] { contact_dynamics(model, data, contact, q, v, tau, anchors); }), 0);
  EXPECT_EQ(allocations_during([&] { contact_dynamics(model, data, no_contact, q, v, tau); }), 0);
  EXPECT_EQ(allocations_during([&] { impulse_dynamics(model, data, contact, q, v, 0.5); }), 0);
  if (!model.floating_base) return;
  OscReferenceData ref(model);  // sized here, outside the counted calls
  EXPECT_EQ(allocations_during([&] { osc_open_chain(model, data, q, v, f); }), 0);
  EXPECT_EQ(allocations_during([&] { osc_closed_chain(model, data, q, v, contacts); }), 0);
  EXPECT_EQ(allocations_during([&] { osc_closed_chain(model, data, q, v, some_contacts, 1e6); }), 0);
  EXPECT_EQ(allocations_during([&] { osc_closed_form(model, data, ref, q, v, f); }), 0);
  EXPECT_EQ(allocations_during([&] { osc_closed_form_constrained(model, data, ref, q, v, contacts); }), 0);
  EXPECT_EQ(allocations_during([&] { osc_closed_form_constrained(model, data, ref, q, v, some_contacts); }), 0);
}

TEST_P(Allocations, NoDerivativeCallAllocates) {
  if (!RBDC_COUNT_ALLOCATIONS) GTEST_SKIP() << "sanitizer build: allocator not interposed";
  test::RandomState random(6);
  Data data(model);
  DerivativeData derivatives(model);
  const VectorX q = random.configuration(model);
  const VectorX v = random.vector(model.nv);
  const VectorX a = random.vector(model.nv);
  const VectorX tau = random.vector(model.num_joints());
  const Matrix3X f = random.forces(model);
  VectorX q_next(model.nq);
  DerivativeData& d = derivatives;
  EXPECT_EQ(allocations_during([&] { inverse_dynamics_derivatives(model, data, d, q, v, a); }), 0);
  EXPECT_EQ(allocations_during([&] { bias_derivatives(model, data, d, q, v); }), 0);
  EXPECT_EQ(allocations_during([&] { gravity_derivatives(model, data, d, q); }), 0);
  EXPECT_EQ(allocations_during([&] { forward_dynamics_derivatives(model, data, d, q, v, tau, f); }), 0);
  EXPECT_EQ(allocations_during([&] { feet_velocity_derivatives(model, data, d, q, v); }), 0);
  EXPECT_EQ(allocations_during([&] { feet_force_term_derivatives(model, data, d, q, f); }), 0);
  EXPECT_EQ(allocations_during([&] { integrate(model, q, v, q_next); }), 0);
  std::vector<int> contacts;
  for (int k = 0; k < static_cast<int>(model.feet.size()); ++k) contacts.push_back(k);
  ContactDynamicsData contact(model, contacts, BaumgarteGains{10.0, 2.0});  // sized outside
  EXPECT_EQ(allocations_during([&] { contact_dynamics_derivatives(model, data, d, contact, q, v, tau, f); }), 0);
}

INSTANTIATE_TEST_SUITE_P(Robots, Allocations, ::testing::Range(0, 4));

}  // namespace
}  // namespace rbdc
