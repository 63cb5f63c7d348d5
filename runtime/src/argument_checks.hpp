// Entry checks shared by the runtime algorithms: wrong dimensions throw std::invalid_argument
// naming the function and the argument (the error path is the only one that allocates).
#pragma once

#include <stdexcept>
#include <string>

#include "rbdc/data.hpp"

namespace rbdc::detail {

inline void check_size(const char* function, const char* argument, Eigen::Index actual,
                       Eigen::Index expected) {
  if (actual != expected) {
    throw std::invalid_argument(std::string("rbdc::") + function + ": " + argument + " has " +
                                std::to_string(actual) + " entries, expected " +
                                std::to_string(expected));
  }
}

inline void check_data(const char* function, const Model& model, const Data& data) {
  if (static_cast<int>(data.v.size()) != model.nb || data.c.size() != model.nv ||
      data.feet_position.cols() != static_cast<Eigen::Index>(model.feet.size()) ||
      data.frame_position.cols() != static_cast<Eigen::Index>(model.frames.size())) {
    throw std::invalid_argument(std::string("rbdc::") + function +
                                ": data was built for a different model than '" + model.name +
                                "'");
  }
}

inline void check_q(const char* function, const Model& model, const Data& data, const VectorRef& q) {
  check_data(function, model, data);
  check_size(function, "q", q.size(), model.nq);
}

inline void check_qv(const char* function, const Model& model, const Data& data, const VectorRef& q,
                     const VectorRef& v) {
  check_q(function, model, data, q);
  check_size(function, "v", v.size(), model.nv);
}

inline void check_feet_matrix(const char* function, const char* argument, const Model& model,
                              const Matrix3X& f) {
  check_size(function, argument, f.cols(), static_cast<Eigen::Index>(model.feet.size()));
}

// Functions that need M⁻¹ refuse a model whose M is singular (Model::singular_mass_matrix).
inline void check_invertible_mass(const char* function, const Model& model) {
  if (!model.singular_mass_matrix.empty()) {
    throw std::invalid_argument(std::string("rbdc::") + function + ": model '" + model.name + "': " +
                                model.singular_mass_matrix + "; this function needs M⁻¹ (docs/model.md, "
                                "\"Singular mass matrix\")");
  }
}

}  // namespace rbdc::detail
