#include "momenta/analysis/state_space.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <Eigen/Cholesky>

#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"

namespace momenta::analysis {
namespace {

// Throws unless `matrix` is rows×cols.
void check_size(const MatX& matrix, const char* what, Eigen::Index rows, Eigen::Index cols,
                const char* why) {
  if (matrix.rows() != rows || matrix.cols() != cols) {
    throw InvalidArgument(fmt::format("StateSpace: {} is {}×{} but must be {}×{} ({})", what,
                                      matrix.rows(), matrix.cols(), rows, cols, why));
  }
}

// Throws naming the first entry that is NaN or infinite.
void check_matrix_finite(const MatX& matrix, const char* what) {
  for (Eigen::Index j = 0; j < matrix.cols(); ++j) {
    for (Eigen::Index i = 0; i < matrix.rows(); ++i) {
      if (!std::isfinite(matrix(i, j))) {
        throw InvalidArgument(
            fmt::format("StateSpace: {}({}, {}) = {} is not finite", what, i, j, matrix(i, j)));
      }
    }
  }
}

// Fills an empty name list with prefix1..prefixN, else checks its length and uniqueness.
std::vector<std::string> checked_names(std::vector<std::string> names, std::size_t count,
                                       const char* prefix, const char* what) {
  if (names.empty()) {
    names.reserve(count);
    for (std::size_t i = 0; i < count; ++i) names.push_back(fmt::format("{}{}", prefix, i + 1));
    return names;
  }
  if (names.size() != count) {
    throw InvalidArgument(
        fmt::format("StateSpace: {} {} names given for {} {}s", names.size(), what, count, what));
  }
  std::set<std::string_view> seen;
  for (const std::string& name : names) {
    if (name.empty()) throw InvalidArgument(fmt::format("StateSpace: an empty {} name", what));
    if (!seen.insert(name).second) {
      throw InvalidArgument(fmt::format("StateSpace: {} name '{}' appears twice", what, name));
    }
  }
  return names;
}

// Index of `name` in `names`, or InvalidArgument listing them with a suggestion.
std::size_t index_of(const std::vector<std::string>& names, std::string_view name,
                     const char* what) {
  const auto found = std::find(names.begin(), names.end(), name);
  if (found != names.end()) return static_cast<std::size_t>(found - names.begin());
  const std::vector<std::string_view> candidates(names.begin(), names.end());
  throw InvalidArgument(fmt::format("StateSpace: no {} named '{}'{}; the {}s are: {}", what, name,
                                    did_you_mean(name, candidates), what, fmt::join(names, ", ")));
}

}  // namespace

StateSpace::StateSpace(MatX A, MatX B, MatX C, MatX D, std::vector<std::string> state_names,
                       std::vector<std::string> input_names, std::vector<std::string> output_names,
                       double sample_time)
    : A_(std::move(A)),
      B_(std::move(B)),
      C_(std::move(C)),
      D_(std::move(D)),
      sample_time_(sample_time) {
  if (!std::isfinite(sample_time) || sample_time < 0.0) {
    throw InvalidArgument(
        fmt::format("StateSpace: sample time {} s: it must be 0 (continuous) or a positive period",
                    sample_time));
  }
  // A fixes n; B's columns fix m and C's rows fix p, the rest must agree.
  const Eigen::Index n = A_.rows();
  check_size(A_, "A", n, n, "A must be square");
  check_size(B_, "B", n, B_.cols(), "B has one row per state");
  check_size(C_, "C", C_.rows(), n, "C has one column per state");
  if (D_.size() == 0) D_ = MatX::Zero(C_.rows(), B_.cols());
  check_size(D_, "D", C_.rows(), B_.cols(), "D is outputs × inputs");
  check_matrix_finite(A_, "A");
  check_matrix_finite(B_, "B");
  check_matrix_finite(C_, "C");
  check_matrix_finite(D_, "D");
  state_names_ = checked_names(std::move(state_names), state_count(), "x", "state");
  input_names_ = checked_names(std::move(input_names), input_count(), "u", "input");
  output_names_ = checked_names(std::move(output_names), output_count(), "y", "output");
}

std::size_t StateSpace::input_index(std::string_view name) const {
  return index_of(input_names_, name, "input");
}
std::size_t StateSpace::output_index(std::string_view name) const {
  return index_of(output_names_, name, "output");
}
std::size_t StateSpace::state_index(std::string_view name) const {
  return index_of(state_names_, name, "state");
}

StateSpace StateSpace::with_units(Units units) const {
  const auto check = [](const std::vector<std::string>& list, std::size_t count, const char* what) {
    if (!list.empty() && list.size() != count) {
      throw InvalidArgument(
          fmt::format("StateSpace: {} {} units for {} {}s", list.size(), what, count, what));
    }
  };
  check(units.states, state_count(), "state");
  check(units.inputs, input_count(), "input");
  check(units.outputs, output_count(), "output");
  StateSpace out = *this;
  out.units_ = std::move(units);
  return out;
}

StateSpace StateSpace::siso(std::size_t input, std::size_t output) const {
  if (input >= input_count()) {
    throw InvalidArgument(fmt::format(
        "StateSpace::siso: input index {} but the system has {} inputs", input, input_count()));
  }
  if (output >= output_count()) {
    throw InvalidArgument(fmt::format(
        "StateSpace::siso: output index {} but the system has {} outputs", output, output_count()));
  }
  const auto i = static_cast<Eigen::Index>(input);
  const auto o = static_cast<Eigen::Index>(output);
  const auto pick = [](const std::vector<std::string>& units, std::size_t k) {
    return units.empty() ? std::vector<std::string>{} : std::vector<std::string>{units[k]};
  };
  return StateSpace(A_, B_.col(i), C_.row(o), D_.block(o, i, 1, 1), state_names_,
                    {input_names_[input]}, {output_names_[output]}, sample_time_)
      .with_units({units_.states, pick(units_.inputs, input), pick(units_.outputs, output)});
}

StateSpace StateSpace::siso(std::string_view input, std::string_view output) const {
  return siso(input_index(input), output_index(output));
}

StateSpace second_order_state_space(const MatX& M, const MatX& C_damping, const MatX& K,
                                    const MatX& F, const MatX& Cq, const MatX& Cv,
                                    std::vector<std::string> coordinate_names,
                                    std::vector<std::string> input_names,
                                    std::vector<std::string> output_names) {
  // Sizes: nq coordinates from M, m inputs from F, p outputs from Cq.
  const Eigen::Index nq = M.rows();
  const auto require = [](const MatX& X, const char* what, Eigen::Index rows, Eigen::Index cols) {
    if (X.rows() != rows || X.cols() != cols) {
      throw InvalidArgument(fmt::format("second_order_state_space: {} is {}×{} but must be {}×{}",
                                        what, X.rows(), X.cols(), rows, cols));
    }
  };
  require(M, "M", nq, nq);
  require(C_damping, "C (damping)", nq, nq);
  require(K, "K", nq, nq);
  require(F, "F", nq, F.cols());
  require(Cq, "Cq", Cq.rows(), nq);
  require(Cv, "Cv", Cq.rows(), nq);
  if (!coordinate_names.empty() && coordinate_names.size() != static_cast<std::size_t>(nq)) {
    throw InvalidArgument(
        fmt::format("second_order_state_space: {} coordinate names for {} "
                    "coordinates",
                    coordinate_names.size(), nq));
  }

  // M must be symmetric positive definite: it is a mass matrix.
  const double scale = M.cwiseAbs().maxCoeff();
  if (!M.allFinite() || (M - M.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale) {
    throw InvalidArgument("second_order_state_space: the mass matrix M is not symmetric");
  }
  const Eigen::LLT<MatX> mass(M);
  if (mass.info() != Eigen::Success) {
    throw InvalidArgument(
        fmt::format("second_order_state_space: the mass matrix M is not positive definite:\n{}",
                    fmt::streamed(M)));
  }

  // First-order companion form x = [q; q̇].
  MatX A = MatX::Zero(2 * nq, 2 * nq);
  A.topRightCorner(nq, nq).setIdentity();
  A.bottomLeftCorner(nq, nq) = -mass.solve(K);
  A.bottomRightCorner(nq, nq) = -mass.solve(C_damping);
  MatX B = MatX::Zero(2 * nq, F.cols());
  B.bottomRows(nq) = mass.solve(F);
  MatX C(Cq.rows(), 2 * nq);
  C << Cq, Cv;

  // Names: q_i then q_i_dot.
  if (coordinate_names.empty()) {
    for (Eigen::Index i = 0; i < nq; ++i) coordinate_names.push_back(fmt::format("q{}", i + 1));
  }
  std::vector<std::string> state_names = coordinate_names;
  for (const std::string& name : coordinate_names) state_names.push_back(name + "_dot");
  return StateSpace(std::move(A), std::move(B), std::move(C), MatX(), std::move(state_names),
                    std::move(input_names), std::move(output_names));
}

}  // namespace momenta::analysis
