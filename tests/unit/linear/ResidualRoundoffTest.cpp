// residualRoundoff: eps || |A| |x| ||_2, a known answer on 1 and 2 ranks (the tridiagonal
// [-1 2 -1] with x alternating in sign: |A| |x| sums every entry's magnitude, where A x cancels).
#include "linear/ResidualRoundoff.hpp"

#include <Tpetra_Core.hpp>

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace contactlab {
namespace {

TEST(ResidualRoundoff, IsEpsilonTimesTheNormOfAbsoluteAtimesAbsoluteX) {
  const GO n = 6;
  auto comm = Tpetra::getDefaultComm();
  auto map = Teuchos::rcp(new Map(n, 0, comm));
  Matrix A(map, 3);
  for (LO i = 0; i < static_cast<LO>(map->getNodeNumElements()); ++i) {
    const GO row = map->getGlobalElement(i);
    for (GO col = std::max<GO>(row - 1, 0); col <= std::min<GO>(row + 1, n - 1); ++col) {
      const double value = col == row ? 2.0 : -1.0;
      A.insertGlobalValues(row, 1, &value, &col);
    }
  }
  A.fillComplete();
  MultiVector x(map, 1);
  auto data = x.getDataNonConst(0);
  for (LO i = 0; i < static_cast<LO>(data.size()); ++i) {
    const GO row = map->getGlobalElement(i);
    data[i] = (row % 2 ? -1.0 : 1.0) * 1e6 * static_cast<double>(row + 1);
  }
  // |A| |x| row i: 2 (i + 1) + i + (i + 2) = 4 (i + 1) inside, 2 + 2 = 4 and 2 n + (n - 1) at
  // the ends (times 1e6).
  double sum = 0;
  for (GO i = 0; i < n; ++i) {
    double row = 2.0 * static_cast<double>(i + 1);
    if (i > 0) row += static_cast<double>(i);
    if (i < n - 1) row += static_cast<double>(i + 2);
    sum += row * row;
  }
  const double expected = std::numeric_limits<double>::epsilon() * 1e6 * std::sqrt(sum);
  EXPECT_NEAR(residualRoundoff(A, x), expected, 1e-12 * expected);
}

}  // namespace
}  // namespace contactlab
