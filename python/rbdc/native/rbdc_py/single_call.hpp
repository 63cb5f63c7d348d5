// The fast path of a single-state call (batch_call.hpp tries it first): every input a float64 numpy
// array of exactly its one-state shape, aligned and contiguous, a unit quaternion, and `out=` absent
// or such arrays (writeable). That call is the common one in a control loop and its cost is all
// overhead: it skips the batch machinery (no array conversion, no shape vectors, no Strided gather
// and scatter, no workspace allocation; the GIL kept), reads the numpy arrays' fields directly and
// allocates each output with one numpy call. Any other call returns null and takes the checked
// general path, which gives the error messages. docs/python.md.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cmath>
#include <vector>

#include "rbdc_py/batch_loop.hpp"

namespace rbdc_py {

namespace py = pybind11;

/// Arguments a fast call handles per side (the generated functions have at most 4 inputs, 4 outputs).
constexpr size_t kMaxSingleArgs = 8;

/// True if `value` is an aligned float64 array of the one-state shape of `arg` (an input's 1x1 as
/// shape ()), and writeable if `writeable`.
inline bool is_one_double_state(const ArgSpec& arg, bool is_input, PyObject* value, bool writeable) {
  const auto& api = py::detail::npy_api::get();
  if (!value || !api.PyArray_Check_(value)) return false;
  const auto* array = py::detail::array_proxy(value);
  if (py::detail::array_descriptor_proxy(array->descr)->type_num != api.NPY_DOUBLE_) return false;
  const int needed = api.NPY_ARRAY_ALIGNED_ | (writeable ? api.NPY_ARRAY_WRITEABLE_ : 0);
  if ((array->flags & needed) != needed) return false;
  if (arg.cols != 1 || arg.matrix)
    return array->nd == 2 && array->dimensions[0] == arg.rows && array->dimensions[1] == arg.cols;
  if (is_input && arg.rows == 1) return array->nd == 0;
  return array->nd == 1 && array->dimensions[0] == arg.rows;
}

/// How a one-state array meets the C++ API's column-major layout: as it is, transposed (a matrix in
/// numpy's C order), or not at all (strided: the general path's).
enum class Layout { as_is, transposed, strided };

inline Layout layout_of(const ArgSpec& arg, PyObject* value) {
  const auto& api = py::detail::npy_api::get();
  const int flags = py::detail::array_proxy(value)->flags;
  if (flags & api.NPY_ARRAY_F_CONTIGUOUS_) return Layout::as_is;  // a contiguous vector is both
  if (flags & api.NPY_ARRAY_C_CONTIGUOUS_) return arg.cols == 1 ? Layout::as_is : Layout::transposed;
  return Layout::strided;
}

inline double* data_of(PyObject* array) { return reinterpret_cast<double*>(py::detail::array_proxy(array)->data); }

/// A new C-ordered float64 array of one state of `arg` (an output).
inline py::object new_double_state(const ArgSpec& arg) {
  const auto& api = py::detail::npy_api::get();
  Py_intptr_t dims[2] = {arg.rows, arg.cols};
  const int nd = (arg.cols != 1 || arg.matrix) ? 2 : 1;
  PyObject* array = api.PyArray_NewFromDescr_(api.PyArray_Type_, api.PyArray_DescrFromType_(api.NPY_DOUBLE_), nd, dims,
                                              nullptr, nullptr, 0, nullptr);
  if (!array) throw py::error_already_set();
  return py::reinterpret_steal<py::object>(array);
}

/// (rows, cols) row-major (numpy's C order) to column-major (the C++ API's) and back; writes in
/// order (strided stores cost several times strided loads).
inline void transpose(const double* from, int rows, int cols, double* to) {
  for (int c = 0; c < cols; ++c)
    for (int r = 0; r < rows; ++r) to[c * rows + r] = from[r * cols + c];
}

/// The caller's array for output o (`out`: an array, or a tuple of one per output), null if none
/// is given or `out` is not of that form (the general path then says what is wrong).
inline PyObject* given_output(const FunctionSpec& f, py::handle out, size_t o) {
  if (out.is_none()) return nullptr;
  if (!PyTuple_Check(out.ptr())) return f.outputs.size() == 1 ? out.ptr() : nullptr;
  return PyTuple_GET_SIZE(out.ptr()) == static_cast<Py_ssize_t>(f.outputs.size()) ? PyTuple_GET_ITEM(out.ptr(), o) : nullptr;
}

/// The call on one float64 state, or null if the call is not one the fast path takes.
inline py::object call_single(const FunctionSpec& f, const Runner& runner, const py::handle* values, py::handle out) {
  if (!runner.run_one || f.inputs.size() > kMaxSingleArgs || f.outputs.size() > kMaxSingleArgs) return {};
  // Column-major copies of the matrices numpy holds in C order: one buffer per thread.
  thread_local std::vector<double> scratch;
  size_t scratch_size = 0;
  for (const ArgSpec& a : f.inputs) scratch_size += static_cast<size_t>(a.size());
  for (const ArgSpec& a : f.outputs) scratch_size += static_cast<size_t>(a.size());
  if (scratch.size() < scratch_size) scratch.resize(scratch_size);
  double* free_scratch = scratch.data();

  std::array<const double*, kMaxSingleArgs> in{};
  for (size_t i = 0; i < f.inputs.size(); ++i) {
    const ArgSpec& a = f.inputs[i];
    PyObject* value = values[i].ptr();
    if (!is_one_double_state(a, true, value, false)) return {};
    const Layout layout = layout_of(a, value);
    if (layout == Layout::strided) return {};
    in[i] = data_of(value);
    if (layout == Layout::transposed) {
      transpose(in[i], a.rows, a.cols, free_scratch);
      in[i] = free_scratch;
      free_scratch += a.size();
    }
    if (a.quaternion >= 0) {
      double norm2 = 0;
      for (int k = 0; k < 4; ++k) norm2 += in[i][a.quaternion + k] * in[i][a.quaternion + k];
      if (std::abs(norm2 - 1) > kQuaternionTolerance) return {};  // the general path says why
    }
  }

  std::array<py::object, kMaxSingleArgs> outputs;  // null handles (a default py::array would be a numpy call)
  std::array<Layout, kMaxSingleArgs> layouts{};
  std::array<double*, kMaxSingleArgs> result{};
  for (size_t o = 0; o < f.outputs.size(); ++o) {
    const ArgSpec& a = f.outputs[o];
    PyObject* given = given_output(f, out, o);
    if (!out.is_none() && !is_one_double_state(a, false, given, true)) return {};
    outputs[o] = given ? py::reinterpret_borrow<py::object>(given) : new_double_state(a);
    layouts[o] = layout_of(a, outputs[o].ptr());
    if (layouts[o] == Layout::strided) return {};
    result[o] = layouts[o] == Layout::as_is ? data_of(outputs[o].ptr()) : free_scratch;
    if (layouts[o] == Layout::transposed) free_scratch += a.size();
  }
  for (size_t o = 0; o < f.outputs.size() && f.zero_outputs; ++o) std::fill_n(result[o], f.outputs[o].size(), 0.0);
  runner.run_one(runner.context, in.data(), result.data());
  for (size_t o = 0; o < f.outputs.size(); ++o)
    if (layouts[o] == Layout::transposed) transpose(result[o], f.outputs[o].cols, f.outputs[o].rows, data_of(outputs[o].ptr()));
  if (f.outputs.size() == 1) return std::move(outputs[0]);
  py::tuple tuple(f.outputs.size());
  for (size_t o = 0; o < f.outputs.size(); ++o) tuple[o] = std::move(outputs[o]);
  return std::move(tuple);
}

}  // namespace rbdc_py
