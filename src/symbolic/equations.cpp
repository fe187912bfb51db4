// The equations of motion in symbols: derive_equations runs the derivation (derivation.hpp) and
// Equations answers for it (the names, the parameters; printing.cpp and linearization.cpp the
// rest). identifier() makes a name a symbol's.

#include "momenta/symbolic/equations.hpp"

#include <cctype>
#include <memory>
#include <string>

#include "derivation.hpp"
#include "equations_impl.hpp"

namespace momenta::symbolic {

namespace detail {
std::string identifier(const std::string& name) {
  std::string s = name;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) s = "_" + s;
  return s;
}
}  // namespace detail

using detail::Derivation;

Equations::Equations(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
Equations::~Equations() = default;
Equations::Equations(const Equations&) = default;
Equations& Equations::operator=(const Equations&) = default;

const std::vector<std::string>& Equations::configuration_names() const { return impl_->q_names; }
const std::vector<std::string>& Equations::speed_names() const { return impl_->v_names; }
const std::vector<std::string>& Equations::acceleration_names() const { return impl_->a_names; }
const std::vector<int>& Equations::free_speeds() const { return impl_->free; }
const std::vector<std::string>& Equations::input_names() const { return impl_->input_names; }
const std::vector<Parameter>& Equations::parameters() const { return impl_->parameters; }
const std::vector<FormNumber>& Equations::form_numbers() const { return impl_->form_numbers; }

Equations derive_equations(const model::Model& model, const EquationOptions& options) {
  Derivation derivation(model, options);
  return Equations(std::make_shared<const Equations::Impl>(derivation.run()));
}

}  // namespace momenta::symbolic
