// momenta's exceptions as a Python hierarchy. Each class derives from momenta.Error and from the
// built-in exception a Python user would catch for it, so `except ValueError` works as well as
// `except momenta.InvalidArgument`:
//
//   Error(Exception)
//   ├── InvalidArgument(Error, ValueError)
//   │   └── InvalidInertia(InvalidArgument)
//   ├── MeshError(Error, ValueError)
//   ├── ParseError(Error, ValueError)     .file, .line, .column
//   ├── FileError(Error, OSError)
//   ├── NumericalError(Error, ArithmeticError)   .result: the rows up to the failure, when a run
//   └── Interrupted(Error)
//
// Messages are the C++ ones (file:line:column: key: message for files).

#include <Python.h>

#include <array>
#include <string>
#include <string_view>
#include <utility>

#include "bindings.hpp"
#include "momenta/common/error.hpp"

namespace momenta::python {
namespace {

// New exception classes, owned by the module (kept alive for the translator below).
PyObject* new_exception(py::module_& m, const char* name, py::tuple bases, const char* doc) {
  const std::string qualified = std::string("momenta.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), /*dict=*/nullptr);
  if (!type) throw py::error_already_set();
  m.add_object(name, py::handle(type));
  return type;
}

struct Classes {
  PyObject* error = nullptr;
  PyObject* invalid_argument = nullptr;
  PyObject* invalid_inertia = nullptr;
  PyObject* mesh_error = nullptr;
  PyObject* parse_error = nullptr;
  PyObject* file_error = nullptr;
  PyObject* numerical_error = nullptr;
  PyObject* interrupted = nullptr;
};
Classes classes;

void raise(PyObject* type, const Error& e) {
  PyErr_SetString(type, e.spelled(python_spelling).c_str());
}

void raise_parse_error(const ParseError& e) {
  py::object error =
      py::reinterpret_borrow<py::object>(classes.parse_error)(e.spelled(python_spelling));
  error.attr("file") = e.file();
  error.attr("line") = e.line();
  error.attr("column") = e.column();
  PyErr_SetObject(classes.parse_error, error.ptr());
}

}  // namespace

std::string python_spelling(std::string_view name, std::string_view value) {
  // The library's names whose keywords differ from <name>=.
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 3> kKeywords{{
      {"step", "dt"},
      {"relative_tolerance", "rtol"},
      {"absolute_tolerance", "atol"},
  }};
  std::string keyword(name);
  for (const auto& [option, spelled] : kKeywords) {
    if (option == name) keyword = spelled;
  }
  // MJCF rather than URDF is a function of its own; switches (overwrite, resume, record
  // reactions) are True; a name's value a string.
  if (name == "mjcf") return "to_mjcf()";
  if (name == "code") return "the command line's `momenta equations --cpp`";
  if (name == "linearize") return "momenta.linearize()";
  if (name == "force" || name == "resume" || name == "reactions") {
    return keyword + "=True";
  }
  if (value.empty()) return keyword + "=";
  const bool number = value.find_first_not_of("0123456789.eE+-") == std::string_view::npos;
  return keyword + "=" + (number ? std::string(value) : "'" + std::string(value) + "'");
}

void raise_numerical_error(const NumericalError& e, const py::object& partial_result) {
  py::object error =
      py::reinterpret_borrow<py::object>(classes.numerical_error)(e.spelled(python_spelling));
  error.attr("result") = partial_result;
  PyErr_SetObject(classes.numerical_error, error.ptr());
  throw py::error_already_set();
}

void bind_errors(py::module_& m) {
  const py::handle exception(PyExc_Exception);
  classes.error =
      new_exception(m, "Error", py::make_tuple(exception), "Base of every error momenta raises.");
  const py::handle error(classes.error);
  classes.invalid_argument =
      new_exception(m, "InvalidArgument", py::make_tuple(error, py::handle(PyExc_ValueError)),
                    "An argument outside its documented domain (a negative length, a wrong "
                    "size, an unknown name).");
  classes.invalid_inertia =
      new_exception(m, "InvalidInertia", py::make_tuple(py::handle(classes.invalid_argument)),
                    "Mass properties no physical body has.");
  classes.mesh_error =
      new_exception(m, "MeshError", py::make_tuple(error, py::handle(PyExc_ValueError)),
                    "A triangle mesh that does not bound a solid.");
  classes.parse_error = new_exception(
      m, "ParseError", py::make_tuple(error, py::handle(PyExc_ValueError)),
      "A malformed input file; str() reads 'file:line:column: message' and the attributes "
      "file, line and column (1-based; 0 when unknown) say where.");
  classes.file_error =
      new_exception(m, "FileError", py::make_tuple(error, py::handle(PyExc_OSError)),
                    "A file that cannot be read, or does not exist.");
  classes.numerical_error =
      new_exception(m, "NumericalError", py::make_tuple(error, py::handle(PyExc_ArithmeticError)),
                    "A non-finite value or a failure to converge at run time. Raised by simulate, "
                    "its attribute result holds the rows recorded up to the failure.");
  classes.interrupted = new_exception(m, "Interrupted", py::make_tuple(error),
                                      "A run stopped because it was asked to.");

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ParseError& e) {
      raise_parse_error(e);
    } catch (const InvalidInertia& e) {
      raise(classes.invalid_inertia, e);
    } catch (const InvalidArgument& e) {
      raise(classes.invalid_argument, e);
    } catch (const MeshError& e) {
      raise(classes.mesh_error, e);
    } catch (const FileError& e) {
      raise(classes.file_error, e);
    } catch (const NumericalError& e) {
      raise(classes.numerical_error, e);
    } catch (const Interrupted& e) {
      raise(classes.interrupted, e);
    } catch (const Error& e) {
      raise(classes.error, e);
    }
  });
}

}  // namespace momenta::python
