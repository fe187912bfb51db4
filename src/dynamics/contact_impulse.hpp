#pragma once
// What impulse.cpp and simultaneous_impact.cpp share about a contact's two points.

#include <vector>

#include "momenta/dynamics/impulse.hpp"

namespace momenta::dynamics::detail {

/// The pair ±P: P on B's point, −P on A's (none on the world).
std::vector<PointImpulse> impulse_pair(const PointContact& c, const Vec3& P);

/// v_Pb − v_Pa at (q, v), in W.
Vec3 relative_velocity(const Model& model, Data& data, VecRef q, VecRef v, const PointContact& c);

/// n · (v_Pb − v_Pa) at (q, v).
double normal_speed(const Model& model, Data& data, VecRef q, VecRef v, const PointContact& c);

}  // namespace momenta::dynamics::detail
