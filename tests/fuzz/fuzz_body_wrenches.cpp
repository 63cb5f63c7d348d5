// libFuzzer target: a body-wrench JSON file (rbdc/body_wrenches_file.hpp) for the fixed robot of
// base_robot.hpp.
#include "base_robot.hpp"
#include "fuzz_support.hpp"
#include "rbdc/body_wrenches_file.hpp"
#include "rbdc/urdf_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const rbdc_fuzz::InputFile file(".json");
  static const rbdc::Model model = rbdc::load_urdf(rbdc_fuzz::base_robot_urdf());
  const std::string& path = file.write(data, size);
  rbdc_fuzz::expect_result_or_error(path, [&] { rbdc::read_body_wrenches(path, model); });
  return 0;
}
