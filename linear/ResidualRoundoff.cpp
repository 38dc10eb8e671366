#include "linear/ResidualRoundoff.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cmath>
#include <limits>

namespace contactlab {

double residualRoundoff(const Matrix& A, const MultiVector& x) {
  MultiVector onColumns(A.getColMap(), x.getNumVectors());
  const auto importer = A.getGraph()->getImporter();
  if (importer.is_null())
    Tpetra::deep_copy(onColumns, x);
  else
    onColumns.doImport(x, *importer, Tpetra::INSERT);
  const auto local = A.getLocalMatrixHost();
  const auto xv = onColumns.getLocalViewHost(Tpetra::Access::ReadOnly);
  double sum = 0.0;
  for (std::size_t j = 0; j < x.getNumVectors(); ++j)
    for (std::size_t i = 0; i < static_cast<std::size_t>(local.numRows()); ++i) {
      double row = 0.0;
      for (auto k = local.graph.row_map(i); k < local.graph.row_map(i + 1); ++k)
        row += std::fabs(local.values(k)) * std::fabs(xv(local.graph.entries(k), j));
      sum += row * row;
    }
  double total = 0.0;
  Teuchos::reduceAll(*A.getComm(), Teuchos::REDUCE_SUM, sum, Teuchos::outArg(total));
  return std::numeric_limits<double>::epsilon() * std::sqrt(total);
}

}  // namespace contactlab
