// libFuzzer target of the IR writer (rbdc/ir_json.hpp): a model built from raw bytes (any names,
// any double bit patterns, any parent numbering) through build_model, whose IR must then be strict
// JSON; and every double, as json_number writes it, must read back to the same bits.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "fuzz_support.hpp"
#include "rbdc/ir_json.hpp"
#include "rbdc/model_builder.hpp"

namespace {

const char* const kSource = "fuzz-ir-spec";

double raw_double(FuzzedDataProvider& in) {
  const uint64_t bits = in.ConsumeIntegral<uint64_t>();
  double x;
  std::memcpy(&x, &bits, sizeof x);
  if (std::isfinite(x)) {
    const std::string text = rbdc::json_number(x);
    const double back = std::strtod(text.c_str(), nullptr);
    if (std::memcmp(&back, &x, sizeof x) != 0) {
      std::fprintf(stderr, "fuzz: json_number(%a) = %s reads back as %a\n", x, text.c_str(), back);
      std::abort();
    }
  }
  return x;
}

rbdc::Vector3 raw_vector(FuzzedDataProvider& in) {
  const double x = raw_double(in), y = raw_double(in);
  return {x, y, raw_double(in)};
}

rbdc::Body raw_body(FuzzedDataProvider& in) {
  rbdc::Body b;
  b.name = in.ConsumeRandomLengthString(12);
  b.mass = raw_double(in);
  b.com = raw_vector(in);
  const rbdc::Vector3 diagonal = raw_vector(in), off = raw_vector(in);
  b.inertia_com << diagonal.x(), off.z(), off.y(), off.z(), diagonal.y(), off.x(), off.y(), off.x(), diagonal.z();
  return b;
}

rbdc::JointSpec raw_joint(FuzzedDataProvider& in) {
  rbdc::JointSpec j;
  j.name = in.ConsumeRandomLengthString(12);
  j.type = in.ConsumeBool() ? rbdc::JointType::Prismatic : rbdc::JointType::Revolute;
  j.axis = raw_vector(in);
  const rbdc::Vector3 angles = raw_vector(in);  // a rotation from Euler angles: build_model wants E_T orthonormal
  j.rotation = (Eigen::AngleAxisd(angles.x(), rbdc::Vector3::UnitZ()) *
                Eigen::AngleAxisd(angles.y(), rbdc::Vector3::UnitY()) *
                Eigen::AngleAxisd(angles.z(), rbdc::Vector3::UnitX())).toRotationMatrix();
  j.translation = raw_vector(in);
  if (in.ConsumeBool()) {
    j.lower = raw_double(in);
    j.upper = raw_double(in);
  }
  return j;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  rbdc::ModelSpec spec;
  spec.source = kSource;
  spec.name = in.ConsumeRandomLengthString(12);
  spec.floating_base = in.ConsumeBool();
  const int nb = in.ConsumeIntegralInRange(1, 5);
  spec.bodies.push_back(raw_body(in));
  for (int i = 1; i < nb; ++i) {
    spec.pred.push_back(in.ConsumeIntegralInRange(-1, i));
    spec.succ.push_back(i);
    spec.joints.push_back(raw_joint(in));
    spec.bodies.push_back(raw_body(in));
  }
  if (in.ConsumeBool()) {
    spec.feet.push_back({in.ConsumeRandomLengthString(12), in.ConsumeIntegralInRange(-1, nb), raw_vector(in)});
  }
  rbdc_fuzz::expect_result_or_error(kSource, [&] {
    std::vector<std::string> warnings;
    rbdc_fuzz::check_ir(rbdc::build_model(spec, &warnings));
  });
  return 0;
}
