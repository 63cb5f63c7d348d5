// The numpy boundary shared by every rbdc extension module (the runtime's and each compiled one):
// a function is described by its arguments' names and C++ shapes (column-major, as the C++ API
// takes them); a call checks the numpy arguments once, with messages naming the argument, then
// runs an unchecked kernel over the states in C++ threads with the GIL released (MuJoCo's rollout
// bindings do the same). docs/python.md.
//
// numpy side: one state of an argument has shape () for a 1x1 input, (rows,) for a vector and
// (rows, cols) for a matrix; a batch puts N in front. An input given for one state while others
// are batches is used for every state. Inputs are float64 or float32 (integers become float64),
// any strides; the kernel computes in float32 only when every input is float32.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace rbdc_py {

namespace py = pybind11;

/// One argument of a C++ function: rows x cols, stored column-major.
struct ArgSpec {
  const char* name;
  int rows;
  int cols;
  int quaternion = -1;  ///< q of a floating base: index of the quaternion's w (checked non-zero)
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
  py::ssize_t batch = 0, row = 0, col = 0;
};

/// The Pack argument of call() for kernels that take no packs.
template <class T, int W>
struct NoPack;

/// Kernels that are not templated on the scalar (the runtime's) say so; they run in double, state
/// by state.
template <class Kernel, class = void>
struct takes_packs : std::true_type {};
template <class Kernel>
struct takes_packs<Kernel, std::void_t<decltype(Kernel::double_only)>> : std::false_type {};

/// What one thread runs: `kernel.worker()` if the kernel has per-thread workspace (the runtime's
/// Data), else the kernel itself.
template <class Kernel>
auto make_worker(const Kernel& kernel, int) -> decltype(kernel.worker()) { return kernel.worker(); }
template <class Kernel>
const Kernel& make_worker(const Kernel& kernel, long) { return kernel; }

// ---- argument checks (with the GIL) ----------------------------------------------------------

inline std::string shape_text(const std::vector<py::ssize_t>& shape) {
  std::string text = "(";
  for (size_t k = 0; k < shape.size(); ++k) text += (k ? ", " : "") + std::to_string(shape[k]);
  return text + (shape.size() == 1 ? ",)" : ")");
}

inline std::vector<py::ssize_t> state_shape(const ArgSpec& arg, bool is_input) {
  if (arg.cols != 1) return {arg.rows, arg.cols};
  if (is_input && arg.rows == 1) return {};
  return {arg.rows};
}

inline std::string where(const FunctionSpec& f, const char* argument) {
  return std::string("rbdc: ") + f.name + ": " + argument;
}

/// The input as a float64 or float32 array (integers and lists of numbers become float64).
inline py::array as_float_array(const FunctionSpec& f, const ArgSpec& arg, py::handle value) {
  if (value.is_none()) throw py::type_error(where(f, arg.name) + " is missing");
  py::array array = py::array::ensure(value);
  if (!array) throw py::type_error(where(f, arg.name) + ": not an array of numbers");
  const char kind = array.dtype().kind();
  if (array.dtype().is(py::dtype::of<double>()) || array.dtype().is(py::dtype::of<float>())) return array;
  if (kind == 'i' || kind == 'u' || kind == 'b') return py::array_t<double, py::array::forcecast>(array);
  throw py::type_error(where(f, arg.name) + " has dtype " + std::string(py::str(array.dtype())) +
                       ", expected float64 or float32");
}

inline Strided strided(const py::array& array, bool batched) {
  Strided s;
  s.data = static_cast<char*>(const_cast<void*>(array.data()));
  s.is_double = array.dtype().is(py::dtype::of<double>());
  const int lead = batched ? 1 : 0;
  s.batch = batched ? array.strides(0) : 0;
  if (array.ndim() > lead) s.row = array.strides(lead);
  if (array.ndim() > lead + 1) s.col = array.strides(lead + 1);
  return s;
}

/// Number of states of an argument checked against its one-state shape: -1 for one state.
inline py::ssize_t batch_size(const FunctionSpec& f, const ArgSpec& arg, const py::array& array,
                              bool is_input, const char* label) {
  const std::vector<py::ssize_t> one = state_shape(arg, is_input);
  const std::vector<py::ssize_t> shape(array.shape(), array.shape() + array.ndim());
  if (shape == one) return -1;
  if (shape.size() == one.size() + 1 && std::equal(one.begin(), one.end(), shape.begin() + 1)) return shape[0];
  std::vector<py::ssize_t> batch = one;
  batch.insert(batch.begin(), -1);
  std::string expected = shape_text(batch);
  expected.replace(1, 2, "N");
  throw py::value_error(where(f, label) + " has shape " + shape_text(shape) + ", expected " +
                        shape_text(one) + " or " + expected);
}

// ---- the loop over states (without the GIL) --------------------------------------------------

template <class T>
inline T read(const Strided& s, py::ssize_t n, int r, int c) {
  const char* p = s.data + n * s.batch + r * s.row + c * s.col;
  return s.is_double ? static_cast<T>(*reinterpret_cast<const double*>(p))
                     : static_cast<T>(*reinterpret_cast<const float*>(p));
}

