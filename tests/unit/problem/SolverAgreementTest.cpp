// Every linear solver gives the same displacements on an elasticity system assembled by the
// problem (the linear module's own tests cover Laplacians, saddle points and non-symmetric
// matrices).
#include "ProblemTestSupport.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab::test {
namespace {

TEST(SolverAgreement, ElasticityOnEverySolver) {
  auto mesh = unitMesh("hex8", 4);
  Field exact = [](const double* x, double* u) { u[0] = u[1] = 0, u[2] = -0.01 * x[2]; };
  auto model = elasticModel(mesh, 1000.0, 0.3, exact, {});
  model.dirichlet.resize(1);  // clamp xmin only...
  BodyForce gravity;
  gravity.name = "gravity";
  gravity.value = {0.0, 0.0, -1.0};
  model.bodyForces.push_back(gravity);  // ...and hang the block under its weight
  auto comm = Tpetra::getDefaultComm();
  Problem problem(model, comm);

  Teuchos::ParameterList symmetric, cgSgs, cgMueLu, gmres;
  symmetric.set("Mode", "symmetric");
  cgSgs.set("Method", "cg");
  cgSgs.set("Preconditioner", "ifpack2-sgs");
  cgSgs.set("Tolerance", 1e-12);
  cgMueLu = cgSgs;
  cgMueLu.set("Preconditioner", "muelu");
  gmres.set("Method", "gmres");
  gmres.set("Preconditioner", "ifpack2-ilut");
  gmres.set("Tolerance", 1e-12);
  std::vector<std::pair<std::string, Teuchos::ParameterList>> solvers = {
      {"mumps", {}},    {"mumps", symmetric}, {"klu2", {}},
      {"belos", cgSgs}, {"belos", cgMueLu},   {"belos", gmres}};

  auto reference = solve(problem, *makeSolver("mumps", comm));
  const double scale = reference->normInf();
  ASSERT_GT(scale, 0.0);
  for (auto& [name, params] : solvers) {
    auto solver = makeSolver(name, comm, params);
    auto u = solve(problem, *solver);
    u->update(-1.0, *reference, 1.0);
    EXPECT_LT(u->normInf(), 1e-8 * scale) << name << " " << params;
  }
}

}  // namespace
}  // namespace contactlab::test
