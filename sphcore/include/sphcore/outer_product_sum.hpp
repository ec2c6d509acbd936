// A sum of outer products a (x) b of 2-vectors, as the gradients of a field
// over a particle's neighbours are summed (the deformation gradient of the
// total-Lagrangian solid, the fitted velocity gradient of the Jaumann one).
// It is kept as the two columns of the 2x2 matrix, b_x a and b_y a, each one
// register: summed as an Eigen 2x2 matrix it went through the stack, and
// reading it back whole from two half-width stores stalled every term.
// GradientSums (renormalisation.hpp) keeps its sums as vectors for the same
// reason, in its own code: built on this class, it gave the same bits but
// the water's pass ran slower.
#pragma once

#include "sphcore/types.hpp"

namespace sph {

class OuterProductSum {
 public:
  void add(const Vec2& a, const Vec2& b) {
    column_x_ += a * b.x();
    column_y_ += a * b.y();
  }

  // sum a b^T.
  Mat2 matrix() const {
    Mat2 sum;
    sum << column_x_, column_y_;
    return sum;
  }

 private:
  Vec2 column_x_ = Vec2::Zero(), column_y_ = Vec2::Zero();
};

}  // namespace sph
