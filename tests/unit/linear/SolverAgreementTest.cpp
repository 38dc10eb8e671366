// Every solver that applies to a matrix gives the same solution, built through the registry
// from scene-like parameter lists, on contiguous and scattered (non-contiguous) row maps.
#include "LinearTestProblems.hpp"

#include "linear/LinearSolverRegistry.hpp"

#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace contactlab {
namespace {

using test::Layout;

Teuchos::RCP<const Comm> world() {
  return Tpetra::getDefaultComm();
}

struct SolverSpec {
  std::string type;
  std::vector<std::pair<std::string, std::string>> strings;  // enumerated parameters
  std::string label() const {
    std::string s = type;
    for (const auto& [key, value] : strings)
      s += " " + key + "=" + value;
    return s;
  }
};

std::unique_ptr<LinearSolver> build(const SolverSpec& spec) {
  registerLinearSolvers();
  Teuchos::ParameterList params;
  for (const auto& [key, value] : spec.strings)
    params.set(key, value);
  if (spec.type == "belos") params.set("Tolerance", 1e-12);
  return linearSolverRegistry().get(spec.type).build(params, world());
}

struct Problem {
  std::string name;
  std::vector<SolverSpec> solvers;
};

std::vector<Problem> problems() {
  const SolverSpec general{"mumps", {{"Mode", "general"}}};
  const SolverSpec indefinite{"mumps", {{"Mode", "symmetric-indefinite"}}};
  const SolverSpec klu2{"klu2", {}};
  std::vector<SolverSpec> spd = {general, indefinite, klu2, {"mumps", {{"Mode", "symmetric"}}}};
  for (const char* prec : {"none", "ifpack2-sgs", "ifpack2-riluk", "muelu"})
    spd.push_back({"belos", {{"Method", "cg"}, {"Preconditioner", prec}}});
  // ILUT is not symmetric (CG refuses it): GMRES on the SPD matrix instead.
  spd.push_back({"belos", {{"Method", "gmres"}, {"Preconditioner", "ifpack2-ilut"}}});
  std::vector<SolverSpec> nonsymmetric = {general, klu2};
  for (const char* prec : {"none", "ifpack2-sgs", "ifpack2-riluk", "ifpack2-ilut", "muelu"})
    nonsymmetric.push_back({"belos", {{"Method", "gmres"}, {"Preconditioner", prec}}});
  return {
      {"laplacian2d", spd}, {"saddle", {general, indefinite, klu2}}, {"convdiff", nonsymmetric}};
}

Teuchos::RCP<Matrix> matrixOf(const std::string& name, Layout layout) {
  if (name == "laplacian2d") return test::laplacian2D(31, 26, layout, world());
  if (name == "saddle") return test::saddlePoint(20, 15, layout, world());
  return test::convectionDiffusion(28, 4.0, layout, world());
}

class SolverAgreement : public ::testing::TestWithParam<std::tuple<int, Layout>> {};

TEST_P(SolverAgreement, AllApplicableSolversGiveTheSameSolution) {
  const auto problem = problems()[std::get<0>(GetParam())];
  const auto A = matrixOf(problem.name, std::get<1>(GetParam()));
  const auto b = test::rightHandSide(*A, 2);
  Teuchos::RCP<MultiVector> reference;
  for (const auto& spec : problem.solvers) {
    SCOPED_TRACE(problem.name + ": " + spec.label());
    const auto solver = build(spec);
    solver->setMatrix(A, true);
    auto x = Teuchos::rcp(new MultiVector(A->getDomainMap(), 2));
    solver->solve(*b, *x);
    EXPECT_LT(test::relativeResidual(*A, *b, *x), 1e-10);
    if (reference.is_null())
      reference = x;
    else
      EXPECT_LT(test::relativeDifference(*x, *reference), 1e-8);
  }
}

INSTANTIATE_TEST_SUITE_P(Problems, SolverAgreement,
                         ::testing::Combine(::testing::Values(0, 1, 2),
                                            ::testing::Values(Layout::contiguous,
                                                              Layout::scattered)));

}  // namespace
}  // namespace contactlab
