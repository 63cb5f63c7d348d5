// libFuzzer target: a topology YAML file read both ways (docs/model.md, "Topology files"): as a
// standalone model (load_topology) and as the overlay of a fixed URDF (base_robot.hpp); what loads
// is written as IR.
#include "base_robot.hpp"
#include "fuzz_support.hpp"
#include "rbdc/topology_file.hpp"
#include "rbdc/urdf_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const rbdc_fuzz::InputFile file(".yaml");
  const std::string& urdf = rbdc_fuzz::base_robot_urdf();
  const std::string& path = file.write(data, size);
  std::vector<std::string> warnings;
  rbdc_fuzz::expect_result_or_error(path, [&] { rbdc_fuzz::check_ir(rbdc::load_topology(path, &warnings)); });
  rbdc_fuzz::expect_result_or_error(path, [&] {
    rbdc::UrdfOptions opts;
    opts.topology_file = path;
    rbdc_fuzz::check_ir(rbdc::load_urdf(urdf, opts, &warnings));
  });
  return 0;
}
