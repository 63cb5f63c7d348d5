// rbdc-model: load and validate a robot, write its IR (docs/ir.md) for the generator.
#include <fstream>
#include <iostream>

#include "check_report.hpp"
#include "rbdc/ir_json.hpp"
#include "tool_options.hpp"

int main(int argc, char** argv) {
  using namespace rbdc::tools;
  return run_tool([&] {
    LoadOptions opts;
    std::string output;
    bool check = false;
    const ExtraOption output_option = [&](int n, char** args, int& i) {
      const std::string arg = args[i];
      if (arg == "--check") return check = true;
      if (arg != "-o" && arg != "--output") return false;
      if (i + 1 >= n) throw std::invalid_argument(arg + " needs a file name");
      output = args[++i];
      return true;
    };
    if (!parse_load_options(argc, argv, opts, output_option)) {
      std::cout << "usage: rbdc-model ROBOT [options] [-o IR.json | --check]\n"
                   "Loads and validates a robot and writes its IR (rbdc-ir-1 JSON, docs/ir.md).\n"
                   "Warnings go to stderr as 'warning: …'; errors as 'error: …' with exit code 2.\n\n"
                << kLoadOptionsHelp << "  -o, --output FILE   write the IR to FILE (default: stdout)\n"
                   "  --check             lint instead: every warning and the error with file:line, then\n"
                   "                      the topology (PRED, SUCC, lambda, DoF, mass) on stdout; exit 2\n"
                   "                      only when the robot is refused\n";
      return 0;
    }
    if (check) return write_check_report(opts, std::cout);
    const std::string ir = rbdc::to_ir_json(load_model(opts));
    if (output.empty()) {
      std::cout << ir;
      return 0;
    }
    std::ofstream out(output, std::ios::binary);
    out << ir;
    out.close();
    if (!out) throw std::runtime_error("cannot write '" + output + "'");
    return 0;
  });
}
