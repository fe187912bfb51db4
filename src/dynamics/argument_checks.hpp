#pragma once
// Always-on size checks at the door of every public dynamics algorithm (Pinocchio checks sizes on
// every algorithm the same way): a few integer comparisons per call, measured at under 2 % of the
// 7-link ABA (docs/dynamics.md). A wrong size throws InvalidArgument naming the algorithm, the
// argument, the size given and the size expected, instead of reading out of bounds.

#include <span>

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics::detail {

[[noreturn]] void throw_size_error(const char* algorithm, const char* argument, long given,
                                   long expected, const char* expected_name);

inline void check_size(const char* algorithm, const char* argument, long given, long expected,
                       const char* expected_name) {
  if (given != expected) [[unlikely]] {
    throw_size_error(algorithm, argument, given, expected, expected_name);
  }
}

/// data built for a model of this size.
inline void check_data(const char* algorithm, const Model& model, const Data& data) {
  check_size(algorithm, "data (built for another model?)", static_cast<long>(data.X_WB.size()),
             model.num_bodies(), "one pose per body");
}

/// data built for a model of this size; q of size nq.
inline void check_data_and_q(const char* algorithm, const Model& model, const Data& data,
                             VecRef q) {
  check_data(algorithm, model, data);
  check_size(algorithm, "q", q.size(), model.nq(), "nq");
}

/// A vector of the velocity space (v, vdot, tau) of size nv.
inline void check_nv(const char* algorithm, const char* argument, const Model& model, VecRef x) {
  check_size(algorithm, argument, x.size(), model.nv(), "nv");
}

/// External wrenches: none, or one per body (the world's included).
inline void check_f_ext(const char* algorithm, const Model& model, std::span<const Vec6> f_ext) {
  if (!f_ext.empty()) {
    check_size(algorithm, "f_ext", static_cast<long>(f_ext.size()), model.num_bodies(),
               "one wrench per body, or none");
  }
}

/// The arguments of an inverse-dynamics pass (rnea, joint_reactions, rnea_derivatives): data, q,
/// v, vdot and f_ext, each checked as above.
inline void check_inverse_dynamics(const char* algorithm, const Model& model, const Data& data,
                                   VecRef q, VecRef v, VecRef vdot, std::span<const Vec6> f_ext) {
  check_data_and_q(algorithm, model, data, q);
  check_nv(algorithm, "v", model, v);
  check_nv(algorithm, "vdot", model, vdot);
  check_f_ext(algorithm, model, f_ext);
}

}  // namespace momenta::dynamics::detail
