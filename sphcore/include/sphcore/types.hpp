// Small fixed-size vector and tensor types of the 2-D solvers.
#pragma once

#include <Eigen/Core>

namespace sph {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

}  // namespace sph
