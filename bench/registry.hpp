// The benchmark cases: one per robot, quantity and implementation, named "robot/quantity/impl".
// A case is a plain function pointer called with its context and a state index, so every timed call
// goes through a call the compiler cannot inline or hoist. Implementations register a provider (run
// from main, after the command line is read) that loads its robots and adds its cases; an
// implementation whose CMake target is missing simply has no provider linked in.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace rbdc_bench {

/// States pre-generated per robot and cycled (a power of two, so the index wraps with a mask).
constexpr int kStateCount = 1024;

using CallFn = void (*)(void* context, int state);

struct Case {
  std::string robot, quantity, implementation;
  std::shared_ptr<void> context;  ///< owns what `call` reads and writes
  CallFn call;
  std::string name() const { return robot + "/" + quantity + "/" + implementation; }
};

std::vector<Case>& cases();

void add_case(const std::string& robot, const std::string& quantity,
              const std::string& implementation, std::shared_ptr<void> context, CallFn call);

using Provider = void (*)();

/// Static registration of a provider; returns a dummy so it can initialise a namespace-scope bool.
bool register_provider(Provider provider);
const std::vector<Provider>& providers();

}  // namespace rbdc_bench
