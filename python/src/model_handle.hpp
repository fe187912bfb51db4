#pragma once
// What momenta.Model holds: the model file (or a built model wrapped as one), shared by every
// object made from it (workspaces, simulations), so a model outlives them all.

#include <memory>

#include "bindings.hpp"
#include "momenta/io/model_file.hpp"

namespace momenta::python {

struct StateDerivative;  // state_derivative.cpp

struct ModelHandle {
  std::shared_ptr<const io::ModelFile> file;
  /// Model.dynamics' systems, made at its first call and shared by copies of this handle.
  mutable std::shared_ptr<StateDerivative> state_derivative = nullptr;
  const model::Model& model() const { return file->model; }
};

/// A body given by name (str) or index (int), checked against the model: InvalidArgument with a
/// did-you-mean for an unknown name, IndexError for an index out of range.
int body_index_arg(const ModelHandle& h, const py::handle& body);

void bind_model_builder(py::module_& m);

}  // namespace momenta::python
