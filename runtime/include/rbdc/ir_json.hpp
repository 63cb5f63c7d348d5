// The rbdc IR (docs/ir.md): the validated Model as sorted, byte-stable JSON for the generator.
#pragma once

#include <string>

#include "rbdc/model.hpp"

namespace rbdc {

/// The IR of `model`: keys sorted, numbers with 17 significant digits (exact round trip),
/// independent of the locale, ending with a newline.
std::string to_ir_json(const Model& model);

/// One JSON number: shortest form of 17 significant digits ("%.17g" without the locale).
std::string json_number(double x);

}  // namespace rbdc
