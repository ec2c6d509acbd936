// Small fixed-size vector and tensor types of the 2-D solvers.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sph {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

// The doubles of 2-vectors (x, y per vector) or 2x2 matrices (4 per matrix,
// column by column) stored one after the other, for loops over plain arrays:
// copied whole into a message's packed array, or read by a loop that the
// compiler vectorises (through Eigen's types it would not). None when empty.
static_assert(sizeof(Vec2) == 2 * sizeof(double) && sizeof(Mat2) == 4 * sizeof(double));
inline const double* doubles_of(const std::vector<Vec2>& vectors) {
  return vectors.empty() ? nullptr : vectors.front().data();
}
inline double* doubles_of(std::vector<Vec2>& vectors) {
  return vectors.empty() ? nullptr : vectors.front().data();
}
inline const double* doubles_of(const std::vector<Mat2>& matrices) {
  return matrices.empty() ? nullptr : matrices.front().data();
}

// A B of 2x2 matrices, by components. Eigen's product builds its result as
// two column halves on the stack and then reads it back whole, and that read
// stalls (store forwarding fails across the halves): perf put a quarter of
// the solid's stress update on it.
inline Mat2 product_2x2(const Mat2& A, const Mat2& B) {
  Mat2 AB;
  AB(0, 0) = A(0, 0) * B(0, 0) + A(0, 1) * B(1, 0);
  AB(1, 0) = A(1, 0) * B(0, 0) + A(1, 1) * B(1, 0);
  AB(0, 1) = A(0, 0) * B(0, 1) + A(0, 1) * B(1, 1);
  AB(1, 1) = A(1, 0) * B(0, 1) + A(1, 1) * B(1, 1);
  return AB;
}

}  // namespace sph
