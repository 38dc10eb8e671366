// BelosSolver: CG with every preconditioner on SPD matrices, GMRES on a non-symmetric one, the
// near-null space for MueLu, and the error of a solve that does not converge.
#include "LinearTestProblems.hpp"

#include "linear/BelosSolver.hpp"
#include "linear/MumpsSolver.hpp"

#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>

namespace contactlab {
namespace {

using test::Layout;
using Kind = PreconditionerOptions::Kind;
using Method = BelosSolver::Method;

Teuchos::RCP<const Comm> world() {
  return Tpetra::getDefaultComm();
}

BelosSolver::Options optionsWith(Method method, Kind kind) {
  BelosSolver::Options o;
  o.method = method;
  o.preconditioner.kind = kind;
  o.tolerance = 1e-12;
  return o;
}

Teuchos::RCP<MultiVector> mumpsSolution(const Teuchos::RCP<Matrix>& A, const MultiVector& b) {
  MumpsSolver mumps({}, world());
  mumps.setMatrix(A, true);
  auto x = Teuchos::rcp(new MultiVector(A->getDomainMap(), b.getNumVectors()));
  mumps.solve(b, *x);
  return x;
}

struct BelosCase {
  Method method;
  Kind kind;
  Layout layout;
};

class BelosCases : public ::testing::TestWithParam<BelosCase> {};

TEST_P(BelosCases, AgreesWithMumps) {
  const auto& c = GetParam();
  const auto A = c.method == Method::cg ? test::laplacian3D(12, c.layout, world())
                                        : test::convectionDiffusion(30, 5.0, c.layout, world());
  const auto b = test::rightHandSide(*A, 2);
  BelosSolver solver(optionsWith(c.method, c.kind), world());
  solver.setMatrix(A, true);
  MultiVector x(A->getDomainMap(), 2);
  x.putScalar(1e3);  // ignored: the initial guess is zero
  solver.solve(*b, x);
  EXPECT_LT(solver.stats().relativeResidual, 1e-11);
  EXPECT_GT(solver.stats().iterations, 0);
  EXPECT_LT(test::relativeDifference(x, *mumpsSolution(A, *b)), 1e-8);
  // A second matrix: the preconditioner is rebuilt.
  A->resumeFill();
  A->scale(3.0);
  A->fillComplete();
  solver.setMatrix(A, false);
  MultiVector x3(A->getDomainMap(), 2);
  solver.solve(*b, x3);
  x3.scale(3.0);
  EXPECT_LT(test::relativeDifference(x3, x), 1e-8);
  EXPECT_EQ(solver.stats().factorizations, 2);
}

INSTANTIATE_TEST_SUITE_P(
    Preconditioners, BelosCases,
    ::testing::Values(BelosCase{Method::cg, Kind::none, Layout::contiguous},
                      BelosCase{Method::cg, Kind::ifpack2Sgs, Layout::scattered},
                      BelosCase{Method::cg, Kind::ifpack2Riluk, Layout::contiguous},
                      BelosCase{Method::cg, Kind::ifpack2Riluk, Layout::scattered},
                      BelosCase{Method::cg, Kind::muelu, Layout::contiguous},
                      BelosCase{Method::cg, Kind::muelu, Layout::scattered},
                      BelosCase{Method::gmres, Kind::none, Layout::contiguous},
                      BelosCase{Method::gmres, Kind::ifpack2Sgs, Layout::scattered},
                      BelosCase{Method::gmres, Kind::ifpack2Riluk, Layout::contiguous},
                      BelosCase{Method::gmres, Kind::ifpack2Ilut, Layout::scattered},
                      BelosCase{Method::gmres, Kind::muelu, Layout::contiguous}));

TEST(BelosSolver, MueLuUsesTheNearNullSpace) {
  const auto A = test::laplacian3D(14, Layout::contiguous, world());
  const auto b = test::rightHandSide(*A, 1);
  auto constants = Teuchos::rcp(new MultiVector(A->getRowMap(), 1));
  constants->putScalar(1.0);
  int iterations[2];
  for (int k = 0; k < 2; ++k) {
    BelosSolver solver(optionsWith(Method::cg, Kind::muelu), world());
    if (k == 1) solver.setNearNullSpace(constants);
    solver.setMatrix(A, true);
    MultiVector x(A->getDomainMap(), 1);
    solver.solve(*b, x);
    iterations[k] = solver.stats().iterations;
    EXPECT_LT(test::relativeDifference(x, *mumpsSolution(A, *b)), 1e-8);
  }
  // The constant is MueLu's default near-null space for one equation per node: same iterations.
  EXPECT_EQ(iterations[0], iterations[1]);
  EXPECT_LT(iterations[1], 40);
}

TEST(BelosSolver, NonConvergenceThrowsWithIterationsAndResidual) {
  auto o = optionsWith(Method::cg, Kind::none);
  o.maxIterations = 3;
  const auto A = test::laplacian2D(30, 30, Layout::scattered, world());
  BelosSolver solver(o, world());
  solver.setMatrix(A, true);
  MultiVector x(A->getDomainMap(), 1);
  try {
    solver.solve(*test::rightHandSide(*A, 1), x);
    ADD_FAILURE() << "no error";
  } catch (const LinearSolverError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("did not converge"), std::string::npos) << what;
    EXPECT_NE(what.find("after 3 iterations"), std::string::npos) << what;
    EXPECT_NE(what.find("relative residual"), std::string::npos) << what;
  }
}

TEST(BelosSolver, RefusesCgWithTheNonSymmetricIlut) {
  EXPECT_THROW(BelosSolver(optionsWith(Method::cg, Kind::ifpack2Ilut), world()), LinearSolverError);
}

TEST(BelosSolver, ZeroRightHandSideGivesZero) {
  const auto A = test::laplacian2D(8, 8, Layout::contiguous, world());
  BelosSolver solver(optionsWith(Method::gmres, Kind::ifpack2Sgs), world());
  solver.setMatrix(A, true);
  MultiVector b(A->getRangeMap(), 1), x(A->getDomainMap(), 1);
  x.putScalar(5.0);
  solver.solve(b, x);
  EXPECT_EQ(x.getVector(0)->normInf(), 0.0);
}

}  // namespace
}  // namespace contactlab
