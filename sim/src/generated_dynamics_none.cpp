// Built when generated/mini_cheetah/full.hpp is not available: no generated dynamics.
#include "rbdc/sim/dynamics.hpp"

namespace rbdc::sim {

std::unique_ptr<DynamicsModel> make_generated_dynamics() { return nullptr; }

}  // namespace rbdc::sim
