#pragma once
// Shared by the problem tests: structured meshes of every element type, a linear-elastic model
// with the exact solution imposed on the whole boundary, and a MUMPS solve.
#include "algorithms/RunStatic.hpp"
#include "core/materials/LinearElastic.hpp"
#include "core/mesh/MeshGenerators.hpp"
#include "core/problem/Problem.hpp"
#include "linear/LinearSolverRegistry.hpp"

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_Core.hpp>

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

inline Teuchos::RCP<const Comm> selfComm() {
  return Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
}

}  // namespace contactlab::test
