// libFuzzer target: a URDF file through load_urdf (read_urdf_outline, urdfdom, the translation and
// build_model), then the IR of what loads. Inputs of even length load with a floating base, odd ones
// fixed, so that mutations reach both.
#include "fuzz_support.hpp"
#include "rbdc/urdf_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const rbdc_fuzz::InputFile file(".urdf");
  const std::string& path = file.write(data, size);
  rbdc::UrdfOptions opts;
  opts.floating_base = size % 2 == 0;
  rbdc_fuzz::expect_result_or_error(path, [&] {
    std::vector<std::string> warnings;
    rbdc_fuzz::check_ir(rbdc::load_urdf(path, opts, &warnings));
  });
  return 0;
}
