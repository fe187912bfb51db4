#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <complex>

#include "bindings.hpp"

namespace momenta::python {
namespace {

std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) {
    text += (d ? ", " : "") + std::to_string(a.shape(d));
  }
  return text + (a.ndim() == 1 ? ",)" : ")");
}

// Already a C-contiguous, aligned float64 array in native byte order: read in place.
bool is_native_float64_vector(const py::handle& object) {
  const auto& api = py::detail::npy_api::get();
  if (!api.PyArray_Check_(object.ptr())) return false;
  const auto* array = py::detail::array_proxy(object.ptr());
  const auto* descr = py::detail::array_descriptor_proxy(array->descr);
  constexpr int kInPlace =
      py::detail::npy_api::NPY_ARRAY_C_CONTIGUOUS_ | py::detail::npy_api::NPY_ARRAY_ALIGNED_;
  constexpr char kSwapped = std::endian::native == std::endian::little ? '>' : '<';
  return descr->type_num == py::detail::npy_api::NPY_DOUBLE_ && descr->byteorder != kSwapped &&
         (array->flags & kInPlace) == kInPlace;
}

py::array_t<double> new_array(int ndim, Py_intptr_t* shape) {
  auto& api = py::detail::npy_api::get();
  PyObject* descr = api.PyArray_DescrFromType_(py::detail::npy_api::NPY_DOUBLE_);
  PyObject* array = api.PyArray_NewFromDescr_(api.PyArray_Type_, descr, ndim, shape, nullptr,
                                              nullptr, 0, nullptr);  // steals descr
  if (array == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::array_t<double>>(array);
}

}  // namespace

py::array_t<double> new_float_array(py::ssize_t rows) {
  Py_intptr_t shape[1] = {rows};
  return new_array(1, shape);
}

py::array_t<double> new_float_array(py::ssize_t rows, py::ssize_t cols) {
  Py_intptr_t shape[2] = {rows, cols};
  return new_array(2, shape);
}

py::array_t<double, py::array::c_style> as_float_array(const py::handle& object,
                                                       std::string_view name) {
  // The hot path: already a C-contiguous float64 array, taken as it is.
  using Float64 = py::array_t<double, py::array::c_style>;
  if (is_native_float64_vector(object)) return py::reinterpret_borrow<Float64>(object);
  // Booleans, integers and floats are real numbers; complex numbers, strings and objects are not.
  const py::array raw = py::array::ensure(object);
  const char kind = raw ? raw.dtype().kind() : 'O';
  if (!raw || (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')) {
    throw py::value_error(fmt::format("{}: expected an array of real numbers, got {}", name,
                                      std::string(py::str(py::type::of(object)))));
  }
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(raw);
}

Eigen::Map<const VecX> vector_arg(const py::handle& object, std::string_view name,
                                  Eigen::Index size, std::string_view what, ArgStorage& storage) {
  const auto array = as_float_array(object, name);
  storage = array;
  if (array.ndim() != 1 || (size >= 0 && array.shape(0) != size)) {
    const std::string expected =
        size >= 0 ? fmt::format("a vector of {} numbers ({})", size, what) : "a vector";
    throw py::value_error(
        fmt::format("{}: expected {}, got shape {}", name, expected, shape_text(array)));
  }
  return {array.data(), static_cast<Eigen::Index>(array.shape(0))};
}

Vec3 vec3_arg(const py::handle& object, std::string_view name) {
  ArgStorage storage;
  return vector_arg(object, name, 3, "x, y, z", storage);
}

MatX matrix_arg(const py::handle& object, std::string_view name, Eigen::Index rows,
                Eigen::Index cols) {
  const auto a = as_float_array(object, name);
  const bool fits =
      a.ndim() == 2 && (rows < 0 || a.shape(0) == rows) && (cols < 0 || a.shape(1) == cols);
  if (!fits) {
    const auto dim = [](Eigen::Index n) { return n < 0 ? std::string("n") : std::to_string(n); };
    throw py::value_error(fmt::format("{}: expected a {} × {} matrix, got shape {}", name,
                                      dim(rows), dim(cols), shape_text(a)));
  }
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  return Eigen::Map<const RowMajor>(a.data(), a.shape(0), a.shape(1));
}

Mat3 mat3_arg(const py::handle& object, std::string_view name) {
  return matrix_arg(object, name, 3, 3);
}

py::array_t<std::complex<double>> to_numpy(const Eigen::VectorXcd& x) {
  py::array_t<std::complex<double>> out(x.size());
  std::copy(x.data(), x.data() + x.size(), out.mutable_data());
  return out;
}

}  // namespace momenta::python
