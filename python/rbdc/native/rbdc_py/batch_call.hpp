// The numpy boundary shared by every rbdc extension module (the runtime's and each compiled one):
// a call checks the numpy arguments once, with messages naming the argument, then runs the
// function's Runner (batch_loop.hpp: an unchecked kernel over the states in C++ threads) with the
// GIL released, as MuJoCo's rollout bindings do. docs/python.md.
//
// numpy side: one state of an argument has shape () for a 1x1 input, (rows,) for a vector and
// (rows, cols) for a matrix; a batch puts N in front. An input given for one state while others
// are batches is used for every state. Inputs are float64 or float32 (integers become float64),
// any strides; the kernel computes in float32 only when every input is float32.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "rbdc_py/batch_loop.hpp"
#include "rbdc_py/single_call.hpp"

namespace rbdc_py {

namespace py = pybind11;

// ---- argument checks (with the GIL) ----------------------------------------------------------

inline std::string shape_text(const std::vector<py::ssize_t>& shape) {
  std::string text = "(";
  for (size_t k = 0; k < shape.size(); ++k) text += (k ? ", " : "") + std::to_string(shape[k]);
  return text + (shape.size() == 1 ? ",)" : ")");
}

inline std::vector<py::ssize_t> state_shape(const ArgSpec& arg, bool is_input) {
  if (arg.cols != 1 || arg.matrix) return {arg.rows, arg.cols};
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

template <class T>
py::object call_as(const FunctionSpec& f, const Runner& runner, Runner::Run run, const std::vector<py::array>& inputs,
                   const std::vector<py::ssize_t>& sizes, py::ssize_t n, py::handle out, int threads) {
  std::vector<py::array> outputs = output_arrays<T>(f, out, n);
  std::vector<Strided> in, outs;
  for (size_t i = 0; i < inputs.size(); ++i) in.push_back(strided(inputs[i], sizes[i] >= 0));
  for (const py::array& o : outputs) outs.push_back(strided(o, n >= 0));
  py::ssize_t bad;
  if (n < 0) {
    bad = run(runner.context, f, in, outs, -1, 1);
  } else {
    py::gil_scoped_release release;
    bad = run(runner.context, f, in, outs, n, thread_count(n, threads));
  }
  if (bad >= 0) {
    for (size_t i = 0; i < f.inputs.size(); ++i) {
      const ArgSpec& a = f.inputs[i];
      if (a.quaternion < 0 || !bad_quaternion(in[i], a, n < 0 ? 0 : bad)) continue;
      const std::string state = n < 0 ? std::string(a.name) : std::string(a.name) + "[" + std::to_string(bad) + "]";
      throw py::value_error(where(f, state.c_str()) + ": the quaternion " + a.name + "[" + std::to_string(a.quaternion) + ":" +
                            std::to_string(a.quaternion + 4) + "] has norm " + std::to_string(std::sqrt(quaternion_norm2(in[i], a, n < 0 ? 0 : bad))) +
                            ", expected a unit quaternion (w x y z); normalise it");
    }
  }
  if (outputs.size() == 1) return outputs[0];
  py::tuple result(outputs.size());
  for (size_t o = 0; o < outputs.size(); ++o) result[o] = outputs[o];
  return result;
}

/// A call from Python: one float64 state by the fast path (single_call.hpp); else checks the inputs
/// (shape, dtype), picks float32 if every input is float32 and the runner has a float kernel, runs it
/// over every state (a batch without the GIL).
inline py::object call(const FunctionSpec& f, const Runner& runner, const py::handle* values, py::handle out,
                       int threads) {
  if (py::object result = call_single(f, runner, values, out)) return result;
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
  if (all_float && runner.run_float) return call_as<float>(f, runner, runner.run_float, inputs, sizes, n, out, threads);
  return call_as<double>(f, runner, runner.run_double, inputs, sizes, n, out, threads);
}

}  // namespace rbdc_py
