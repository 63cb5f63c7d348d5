// rbdc::check_finite(x, y, …): true when every entry of every argument is finite (no NaN, no Inf).
// The algorithms themselves do not test their inputs for NaN (a NaN in gives NaN out, never a
// crash); callers that must refuse such inputs, e.g. a controller reading sensors, call this first.
// Cost: one pass over the entries, no allocation.
#pragma once

#include <Eigen/Core>

namespace rbdc {

template <class Derived>
bool check_finite(const Eigen::DenseBase<Derived>& x) {
  return x.allFinite();
}

template <class First, class Second, class... Rest>
bool check_finite(const First& first, const Second& second, const Rest&... rest) {
  return check_finite(first) && check_finite(second, rest...);
}

}  // namespace rbdc
