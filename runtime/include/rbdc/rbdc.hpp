// Umbrella header of the rbdc runtime: the model, its loaders and every reference algorithm.
#pragma once

#include "rbdc/actuator_mode.hpp"
#include "rbdc/bias_terms.hpp"
#include "rbdc/check_finite.hpp"
#include "rbdc/coupling.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/data.hpp"
#include "rbdc/derivatives.hpp"
#include "rbdc/forward_dynamics.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "rbdc/jacobian.hpp"
#include "rbdc/kinematics.hpp"
#include "rbdc/manifold.hpp"
#include "rbdc/model.hpp"
#include "rbdc/model_builder.hpp"
#include "rbdc/osc.hpp"
#include "rbdc/spatial.hpp"
