#include "rbdc/control/cubic_spline.hpp"

#include <algorithm>

namespace rbdc::control {

CubicSetPoint::CubicSetPoint(double t0, double angle0, double rate0, double t1, double target)
    : t0_(t0), duration_(std::max(t1 - t0, 1e-3)) {
  // Hermite cubic in s = t − t0 with θ(0) = angle0, θ'(0) = rate0, θ(T) = target, θ'(T) = 0.
  const double T = duration_, delta = target - angle0;
  a0_ = angle0;
  a1_ = rate0;
  a2_ = (3 * delta - 2 * rate0 * T) / (T * T);
  a3_ = (-2 * delta + rate0 * T) / (T * T * T);
}

SetPoint CubicSetPoint::at(double t) const {
  const double s = std::clamp(t - t0_, 0.0, duration_);
  SetPoint p;
  p.angle = a0_ + s * (a1_ + s * (a2_ + s * a3_));
  p.rate = (t - t0_ >= duration_) ? 0.0 : a1_ + s * (2 * a2_ + 3 * s * a3_);
  return p;
}

}  // namespace rbdc::control
