// The symmetric eigensolver the finite-strain laws rest on (tensor3::symmetricEigen):
// reconstruction and orthonormal vectors, also for repeated and nearly repeated values.
#include "tests/unit/materials/MaterialTestSupport.hpp"

#include "core/materials/Tensor3.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <vector>

namespace contactlab {
namespace {

using namespace test;
using tensor3::Mat3;

TEST(Tensor3, SymmetricEigenReconstructsWithOrthonormalVectorsAlsoForRepeatedValues) {
  std::mt19937 gen(30);
  std::vector<Mat3> cases = {tensor3::identity(), Mat3{}, diagonal(2, 2, 5), diagonal(3, 1, 3)};
  const Mat3 Q0 = rotation({1, 2, 3}, 0.9);
  for (const Mat3& D : {diagonal(2, 2, 5), diagonal(1, 1 + 1e-12, 4), diagonal(7, 7, 7)})
    cases.push_back(tensor3::multiply(Q0, tensor3::multiplyTranspose(D, Q0)));
  for (int k = 0; k < 20; ++k) {
    const Mat3 F = randomF(gen, k % 2 == 1);
    cases.push_back(tensor3::multiplyTranspose(F, F));
  }
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const Mat3& A = cases[c];
    std::array<double, 3> values;
    Mat3 Q;
    ASSERT_TRUE(tensor3::symmetricEigen(A, values, Q)) << c;
    const double scale = std::max(1.0, maxAbs(A.data(), 9));
    Mat3 rebuilt{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int a = 0; a < 3; ++a)
          rebuilt[i * 3 + j] += values[a] * Q[i * 3 + a] * Q[j * 3 + a];
    EXPECT_LT(maxDifference(rebuilt, A), 1e-14 * scale) << c;
    EXPECT_LT(maxDifference(tensor3::transposeMultiply(Q, Q), tensor3::identity()), 1e-14) << c;
  }
  std::array<double, 3> values;
  Mat3 Q;
  Mat3 bad = tensor3::identity();
  bad[1] = std::nan("");
  EXPECT_FALSE(tensor3::symmetricEigen(bad, values, Q));
}

}  // namespace
}  // namespace contactlab
