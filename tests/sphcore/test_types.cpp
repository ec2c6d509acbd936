// sph::product_2x2 is the matrix product A B, not B A or A B^T.
#include <gtest/gtest.h>

#include "sphcore/types.hpp"

namespace sph {
namespace {

TEST(Product2x2, IsTheMatrixProduct) {
  Mat2 A, B;
  A << 1.0, -2.0, 3.5, 0.25;
  B << -0.5, 4.0, 2.0, 7.0;
  const Mat2 expected = A * B;
  EXPECT_LT((product_2x2(A, B) - expected).norm(), 1e-15 * expected.norm());
  // The operands do not commute, nor is either symmetric: an index swapped
  // anywhere would show.
  EXPECT_GT((B * A - expected).norm(), 1.0);
  EXPECT_GT((A * B.transpose() - expected).norm(), 1.0);
}

}  // namespace
}  // namespace sph
