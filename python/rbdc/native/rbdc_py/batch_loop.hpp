// The loop over states of the rbdc extension modules, without Python (a generated function's
// translation unit includes only this, the generated code and rbdc_gen/batch.hpp): a function is
// described by its arguments' names and C++ shapes (column-major, as the C++ API takes them); each
// thread gathers its states from the numpy buffers into packs of W lanes, runs the kernel, and
// scatters the outputs. The checks and the numpy side are batch_call.hpp. docs/python.md.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <thread>
#include <vector>

namespace rbdc_py {

/// One argument of a C++ function: rows x cols, stored column-major.
struct ArgSpec {
  const char* name;
  int rows;
  int cols;
  int quaternion = -1;  ///< q of a floating base: index of the quaternion's w (checked unit)
  bool matrix = false;  ///< numpy shape (rows, cols) even for one column (feet matrices of one foot)
  int size() const { return rows * cols; }
};

struct FunctionSpec {
  const char* name;
  std::vector<ArgSpec> inputs;
  std::vector<ArgSpec> outputs;
  bool zero_outputs = false;  ///< the kernel leaves some entries unwritten: outputs start at 0
};

/// One argument as numpy holds it: byte strides of the batch (0: one state for all), row and column.
struct Strided {
  char* data = nullptr;
  bool is_double = true;
  std::ptrdiff_t batch = 0, row = 0, col = 0;
};

/// What one thread runs: `kernel.worker()` if the kernel has per-thread workspace (the runtime's
/// Data), else the kernel itself.
template <class Kernel>
auto make_worker(const Kernel& kernel, int) -> decltype(kernel.worker()) { return kernel.worker(); }
template <class Kernel>
const Kernel& make_worker(const Kernel& kernel, long) { return kernel; }

// ---- the loop over states (without the GIL) --------------------------------------------------

template <class T>
inline T read(const Strided& s, std::ptrdiff_t n, int r, int c) {
  const char* p = s.data + n * s.batch + r * s.row + c * s.col;
  return s.is_double ? static_cast<T>(*reinterpret_cast<const double*>(p))
                     : static_cast<T>(*reinterpret_cast<const float*>(p));
}

/// |‖quaternion‖² − 1| above which a state is refused: the generated code assumes a unit quaternion
/// (the runtime normalises it); float32 rounding of a unit quaternion stays far below.
constexpr double kQuaternionTolerance = 1e-5;

/// ‖quaternion‖² of state n's argument (its entries quaternion … quaternion + 3).
inline double quaternion_norm2(const Strided& s, const ArgSpec& arg, std::ptrdiff_t n) {
  double norm2 = 0;
  for (int k = 0; k < 4; ++k) norm2 += read<double>(s, n, arg.quaternion + k, 0) * read<double>(s, n, arg.quaternion + k, 0);
  return norm2;
}

/// True if state n's quaternion is not a unit one (a NaN one passes: NaN in, NaN out).
inline bool bad_quaternion(const Strided& s, const ArgSpec& arg, std::ptrdiff_t n) {
  return arg.quaternion >= 0 && std::abs(quaternion_norm2(s, arg, n) - 1) > kQuaternionTolerance;
}

/// Entry (r, c) of state n goes to dst[(c·rows + r)·step]: column-major, `step` apart (pack lanes).
template <class T>
inline void gather(const Strided& s, const ArgSpec& arg, std::ptrdiff_t n, T* dst, int step) {
  for (int c = 0; c < arg.cols; ++c)
    for (int r = 0; r < arg.rows; ++r) dst[(c * arg.rows + r) * step] = read<T>(s, n, r, c);
}

/// The inverse of gather, in the order of the destination's memory (row by row for numpy's C order):
/// a fresh output array is written front to back, which the store buffers combine into whole lines
/// (a 10^6-state M is 2.6 GB of output; column order wrote each line 18 times).
template <class T>
inline void scatter(const T* src, int step, const ArgSpec& arg, const Strided& s, std::ptrdiff_t n) {
  char* base = s.data + n * s.batch;
  const auto put = [&](int r, int c) {
    *reinterpret_cast<T*>(base + r * s.row + c * s.col) = src[(c * arg.rows + r) * step];
  };
  if (std::abs(s.col) < std::abs(s.row)) {
    for (int r = 0; r < arg.rows; ++r)
      for (int c = 0; c < arg.cols; ++c) put(r, c);
  } else {
    for (int c = 0; c < arg.cols; ++c)
      for (int r = 0; r < arg.rows; ++r) put(r, c);
  }
}

/// Buffers of one thread: every input and output of one group of W states, lane k of entry i at
/// [i·W + k] (for W > 1 the storage of rbdc_gen::Pack<T, W>, whose lanes are contiguous Ts).
template <class Scalar>
struct Workspace {
  std::vector<Scalar> in, out;
  std::vector<const Scalar*> in_ptr;
  std::vector<Scalar*> out_ptr;
  explicit Workspace(const FunctionSpec& f) {
    size_t n_in = 0, n_out = 0;
    for (const ArgSpec& a : f.inputs) n_in += static_cast<size_t>(a.size());
    for (const ArgSpec& a : f.outputs) n_out += static_cast<size_t>(a.size());
    in.assign(n_in, Scalar(0));
    out.assign(n_out, Scalar(0));
    size_t offset = 0;
    for (const ArgSpec& a : f.inputs) in_ptr.push_back(in.data() + offset), offset += static_cast<size_t>(a.size());
    offset = 0;
    for (const ArgSpec& a : f.outputs) out_ptr.push_back(out.data() + offset), offset += static_cast<size_t>(a.size());
  }
};

template <class Scalar>
struct lanes_of { static constexpr int value = 1; using type = Scalar; };

/// States [begin, end) through `kernel` with Scalar = P (a Pack of W lanes of T, or T itself):
/// gathered into lanes, computed, scattered. Returns the first state whose quaternion is not a unit one, or -1.
template <class T, class P, int W, class Worker>
std::ptrdiff_t run_lanes(const FunctionSpec& f, Worker& kernel, const std::vector<Strided>& in,
                      const std::vector<Strided>& out, std::ptrdiff_t begin, std::ptrdiff_t end, Workspace<P>& ws) {
  std::ptrdiff_t bad = -1;
  T* in_lanes = reinterpret_cast<T*>(ws.in.data());
  T* out_lanes = reinterpret_cast<T*>(ws.out.data());
  for (std::ptrdiff_t n = begin; n < end; n += W) {
    size_t offset = 0;
    for (size_t i = 0; i < f.inputs.size(); ++i) {
      for (int k = 0; k < W; ++k) {
        gather(in[i], f.inputs[i], n + k, in_lanes + offset * W + k, W);
        if (bad < 0 && bad_quaternion(in[i], f.inputs[i], n + k)) bad = n + k;
      }
      offset += static_cast<size_t>(f.inputs[i].size());
    }
    kernel(ws.in_ptr.data(), ws.out_ptr.data());
    offset = 0;
    for (size_t o = 0; o < f.outputs.size(); ++o) {
      for (int k = 0; k < W; ++k) scatter(out_lanes + offset * W + k, W, f.outputs[o], out[o], n + k);
      offset += static_cast<size_t>(f.outputs[o].size());
    }
  }
  return bad;
}

/// One thread's share: whole packs first, then the remaining states one by one.
template <class T, template <class, int> class Pack, int W, class Kernel>
std::ptrdiff_t run_range(const FunctionSpec& f, const Kernel& kernel, const std::vector<Strided>& in,
                      const std::vector<Strided>& out, std::ptrdiff_t begin, std::ptrdiff_t end) {
  std::ptrdiff_t bad = -1;
  std::ptrdiff_t packed_end = begin;
  auto&& worker = make_worker(kernel, 0);
  if constexpr (W > 1) {
    packed_end = begin + (end - begin) / W * W;
    if (packed_end > begin) {
      using P = Pack<T, W>;
      static_assert(sizeof(P) == W * sizeof(T), "a Pack is W contiguous lanes");
      Workspace<P> ws(f);
      bad = run_lanes<T, P, W>(f, worker, in, out, begin, packed_end, ws);
    }
  }
  if (packed_end < end) {
    Workspace<T> ws(f);
    const std::ptrdiff_t tail_bad = run_lanes<T, T, 1>(f, worker, in, out, packed_end, end, ws);
    if (bad < 0) bad = tail_bad;
  }
  return bad;
}

/// Splits [0, n) over `threads` threads (whole packs each); returns the first zero-quaternion state.
template <class T, template <class, int> class Pack, int W, class Kernel>
std::ptrdiff_t run_batch(const FunctionSpec& f, const Kernel& kernel, const std::vector<Strided>& in,
                      const std::vector<Strided>& out, std::ptrdiff_t n, int threads) {
  if (threads <= 1) return run_range<T, Pack, W>(f, kernel, in, out, 0, n);
  std::vector<std::ptrdiff_t> bad(static_cast<size_t>(threads), -1);
  std::vector<std::thread> pool;
  const std::ptrdiff_t share = (n + threads - 1) / threads;
  const std::ptrdiff_t step = (share + W - 1) / W * W;
  for (int t = 0; t < threads; ++t) {
    const std::ptrdiff_t begin = std::min<std::ptrdiff_t>(n, t * step), end = std::min<std::ptrdiff_t>(n, begin + step);
    pool.emplace_back([&, t, begin, end] { bad[static_cast<size_t>(t)] = run_range<T, Pack, W>(f, kernel, in, out, begin, end); });
  }
  for (std::thread& thread : pool) thread.join();
  for (std::ptrdiff_t b : bad)
    if (b >= 0) return b;
  return -1;
}

/// Threads for n states: `requested` if > 0, else enough that each has ≥ 2048 states, at most the
/// machine's cores.
inline int thread_count(std::ptrdiff_t n, int requested) {
  if (requested > 0) return static_cast<int>(std::min<std::ptrdiff_t>(requested, std::max<std::ptrdiff_t>(n, 1)));
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return static_cast<int>(std::max<std::ptrdiff_t>(1, std::min<std::ptrdiff_t>(cores, n / 2048)));
}


/// What the numpy layer calls to run a function over checked arguments: `n` states (-1: one state,
/// in the calling thread), in double or in float. Returns the first state whose quaternion is not a unit one,
/// or -1. `context` is the kernel object of a kernel with state (the runtime's), else null.
struct Runner {
  using Run = std::ptrdiff_t (*)(const void* context, const FunctionSpec& f, const std::vector<Strided>& in,
                                 const std::vector<Strided>& out, std::ptrdiff_t n, int threads);
  /// One state in double, contiguous column-major arguments as the C++ API takes them (single_call.hpp).
  using One = void (*)(const void* context, const double* const* in, double* const* out);
  Run run_double;
  Run run_float;  ///< null: the kernel runs in double only (float32 inputs are converted)
  const void* context = nullptr;
  One run_one = nullptr;  ///< null: single states take the batch path too
};

/// The pack type of kernels that take no packs (W = 1).
template <class T, int W>
struct NoPack;

/// Runner::Run for a Kernel: its states in packs of W lanes of T (Pack<T, W>), the rest one by one.
template <class Kernel, class T, template <class, int> class Pack, int W>
std::ptrdiff_t run_kernel(const void* context, const FunctionSpec& f, const std::vector<Strided>& in,
                          const std::vector<Strided>& out, std::ptrdiff_t n, int threads) {
  const Kernel kernel = context ? *static_cast<const Kernel*>(context) : Kernel{};
  if (n < 0) return run_range<T, Pack, 1>(f, kernel, in, out, 0, 1);
  return run_batch<T, Pack, W>(f, kernel, in, out, n, threads);
}

/// Runner::One for a Kernel.
template <class Kernel>
void run_one(const void* context, const double* const* in, double* const* out) {
  const Kernel kernel = context ? *static_cast<const Kernel*>(context) : Kernel{};
  auto&& worker = make_worker(kernel, 0);
  worker(in, out);
}

}  // namespace rbdc_py
