// sph::OuterProductSum is the sum of the outer products a b^T, not of b a^T.
#include <gtest/gtest.h>

#include "sphcore/outer_product_sum.hpp"

namespace sph {
namespace {

TEST(OuterProductSum, IsTheSumOfEachAColumnTimesBRow) {
  const Vec2 a[] = {{1.0, 2.0}, {-3.0, 0.5}, {0.25, -4.0}};
  const Vec2 b[] = {{7.0, -1.0}, {2.0, 3.0}, {-0.5, 6.0}};
  OuterProductSum sum;
  Mat2 expected = Mat2::Zero();
  for (int k = 0; k < 3; ++k) {
    sum.add(a[k], b[k]);
    expected += a[k] * b[k].transpose();
  }
  EXPECT_LT((sum.matrix() - expected).norm(), 1e-14 * expected.norm()) << sum.matrix();
  EXPECT_GT((expected - expected.transpose()).norm(), 1.0);  // the order matters here
  EXPECT_EQ(OuterProductSum().matrix(), Mat2::Zero());
}

}  // namespace
}  // namespace sph
