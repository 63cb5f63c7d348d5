// What one core sustains, for reading an instruction count against a time (tools/instruction_rates.py,
// docs/performance.md, "What bounds each remaining gap"): the clock, by a chain of dependent integer
// additions (one a cycle), then independent floating-point chains: scalar FMAs, 512-bit FMAs, scalar
// additions, and FMAs and additions half and half (the two kinds go to different pipes); last, how
// fast the front end feeds straight-line code that its op cache holds and code that it does not
// (eight-byte no-ops, which nothing behind the decoders holds up).
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
#define RBDC_TIMED_LOOP(iterations, body, ...)                                                       \
  [&] {                                                                                             \
    const auto start = std::chrono::steady_clock::now();                                            \
    asm volatile("mov %0, %%rcx\n1:\n" body "dec %%rcx\njnz 1b\n" ::"r"(iterations) : "rcx", __VA_ARGS__); \
    return seconds_since(start);                                                                    \
  }()

constexpr long kIterations = 100000000;

}  // namespace

// Independent chains, enough of them to cover a pipelined unit's latency times its units (Zen 5:
// two FMA pipes of latency 4, two adders of latency 2; eight FMA chains read 1.5 a cycle there).
#define RBDC_FMA(width, r) "vfmadd231" width " %%" #r "14,%%" #r "15,%%" #r
#define RBDC_FMA12(width, r)                                                                          \
  RBDC_FMA(width, r) "0\n" RBDC_FMA(width, r) "1\n" RBDC_FMA(width, r) "2\n" RBDC_FMA(width, r) "3\n"   \
  RBDC_FMA(width, r) "4\n" RBDC_FMA(width, r) "5\n" RBDC_FMA(width, r) "6\n" RBDC_FMA(width, r) "7\n"   \
  RBDC_FMA(width, r) "8\n" RBDC_FMA(width, r) "9\n" RBDC_FMA(width, r) "10\n" RBDC_FMA(width, r) "11\n"
#define RBDC_ADD(r) "vaddsd %%xmm15,%%xmm" #r ",%%xmm" #r "\n"
#define RBDC_ADD12                                                                                    \
  RBDC_ADD(16) RBDC_ADD(17) RBDC_ADD(18) RBDC_ADD(19) RBDC_ADD(20) RBDC_ADD(21) RBDC_ADD(22) RBDC_ADD(23) \
  RBDC_ADD(24) RBDC_ADD(25) RBDC_ADD(26) RBDC_ADD(27)
#define RBDC_FMA_REGISTERS "xmm0", "xmm1", "xmm2", "xmm3", "xmm4", "xmm5", "xmm6", "xmm7", "xmm8", "xmm9", "xmm10", "xmm11"
#define RBDC_ADD_REGISTERS \
  "xmm16", "xmm17", "xmm18", "xmm19", "xmm20", "xmm21", "xmm22", "xmm23", "xmm24", "xmm25", "xmm26", "xmm27"

// `count` eight-byte no-ops in a row: a loop body of count × 8 bytes of straight-line code.
#define RBDC_NOPS(count) ".rept " #count "\n.byte 0x0f,0x1f,0x84,0x00,0x00,0x00,0x00,0x00\n.endr\n"
constexpr long kCodeIterations = 200000;

int main() {
  const double clock_seconds = RBDC_TIMED_LOOP(kIterations, "add $1, %%rax\n", "rax");
  const double ghz = kIterations / clock_seconds / 1e9;  // the dependent additions: one a cycle
  std::printf("clock: %.2f GHz\n", ghz);
  const auto rate = [&](double seconds, int per_iteration) { return per_iteration * kIterations / seconds / 1e9 / ghz; };
  std::printf("scalar FMAs: %.2f a cycle\n", rate(RBDC_TIMED_LOOP(kIterations, RBDC_FMA12("sd", xmm), RBDC_FMA_REGISTERS), 12));
  std::printf("512-bit FMAs: %.2f a cycle\n", rate(RBDC_TIMED_LOOP(kIterations, RBDC_FMA12("pd", zmm), RBDC_FMA_REGISTERS), 12));
  std::printf("scalar additions: %.2f a cycle\n", rate(RBDC_TIMED_LOOP(kIterations, RBDC_ADD12, RBDC_ADD_REGISTERS), 12));
  std::printf("scalar FMAs and additions, half and half: %.2f a cycle\n",
              rate(RBDC_TIMED_LOOP(kIterations, RBDC_FMA12("sd", xmm) RBDC_ADD12, RBDC_FMA_REGISTERS, RBDC_ADD_REGISTERS), 24));
  // Zen 5's op cache holds 5 500-6 000 of these; code beyond it goes through the decoders, about 16
  // bytes a cycle whether it comes from the level-1 instruction cache or level 2.
  const auto bytes_a_ns = [&](double seconds, int nops) { return 8.0 * nops * kCodeIterations / seconds / 1e9; };
  std::printf("straight-line code, 16 KB: %.0f bytes a ns\n", bytes_a_ns(RBDC_TIMED_LOOP(kCodeIterations, RBDC_NOPS(2048), "memory"), 2048));
  std::printf("straight-line code, 64 KB: %.0f bytes a ns\n", bytes_a_ns(RBDC_TIMED_LOOP(kCodeIterations, RBDC_NOPS(8192), "memory"), 8192));
  return 0;
}
