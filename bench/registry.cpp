#include "registry.hpp"

#include <utility>

namespace rbdc_bench {

std::vector<Case>& cases() {
  static std::vector<Case> all;
  return all;
}

void add_case(const std::string& robot, const std::string& quantity,
              const std::string& implementation, std::shared_ptr<void> context, CallFn call) {
  cases().push_back({robot, quantity, implementation, std::move(context), call});
}

namespace {
std::vector<Provider>& provider_list() {
  static std::vector<Provider> list;
  return list;
}
}  // namespace

bool register_provider(Provider provider) {
  provider_list().push_back(provider);
  return true;
}

const std::vector<Provider>& providers() { return provider_list(); }

}  // namespace rbdc_bench