/// True if state n's quaternion has norm zero (it cannot be normalised; a NaN one passes as NaN).
inline bool zero_quaternion(const Strided& s, const ArgSpec& arg, py::ssize_t n) {
  if (arg.quaternion < 0) return false;
  double norm2 = 0;
  for (int k = 0; k < 4; ++k) norm2 += read<double>(s, n, arg.quaternion + k, 0) * read<double>(s, n, arg.quaternion + k, 0);
  return norm2 == 0;
}

/// Entry (r, c) of state n goes to dst[(c·rows + r)·step]: column-major, `step` apart (pack lanes).
template <class T>
inline void gather(const Strided& s, const ArgSpec& arg, py::ssize_t n, T* dst, int step) {
  for (int c = 0; c < arg.cols; ++c)
    for (int r = 0; r < arg.rows; ++r) dst[(c * arg.rows + r) * step] = read<T>(s, n, r, c);
}

template <class T>
inline void scatter(const T* src, int step, const ArgSpec& arg, const Strided& s, py::ssize_t n) {
  char* base = s.data + n * s.batch;
  for (int c = 0; c < arg.cols; ++c)
    for (int r = 0; r < arg.rows; ++r)
      *reinterpret_cast<T*>(base + r * s.row + c * s.col) = src[(c * arg.rows + r) * step];
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
/// gathered into lanes, computed, scattered. Returns the first state whose quaternion is zero, or -1.
template <class T, class P, int W, class Worker>
py::ssize_t run_lanes(const FunctionSpec& f, Worker& kernel, const std::vector<Strided>& in,
                      const std::vector<Strided>& out, py::ssize_t begin, py::ssize_t end, Workspace<P>& ws) {
  py::ssize_t bad = -1;
  T* in_lanes = reinterpret_cast<T*>(ws.in.data());
  T* out_lanes = reinterpret_cast<T*>(ws.out.data());
  for (py::ssize_t n = begin; n < end; n += W) {
    size_t offset = 0;
    for (size_t i = 0; i < f.inputs.size(); ++i) {
      for (int k = 0; k < W; ++k) {
        gather(in[i], f.inputs[i], n + k, in_lanes + offset * W + k, W);
        if (bad < 0 && zero_quaternion(in[i], f.inputs[i], n + k)) bad = n + k;
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
py::ssize_t run_range(const FunctionSpec& f, const Kernel& kernel, const std::vector<Strided>& in,
                      const std::vector<Strided>& out, py::ssize_t begin, py::ssize_t end) {
  py::ssize_t bad = -1;
  py::ssize_t packed_end = begin;
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
    const py::ssize_t tail_bad = run_lanes<T, T, 1>(f, worker, in, out, packed_end, end, ws);
    if (bad < 0) bad = tail_bad;
  }
  return bad;
}

/// Splits [0, n) over `threads` threads (whole packs each); returns the first zero-quaternion state.
template <class T, template <class, int> class Pack, int W, class Kernel>
py::ssize_t run_batch(const FunctionSpec& f, const Kernel& kernel, const std::vector<Strided>& in,
                      const std::vector<Strided>& out, py::ssize_t n, int threads) {
  if (threads <= 1) return run_range<T, Pack, W>(f, kernel, in, out, 0, n);
  std::vector<py::ssize_t> bad(static_cast<size_t>(threads), -1);
  std::vector<std::thread> pool;
  const py::ssize_t share = (n + threads - 1) / threads;
  const py::ssize_t step = (share + W - 1) / W * W;
  for (int t = 0; t < threads; ++t) {
    const py::ssize_t begin = std::min<py::ssize_t>(n, t * step), end = std::min<py::ssize_t>(n, begin + step);
    pool.emplace_back([&, t, begin, end] { bad[static_cast<size_t>(t)] = run_range<T, Pack, W>(f, kernel, in, out, begin, end); });
  }
  for (std::thread& thread : pool) thread.join();
  for (py::ssize_t b : bad)
    if (b >= 0) return b;
  return -1;
}

/// Threads for n states: `requested` if > 0, else enough that each has ≥ 2048 states, at most the
/// machine's cores.
inline int thread_count(py::ssize_t n, int requested) {
  if (requested > 0) return static_cast<int>(std::min<py::ssize_t>(requested, std::max<py::ssize_t>(n, 1)));
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return static_cast<int>(std::max<py::ssize_t>(1, std::min<py::ssize_t>(cores, n / 2048)));
}

// ---- the call ----------------------------------------------------------------------------------

/// The outputs: new arrays, or the caller's `out` (an array, or a tuple/list of one per output).
template <class T>
std::vector<py::array> output_arrays(const FunctionSpec& f, py::handle out, py::ssize_t n) {
  std::vector<py::array> arrays;
  if (out.is_none()) {
    for (const ArgSpec& a : f.outputs) {
      std::vector<py::ssize_t> shape = state_shape(a, false);
      if (n >= 0) shape.insert(shape.begin(), n);
      py::array_t<T> array(shape);
      if (f.zero_outputs) std::fill_n(array.mutable_data(), array.size(), T(0));
      arrays.push_back(array);
    }
    return arrays;
  }
  std::vector<py::handle> given;
  if (f.outputs.size() == 1 && !py::isinstance<py::tuple>(out) && !py::isinstance<py::list>(out)) {
    given.push_back(out);
  } else {
    py::sequence sequence = py::reinterpret_borrow<py::sequence>(out);
    if (!py::isinstance<py::sequence>(out) || sequence.size() != f.outputs.size())
      throw py::type_error(where(f, "out") + ": expected " + std::to_string(f.outputs.size()) + " arrays");
    for (py::handle h : sequence) given.push_back(h);
  }
  for (size_t o = 0; o < f.outputs.size(); ++o) {
    const std::string label = f.outputs.size() == 1 ? std::string("out") : "out[" + std::to_string(o) + "] (" + f.outputs[o].name + ")";
    if (!py::isinstance<py::array>(given[o])) throw py::type_error(where(f, label.c_str()) + ": not a numpy array");
    py::array array = py::reinterpret_borrow<py::array>(given[o]);
    if (!array.dtype().is(py::dtype::of<T>()))
      throw py::type_error(where(f, label.c_str()) + " has dtype " + std::string(py::str(array.dtype())) +
                           ", expected " + std::string(py::str(py::dtype::of<T>())));
    if (!array.writeable()) throw py::value_error(where(f, label.c_str()) + " is read-only");
    const py::ssize_t m = batch_size(f, f.outputs[o], array, false, label.c_str());
    if (m != n) throw py::value_error(where(f, label.c_str()) + " holds " + (m < 0 ? "one state" : std::to_string(m) + " states") +
                                      ", the inputs " + (n < 0 ? "one state" : std::to_string(n) + " states"));
    if (f.zero_outputs) array.attr("fill")(0);
    arrays.push_back(array);
  }
  return arrays;
}

template <class T, template <class, int> class Pack, int W, class Kernel>
py::object call_as(const FunctionSpec& f, const Kernel& kernel, const std::vector<py::array>& inputs,
                   const std::vector<py::ssize_t>& sizes, py::ssize_t n, py::handle out, int threads) {
  std::vector<py::array> outputs = output_arrays<T>(f, out, n);
  std::vector<Strided> in, outs;
  for (size_t i = 0; i < inputs.size(); ++i) in.push_back(strided(inputs[i], sizes[i] >= 0));
  for (const py::array& o : outputs) outs.push_back(strided(o, n >= 0));
  py::ssize_t bad;
  if (n < 0) {
    bad = run_range<T, Pack, 1>(f, kernel, in, outs, 0, 1);
  } else {
    py::gil_scoped_release release;
    bad = run_batch<T, Pack, W>(f, kernel, in, outs, n, thread_count(n, threads));
  }
  if (bad >= 0) {
    for (const ArgSpec& a : f.inputs) {
      if (a.quaternion < 0) continue;
      const std::string state = n < 0 ? std::string(a.name) : std::string(a.name) + "[" + std::to_string(bad) + "]";
      throw py::value_error(where(f, state.c_str()) + ": the quaternion " + a.name + "[" + std::to_string(a.quaternion) + ":" +
                            std::to_string(a.quaternion + 4) + "] is zero and cannot be normalised");
    }
  }
  if (outputs.size() == 1) return outputs[0];
  py::tuple result(outputs.size());
  for (size_t o = 0; o < outputs.size(); ++o) result[o] = outputs[o];
  return result;
}

/// A call from Python: checks the inputs (shape, dtype), picks float32 if every input is float32,
/// runs the kernel over every state. `Pack<T, W>` is the batch type of the generated code (W lanes).
template <template <class, int> class Pack, int W_double, int W_float, class Kernel>
py::object call(const FunctionSpec& f, const Kernel& kernel, const py::handle* values, py::handle out,
                int threads) {
  std::vector<py::array> inputs;
  std::vector<py::ssize_t> sizes;
  py::ssize_t n = -1;
  const char* batch_argument = nullptr;
  bool all_float = true;
  for (size_t i = 0; i < f.inputs.size(); ++i) {
    inputs.push_back(as_float_array(f, f.inputs[i], values[i]));
    const py::ssize_t m = batch_size(f, f.inputs[i], inputs[i], true, f.inputs[i].name);
    if (m >= 0 && n >= 0 && m != n)
      throw py::value_error(where(f, f.inputs[i].name) + " holds " + std::to_string(m) + " states, " +
                            batch_argument + " " + std::to_string(n));
    if (m >= 0) n = m, batch_argument = f.inputs[i].name;
    sizes.push_back(m);
    all_float = all_float && !inputs[i].dtype().is(py::dtype::of<double>());
  }
  if constexpr (takes_packs<Kernel>::value) {
    if (all_float) return call_as<float, Pack, W_float>(f, kernel, inputs, sizes, n, out, threads);
    return call_as<double, Pack, W_double>(f, kernel, inputs, sizes, n, out, threads);
  } else {
    return call_as<double, Pack, 1>(f, kernel, inputs, sizes, n, out, threads);
  }
}

}  // namespace rbdc_py
