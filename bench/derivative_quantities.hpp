// The six derivative quantities of scenes/derivatives.yaml as stacked Jacobians, the one layout that
// every implementation fills (generated code in any scalar, the runtime, dual numbers, central
// differences): a quantity's result is one column-major block of `rows` × `columns`, its columns the
// directions q tangent (nv, ordered like v), then the plain inputs it differentiates, in the order
// v, a, τ, f. The generated functions' separate outputs (∂/∂q, ∂/∂v, …) are consecutive column
// ranges of that block, its "parts" (dtau_dq, dtau_dv, …).
#pragma once

#include <array>
#include <string>
#include <type_traits>
#include <vector>

namespace rbdc_bench::derivatives {

enum class Quantity { inverse_dynamics, forward_dynamics, bias, gravity, feet_velocity, feet_force_term };
constexpr std::array<Quantity, 6> kQuantities = {Quantity::inverse_dynamics, Quantity::forward_dynamics,
                                                 Quantity::bias, Quantity::gravity,
                                                 Quantity::feet_velocity, Quantity::feet_force_term};

/// The generated function's name: "inverse_dynamics_derivatives", "bias_derivatives", …
const char* quantity_name(Quantity quantity);

/// The plain inputs of the primal functions, in direction order.
enum Input { kV = 0, kA = 1, kTau = 2, kF = 3 };
constexpr int kInputs = 4;

/// Whether `quantity` differentiates plain input `input` (every quantity differentiates q).
constexpr bool differentiates(Quantity quantity, int input) {
  switch (quantity) {
    case Quantity::inverse_dynamics:
    case Quantity::bias:
      return input == kV;
    case Quantity::forward_dynamics:
      return input == kV || input == kTau || input == kF;
    default:
      return false;
  }
}

/// The inputs of one state in scalar T: q, then v, a, τ, f (3 × n_feet, column-major).
template <class T>
struct Pointers {
  const T* q;
  std::array<const T*, kInputs> x;
};

/// Sizes of a robot's inputs and of a quantity's block.
template <class Api>
struct Shape {
  static constexpr std::array<int, kInputs> input_size = {Api::nv, Api::nv, Api::n_joints, 3 * Api::n_feet};
  static constexpr int rows(Quantity quantity) {
    return quantity == Quantity::feet_velocity ? 3 * Api::n_feet : Api::nv;
  }
  static constexpr int columns(Quantity quantity) {
    int n = Api::nv;
    for (int input = 0; input < kInputs; ++input)
      if (differentiates(quantity, input)) n += input_size[input];
    return n;
  }
  static constexpr int size(Quantity quantity) { return rows(quantity) * columns(quantity); }
};

/// A part of a block: the name of the generated output and its [begin, end) in the block.
struct Part {
  std::string name;
  int begin, end;
};

/// The parts of `quantity`'s block for a robot of these dimensions.
std::vector<Part> parts(Quantity quantity, int nv, int n_joints, int n_feet);

/// Calls `use(std::integral_constant<Quantity, quantity>{})`: a run-time quantity to a compile-time one.
template <class Use>
void dispatch(Quantity quantity, Use&& use) {
  using Q = Quantity;
  switch (quantity) {
    case Q::inverse_dynamics: use(std::integral_constant<Q, Q::inverse_dynamics>{}); break;
    case Q::forward_dynamics: use(std::integral_constant<Q, Q::forward_dynamics>{}); break;
    case Q::bias: use(std::integral_constant<Q, Q::bias>{}); break;
    case Q::gravity: use(std::integral_constant<Q, Q::gravity>{}); break;
    case Q::feet_velocity: use(std::integral_constant<Q, Q::feet_velocity>{}); break;
    case Q::feet_force_term: use(std::integral_constant<Q, Q::feet_force_term>{}); break;
  }
}

/// The primal function that `quantity` differentiates, in scalar T (c + g: inverse dynamics at
/// a = 0; ∂(Jᵀf)/∂q: the feet force terms), writing its `rows` outputs.
template <class Api, Quantity quantity, class T>
void primal(const Pointers<T>& x, T* out) noexcept {
  if constexpr (quantity == Quantity::inverse_dynamics) {
    Api::inverse_dynamics(x.q, x.x[kV], x.x[kA], out);
  } else if constexpr (quantity == Quantity::forward_dynamics) {
    Api::forward_dynamics(x.q, x.x[kV], x.x[kTau], x.x[kF], out);
  } else if constexpr (quantity == Quantity::bias) {
    const std::array<T, Api::nv> zero{};
    Api::inverse_dynamics(x.q, x.x[kV], zero.data(), out);
  } else if constexpr (quantity == Quantity::gravity) {
    Api::gravity_terms(x.q, out);
  } else if constexpr (quantity == Quantity::feet_velocity) {
    Api::feet_velocities(x.q, x.x[kV], out);
  } else {
    Api::feet_force_terms(x.q, x.x[kF], out);
  }
}

/// The generated derivative function of `quantity` in scalar T, writing its block.
template <class Api, Quantity quantity, class T>
void generated(const Pointers<T>& x, T* block) noexcept {
  constexpr int nv = Api::nv;
  if constexpr (quantity == Quantity::inverse_dynamics) {
    Api::inverse_dynamics_derivatives(x.q, x.x[kV], x.x[kA], block, block + nv * nv);
  } else if constexpr (quantity == Quantity::forward_dynamics) {
    Api::forward_dynamics_derivatives(x.q, x.x[kV], x.x[kTau], x.x[kF], block, block + nv * nv,
                                      block + 2 * nv * nv, block + (2 * nv + Api::n_joints) * nv);
  } else if constexpr (quantity == Quantity::bias) {
    Api::bias_derivatives(x.q, x.x[kV], block, block + nv * nv);
  } else if constexpr (quantity == Quantity::gravity) {
    Api::gravity_derivatives(x.q, block);
  } else if constexpr (quantity == Quantity::feet_velocity) {
    Api::feet_velocity_derivatives(x.q, x.x[kV], block);
  } else {
    Api::feet_force_term_derivatives(x.q, x.x[kF], block);
  }
}

}  // namespace rbdc_bench::derivatives
