#pragma once
// How small a residual can be computed: the round-off floor Newton's test must not ask to go
// below (PlainNewton).
#include "base/LinearAlgebra.hpp"

namespace contactlab {

// eps * || |A| |x| ||_2: the componentwise bound on the round-off of A x in double precision, up
// to a factor of the entries per row (Higham, "Accuracy and Stability of Numerical Algorithms",
// 2nd ed., section 3.5). A residual R(x) whose Jacobian is A sums terms of that size (element
// forces are K_e u_e), so it carries that round-off too, whatever its true value: a body that a
// Newton iterate throws far (a load-controlled body held by soft springs while its contact is
// frozen open) cannot have its residual computed below that floor, however small the target
// (doc/algorithms.md "Round-off floor"). A's domain map must be x's map. Collective over A's
// communicator; one pass over A's values and an import of x onto A's column map.
double residualRoundoff(const Matrix& A, const MultiVector& x);

}  // namespace contactlab
