// rbdc-bench: times every registered case with Google Benchmark (all Google Benchmark flags apply),
// or, with --count-instructions=N, runs each case N times between callgrind client requests so that
//   valgrind --tool=callgrind --collect-atstart=no rbdc-bench --count-instructions=N
// dumps one profile per case (named after it) whose instruction total / N is the count per call.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <regex>
#include <string>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define RBDC_HAVE_CALLGRIND 1
#endif

#include "registry.hpp"

namespace {

void time_case(benchmark::State& state, const rbdc_bench::Case* c) {
  void* context = c->context.get();
  int k = 0;
  for (auto _ : state) {
    c->call(context, k);
    k = (k + 1) & (rbdc_bench::kStateCount - 1);
  }
}

int count_instructions(long calls, const std::string& filter) {
#ifdef RBDC_HAVE_CALLGRIND
  if (!RUNNING_ON_VALGRIND)
    std::fprintf(stderr, "rbdc-bench: not under valgrind; the counts come from callgrind's dumps\n");
  const std::regex pattern(filter);
  for (const rbdc_bench::Case& c : rbdc_bench::cases()) {
    const std::string name = c.name();
    if (!std::regex_search(name, pattern)) continue;
    void* context = c.context.get();
    for (int k = 0; k < 16; ++k) c.call(context, k);  // warm-up outside the measurement
    CALLGRIND_ZERO_STATS;
    CALLGRIND_TOGGLE_COLLECT;  // on (valgrind runs with --collect-atstart=no)
    for (long i = 0; i < calls; ++i) c.call(context, static_cast<int>(i & (rbdc_bench::kStateCount - 1)));
    CALLGRIND_TOGGLE_COLLECT;  // off
    CALLGRIND_DUMP_STATS_AT(name.c_str());
    std::printf("counted %s\n", name.c_str());
    std::fflush(stdout);
  }
  return 0;
#else
  (void)calls;
  (void)filter;
  std::fprintf(stderr, "rbdc-bench: built without <valgrind/callgrind.h>\n");
  return 2;
#endif
}

}  // namespace

int main(int argc, char** argv) {
  long calls = 0;
  std::string filter = ".";
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--count-instructions=", 21) == 0) calls = std::atol(argv[i] + 21);
    if (std::strncmp(argv[i], "--benchmark_filter=", 19) == 0) filter = argv[i] + 19;
  }
  for (rbdc_bench::Provider provide : rbdc_bench::providers()) provide();
  if (calls > 0) return count_instructions(calls, filter);

  for (const rbdc_bench::Case& c : rbdc_bench::cases())
    benchmark::RegisterBenchmark(c.name().c_str(), time_case, &c);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
