#pragma once
// Shared by the problem tests: structured meshes of every element type, a linear-elastic model
// with the exact solution imposed on the whole boundary, and a MUMPS solve.
#include "algorithms/RunStatic.hpp"
#include "base/InputError.hpp"
#include "core/materials/LinearElastic.hpp"
#include "core/mesh/MeshGenerators.hpp"
#include "core/problem/Problem.hpp"
#include "linear/LinearSolverRegistry.hpp"

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>
#include <memory>
#include <random>
#include <string>

namespace contactlab::test {

inline bool is3D(const std::string& type) {
  return info(elementTypeFromName(type)).dim == 3;
}

inline std::shared_ptr<Mesh> unitMesh(const std::string& type, int n) {
  if (is3D(type)) {
    BoxParams p;
    p.divisions = {n, n, n};
    p.elementType = type;
    return std::make_shared<Mesh>(generateBox(p));
  }
  RectangleParams p;
  p.divisions = {n, n};
  p.elementType = type;
  return std::make_shared<Mesh>(generateRectangle(p));
}

// Moves every node by up to `fraction` of the cell size in each direction (same on all ranks).
inline void distort(Mesh& mesh, int n, double fraction) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> d(-fraction / n, fraction / n);
  for (std::size_t i = 0; i < mesh.numNodes(); ++i)
    for (int c = 0; c < mesh.dim; ++c)
      mesh.coords[3 * i + c] += d(rng);
}

inline std::vector<std::string> boundaryGroups(int dim) {
  if (dim == 3) return {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  return {"left", "right", "bottom", "top"};
}

using Field = std::function<void(const double* x, double* u)>;

// Linear elasticity with u = exact on the whole boundary and body force b.
inline SolidModel elasticModel(std::shared_ptr<Mesh> mesh, double E, double nu, const Field& exact,
                               const Field& body) {
  SolidModel model;
  model.mesh = mesh;
  model.materials["body"] = std::make_shared<LinearElastic>(E, nu);
  for (const auto& g : boundaryGroups(mesh->dim)) {
    DirichletCondition bc;
    bc.name = g;
    bc.group = g;
    for (int c = 0; c < mesh->dim; ++c)
      bc.components.push_back(c);
    bc.field = [exact](const double* x, int c, double) {
      double u[3] = {0, 0, 0};
      exact(x, u);
      return u[c];
    };
    model.dirichlet.push_back(bc);
  }
  if (body) {
    BodyForce f;
    f.name = "manufactured";
    f.field = [body](const double* x, double, double* b) { body(x, b); };
    model.bodyForces.push_back(f);
  }
  return model;
}

inline std::unique_ptr<LinearSolver> makeSolver(const std::string& name,
                                                const Teuchos::RCP<const Comm>& comm,
                                                Teuchos::ParameterList params = {}) {
  registerLinearSolvers();
  return linearSolverRegistry().get(name).build(params, comm);
}

// One load step, Newton (one iteration for a linear problem). Returns the solution.
inline Teuchos::RCP<Vector> solve(Problem& problem, LinearSolver& solver) {
  auto u = problem.createVector();
  StaticSolverOptions options;
  options.maxIterations = 3;
  const RunReport report = runStatic(problem, nullptr, solver, options, *u);
  if (!report.converged) throw std::runtime_error("solve failed: " + report.message);
  return u;
}

// A static run from zero with MUMPS: the displacement and the run's report.
struct StaticRun {
  Teuchos::RCP<Vector> u;
  RunReport report;
};
inline StaticRun runWithMumps(Problem& problem, int maxIterations) {
  const auto solver = makeSolver("mumps", problem.dofs().comm());
  StaticSolverOptions options;
  options.maxIterations = maxIterations;
  StaticRun run{problem.createVector(), {}};
  run.report = runStatic(problem, nullptr, *solver, options, *run.u);
  return run;
}

// w . K v = v . K w for random w, v, K the tangent at a random state near zero that keeps the
// Dirichlet values and the eliminated dofs' constraints (MUMPS' symmetric modes stay usable).
inline void expectSymmetricTangent(Problem& problem, const std::string& what) {
  auto u = problem.createVector(), v = problem.createVector(), w = problem.createVector();
  u->randomize(-1e-2, 1e-2);
  v->randomize(-1.0, 1.0);
  w->randomize(-1.0, 1.0);
  problem.applyDirichlet(1.0, *u);
  problem.completeIncrement(*u);
  problem.assemble(*u, 1.0, nullptr, true);
  auto kv = problem.createVector(), kw = problem.createVector();
  problem.tangent()->apply(*v, *kv);
  problem.tangent()->apply(*w, *kw);
  EXPECT_NEAR(w->dot(*kv), v->dot(*kw), 1e-12 * kv->norm2() * w->norm2()) << what;
}

// Building the problem of `model` is refused with an InputError whose sentence holds `words`.
inline void expectRefused(SolidModel model, const std::string& words) {
  try {
    Problem problem(std::move(model), Tpetra::getDefaultComm());
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    return;
  }
  ADD_FAILURE() << "accepted; expected: " << words;
}

inline Teuchos::RCP<const Comm> selfComm() {
  return Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
}

}  // namespace contactlab::test
