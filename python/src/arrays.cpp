#include <fmt/format.h>

#include <algorithm>
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

}  // namespace

py::array_t<double, py::array::c_style> as_float_array(const py::handle& object,
                                                       std::string_view name) {
  // The hot path: already a C-contiguous float64 array, taken as it is.
  using Float64 = py::array_t<double, py::array::c_style>;
  if (Float64::check_(object)) return py::reinterpret_borrow<Float64>(object);
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
                                  Eigen::Index size, std::string_view what,
                                  py::array_t<double, py::array::c_style>& storage) {
  storage = as_float_array(object, name);
  if (storage.ndim() != 1 || (size >= 0 && storage.shape(0) != size)) {
    const std::string expected =
        size >= 0 ? fmt::format("a vector of {} numbers ({})", size, what) : "a vector";
    throw py::value_error(
        fmt::format("{}: expected {}, got shape {}", name, expected, shape_text(storage)));
  }
  return {storage.data(), static_cast<Eigen::Index>(storage.shape(0))};
}

Vec3 vec3_arg(const py::handle& object, std::string_view name) {
  py::array_t<double, py::array::c_style> storage;
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
