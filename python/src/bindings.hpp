#pragma once
// Shared by the binding files of the `momenta` Python module (momenta._core): how numpy
// arguments become Eigen views and results become numpy arrays, and the per-area entry points
// module.cpp calls.
//
// Arguments. A vector or matrix argument is any real array-like (lists, numpy arrays of any real
// dtype); a C-contiguous float64 array is read in place, anything else is converted once. A
// wrong shape, a complex or non-numeric dtype raises ValueError naming the argument and the
// size expected, before C++ sees it.
//
// Results. Arrays are returned as new numpy arrays owning their data (never views of a
// workspace that the next call overwrites).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <complex>

#include <string>
#include <string_view>
#include <vector>

#include "momenta/common/error.hpp"
#include "momenta/math/types.hpp"

namespace momenta::python {

namespace py = pybind11;

/// A float64, C-contiguous array converted from `object` (no copy when it already is one).
/// Raises ValueError naming `name` when it is not a real numeric array-like.
py::array_t<double, py::array::c_style> as_float_array(const py::handle& object,
                                                       std::string_view name);

/// What keeps an argument's array alive while a view of it is used: empty until vector_arg fills
/// it (a default-constructed py::array_t would allocate an empty numpy array on every call).
using ArgStorage = py::object;

/// A read-only view of a 1-D argument of `size` entries (size < 0: any). `storage` keeps a
/// converted copy alive for as long as the view is used. Raises ValueError naming `name`, the
/// expected size and what `what` it is ("the model's nq").
Eigen::Map<const VecX> vector_arg(const py::handle& object, std::string_view name,
                                  Eigen::Index size, std::string_view what, ArgStorage& storage);

/// A 3-vector argument.
Vec3 vec3_arg(const py::handle& object, std::string_view name);

/// A rows × cols matrix argument (copied; -1: any size along that dimension).
MatX matrix_arg(const py::handle& object, std::string_view name, Eigen::Index rows,
                Eigen::Index cols);

/// A 3 × 3 matrix argument.
Mat3 mat3_arg(const py::handle& object, std::string_view name);

/// A new, uninitialized float64 C-contiguous array of shape (rows,) or (rows, cols), made by
/// numpy's own constructor (pybind11's builds shape and stride vectors on the heap: the lean
/// path keeps a small result's cost to the array object itself).
py::array_t<double> new_float_array(py::ssize_t rows);
py::array_t<double> new_float_array(py::ssize_t rows, py::ssize_t cols);

/// A new numpy array holding a copy of `x`: 1-D for a vector type (one column at compile time),
/// 2-D (rows, columns) otherwise.
template <class Derived>
py::array_t<double> to_numpy(const Eigen::MatrixBase<Derived>& x) {
  if constexpr (Derived::ColsAtCompileTime == 1) {
    py::array_t<double> out = new_float_array(x.size());
    Eigen::Map<VecX>(out.mutable_data(), x.size()) = x;
    return out;
  } else {
    py::array_t<double> out = new_float_array(x.rows(), x.cols());
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    Eigen::Map<RowMajor>(out.mutable_data(), x.rows(), x.cols()) = x;
    return out;
  }
}
py::array_t<std::complex<double>> to_numpy(const Eigen::VectorXcd& x);

/// "NAME =" and the matrix with its row and column names, 6 significant digits (the reprs).
std::string matrix_table(const char* name, const MatX& M, const std::vector<std::string>& rows,
                         const std::vector<std::string>& columns);

/// A system argument: a momenta.StateSpace, a LinearModel (its system), or any object with A, B,
/// C, D (and dt) — scipy.signal's StateSpace (and its lti / dlti through to_ss()),
/// python-control's StateSpace — copied into a momenta StateSpace. Raises TypeError otherwise.
}  // namespace momenta::python
namespace momenta::analysis {
class StateSpace;
}
namespace momenta::python {
analysis::StateSpace state_space_arg(const py::handle& object);

/// Raises momenta.NumericalError with e's message and the attribute `result` (a run's rows up to
/// the failure).
[[noreturn]] void raise_numerical_error(const NumericalError& e, const py::object& partial_result);

/// How Python writes the options the library's messages name (common/error.hpp, OptionMessage):
/// `step` is dt=, `integrator=bdf` is integrator='bdf', `force` is force=True.
std::string python_spelling(std::string_view name, std::string_view value);

// Entry points of each area, called once by module.cpp.
void bind_errors(py::module_& m);
void bind_inertia(py::module_& m);
void bind_balancing(py::module_& m);
void bind_model(py::module_& m);
/// Model.dynamics and Model.input_names (after bind_model).
void bind_state_derivative(py::module_& m);
void bind_dynamics(py::module_& m);
void bind_simulation(py::module_& m);
void bind_analysis(py::module_& m);
void bind_control(py::module_& m);
void bind_sweep(py::module_& m);
void bind_mechanics(py::module_& m);
void bind_identify(py::module_& m);

}  // namespace momenta::python
