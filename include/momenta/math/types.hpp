#pragma once
// Short names for the Eigen types momenta uses everywhere. All quantities are SI.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace momenta {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Mat6X = Eigen::Matrix<double, 6, Eigen::Dynamic>;  ///< Spatial vectors side by side.
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;
using Quat = Eigen::Quaterniond;

/// A read-only view of any contiguous vector of doubles: a VecX, a segment of one, an
/// Eigen::Map over a buffer (a NumPy array) — bound without a copy. The algorithms' vector
/// inputs take this.
using VecRef = Eigen::Ref<const VecX>;

}  // namespace momenta
