// What one core sustains, for reading an instruction count against a time (tools/instruction_rates.py,
// docs/performance.md, "What bounds each remaining gap"): the clock, by a chain of dependent integer
// additions (one a cycle), then independent floating-point chains: scalar FMAs, 512-bit FMAs, and
// FMAs and additions half and half (the two kinds go to different pipes).
//
//   g++ -O2 -march=native tools/machine_peak.cpp -o /tmp/machine_peak && taskset -c 1 /tmp/machine_peak
//
// x86-64 with AVX-512 only (the chains are inline assembly, so no compiler reorders or fuses them).
#include <chrono>
#include <cstdio>

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Each loop iteration runs `per_iteration` instructions of its kind on independent registers.
#define RBDC_TIMED_LOOP(body, ...)                                                                   \
  [&] {                                                                                             \
    const auto start = std::chrono::steady_clock::now();                                            \
    asm volatile("mov %0, %%rcx\n1:\n" body "dec %%rcx\njnz 1b\n" ::"r"(kIterations) : "rcx", __VA_ARGS__); \
    return seconds_since(start);                                                                    \
  }()

constexpr long kIterations = 100000000;

}  // namespace

int main() {
  const double clock_seconds = RBDC_TIMED_LOOP("add $1, %%rax\n", "rax");
  const double ghz = kIterations / clock_seconds / 1e9;  // the dependent additions: one a cycle
  std::printf("clock: %.2f GHz\n", ghz);
  const auto rate = [&](double seconds, int per_iteration) { return per_iteration * kIterations / seconds / 1e9 / ghz; };
#define FMA8(width) \
  "vfmadd231" width " %%xmm14,%%xmm15,%%xmm0\nvfmadd231" width " %%xmm14,%%xmm15,%%xmm1\n" \
  "vfmadd231" width " %%xmm14,%%xmm15,%%xmm2\nvfmadd231" width " %%xmm14,%%xmm15,%%xmm3\n" \
  "vfmadd231" width " %%xmm14,%%xmm15,%%xmm4\nvfmadd231" width " %%xmm14,%%xmm15,%%xmm5\n" \
  "vfmadd231" width " %%xmm14,%%xmm15,%%xmm6\nvfmadd231" width " %%xmm14,%%xmm15,%%xmm7\n"
  std::printf("scalar FMAs: %.2f a cycle\n",
              rate(RBDC_TIMED_LOOP(FMA8("sd"), "xmm0", "xmm1", "xmm2", "xmm3", "xmm4", "xmm5", "xmm6", "xmm7"), 8));
  std::printf("512-bit FMAs: %.2f a cycle\n",
              rate(RBDC_TIMED_LOOP("vfmadd231pd %%zmm14,%%zmm15,%%zmm0\nvfmadd231pd %%zmm14,%%zmm15,%%zmm1\n"
                                   "vfmadd231pd %%zmm14,%%zmm15,%%zmm2\nvfmadd231pd %%zmm14,%%zmm15,%%zmm3\n"
                                   "vfmadd231pd %%zmm14,%%zmm15,%%zmm4\nvfmadd231pd %%zmm14,%%zmm15,%%zmm5\n"
                                   "vfmadd231pd %%zmm14,%%zmm15,%%zmm6\nvfmadd231pd %%zmm14,%%zmm15,%%zmm7\n",
                                   "xmm0", "xmm1", "xmm2", "xmm3", "xmm4", "xmm5", "xmm6", "xmm7"),
                   8));
  std::printf("scalar FMAs and additions, half and half: %.2f a cycle\n",
              rate(RBDC_TIMED_LOOP(FMA8("sd") "vaddsd %%xmm15,%%xmm16,%%xmm16\nvaddsd %%xmm15,%%xmm17,%%xmm17\n"
                                              "vaddsd %%xmm15,%%xmm18,%%xmm18\nvaddsd %%xmm15,%%xmm19,%%xmm19\n"
                                              "vaddsd %%xmm15,%%xmm20,%%xmm20\nvaddsd %%xmm15,%%xmm21,%%xmm21\n"
                                              "vaddsd %%xmm15,%%xmm22,%%xmm22\nvaddsd %%xmm15,%%xmm23,%%xmm23\n",
                                   "xmm0", "xmm1", "xmm2", "xmm3", "xmm4", "xmm5", "xmm6", "xmm7", "xmm16", "xmm17",
                                   "xmm18", "xmm19", "xmm20", "xmm21", "xmm22", "xmm23"),
                   16));
  return 0;
}
