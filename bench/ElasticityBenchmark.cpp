// Benchmark: 3D elasticity on a unit cube (bottom clamped) with MUMPS.
//
// Without --material: small-strain linear elasticity, the top pressed; prints one Markdown row:
// element, dofs, nonzeros, ranks, seconds for mesh, setup, assembly (one full residual +
// tangent, best of three), MUMPS analysis, factorization (symmetric, LDL^T) and solve, and the
// peak memory per rank.
//
// With --material NAME (linear-elastic, saint-venant-kirchhoff, neo-hookean, simo-miehe, built
// through the material registry; E = 200 000, nu = 0.3): the residual and tangent are assembled
// at a deformed state, the homogeneous stretch and shear u = (0.1 z, 0, 0.1 z) (the top's
// Dirichlet value is the stretch), where simo-miehe (yield stress 100, hardening 2 000) is
// plastic everywhere. The factorization is of that tangent, in the mode `Mode: automatic`
// resolves to (symmetric-indefinite when the material's tangent is symmetric, general
// otherwise). The row adds the material, the MUMPS mode and the plastic volume fraction.
//
//   bench_elasticity ELEMENT N [--material NAME] [--header] [--assembly-only]
//                                                            (N divisions per direction)
#include "core/materials/LinearElastic.hpp"
#include "core/materials/MaterialRegistry.hpp"
#include "core/mesh/MeshBroadcast.hpp"
#include "core/mesh/MeshGenerators.hpp"
#include "core/problem/Problem.hpp"
#include "linear/LinearSolverRegistry.hpp"

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_Core.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <sys/resource.h>
#include <vector>

using namespace contactlab;

namespace {

constexpr double kYoung = 2.0e5, kPoisson = 0.3;
// The deformed state of the --material runs: u_x = kShear z, u_z = kStretch z.
constexpr double kShear = 0.1, kStretch = 0.1;

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Options {
  std::string element;
  int divisions = 0;
  std::string material;  // empty: today's linear-elastic row
  bool header = false;
  bool assemblyOnly = false;
};

// Returns false (after a usage line on rank 0) on bad arguments.
bool parseOptions(int argc, char** argv, bool root, Options& o) {
  std::vector<std::string> args(argv + 1, argv + argc);
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--header")
      o.header = true;
    else if (args[i] == "--assembly-only")
      o.assemblyOnly = true;
    else if (args[i] == "--material" && i + 1 < args.size())
      o.material = args[++i];
    else if (o.element.empty())
      o.element = args[i];
    else if (o.divisions == 0)
      o.divisions = std::stoi(args[i]);
    else
      o.divisions = -1;
  }
  if (!o.element.empty() && o.divisions > 0) return true;
  if (root)
    std::cerr << "usage: bench_elasticity ELEMENT N [--material NAME] [--header] "
                 "[--assembly-only]\n";
  return false;
}

std::shared_ptr<Material> buildMaterial(const std::string& name) {
  registerMaterials();
  const auto& entry = materialRegistry().get(name);
  Teuchos::ParameterList p(name);
  p.set("E", kYoung);
  p.set("nu", kPoisson);
  if (name == "simo-miehe") {
    p.set("Yield Stress", 100.0);
    p.set("Isotropic Hardening Modulus", 2000.0);
  }
  p.validateParametersAndSetDefaults(*entry.validParameters());
  return entry.build(p);
}

// u = (kShear z, 0, kStretch z) on the owned nodes: zero on the clamped bottom, the top's
// Dirichlet value on the top.
void imposeDeformation(const Problem& problem, const Mesh& mesh, Vector& u) {
  auto data = u.getDataNonConst(0);
  const auto& nodes = problem.dofs().overlapNodes();
  for (std::size_t i = 0; i < problem.dofs().numOwnedNodes(); ++i) {
    const double z = mesh.coords[3 * nodes[i] + 2];
    data[3 * i + 0] = kShear * z;
    data[3 * i + 1] = 0.0;
    data[3 * i + 2] = kStretch * z;
  }
}

void printHeader(bool nonlinear) {
  if (nonlinear)
    std::cout << "| material | element | dofs | ranks | MUMPS mode | plastic volume | assembly s "
                 "| analysis s | factorization s | solve s | assembly / factorization | peak "
                 "MB/rank |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  else
    std::cout << "| element | dofs | nonzeros | ranks | mesh s | setup s | assembly s | analysis s "
                 "| factorization s | solve s | assembly / factorization | peak MB/rank |\n"
                 "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
}

double peakMegabytes(const Comm& comm) {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  double memory = usage.ru_maxrss / 1024.0, maxMemory = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 1, &memory, &maxMemory);
  return maxMemory;
}

}  // namespace

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  Options o;
  if (!parseOptions(argc, argv, root, o)) return 2;
  const bool nonlinear = !o.material.empty();
  if (o.header && root) printHeader(nonlinear);

  // 1. Mesh on rank 0, broadcast.
  double t0 = now();
  auto mesh = std::make_shared<Mesh>();
  if (root) {
    BoxParams p;
    p.divisions = {o.divisions, o.divisions, o.divisions};
    p.elementType = o.element;
    *mesh = generateBox(p);
  }
  broadcastMesh(*mesh, rawMpiComm(comm), 0);
  const double meshSeconds = now() - t0;

  // 2. Model and problem: partition, dof maps, graph.
  SolidModel model;
  model.mesh = mesh;
  model.materials["body"] =
      nonlinear ? buildMaterial(o.material) : std::make_shared<LinearElastic>(kYoung, kPoisson);
  model.dirichlet.push_back({"clamp", "zmin", {0, 1, 2}, 0.0, {}, {}});
  model.dirichlet.push_back({"press", "zmax", {2}, nonlinear ? kStretch : -0.01, {}, {}});
  t0 = now();
  Problem problem(model, comm);
  const double setupSeconds = now() - t0;

  // 3. Residual and tangent, best of three: the first touches fresh pages, the others show the
  // steady cost. Each starts from the same converged (initial) material state.
  auto u = problem.createVector();
  auto r = problem.createVector();
  if (nonlinear) imposeDeformation(problem, *mesh, *u);
  problem.applyDirichlet(1.0, *u);
  double assemblySeconds = 1e300;
  for (int repeat = 0; repeat < 3; ++repeat) {
    comm->barrier();
    t0 = now();
    problem.assemble(*u, 1.0, r.get(), true);
    comm->barrier();
    assemblySeconds = std::min(assemblySeconds, now() - t0);
  }
  if (!problem.assemblyFailure().code.empty()) {
    if (root) std::cerr << "assembly failed: " << problem.assemblyFailure().message << "\n";
    return 1;
  }

  if (o.assemblyOnly) {
    if (root)
      std::printf("%s %s %lld dofs, %d ranks: setup %.2f s, assembly %.3f s\n",
                  nonlinear ? o.material.c_str() : "", o.element.c_str(),
                  static_cast<long long>(problem.dofs().numGlobalDofs()), comm->getSize(),
                  setupSeconds, assemblySeconds);
    return 0;
  }

  // 4. One MUMPS analysis, factorization and solve of that tangent.
  const bool symmetric = model.materials["body"]->symmetricTangent();
  const std::string mode =
      !nonlinear ? "symmetric" : (symmetric ? "symmetric-indefinite" : "general");
  registerLinearSolvers();
  Teuchos::ParameterList params;
  params.set("Mode", mode);
  auto solver = linearSolverRegistry().get("mumps").build(params, comm);
  solver->setMatrix(problem.tangent(), true);
  auto du = problem.createVector();
  r->scale(-1.0);
  solver->solve(*r, *du);
  const auto& stats = solver->stats();
  const double ratio = 100.0 * assemblySeconds / stats.factorizationSeconds;
  const double memory = peakMegabytes(*comm);
  problem.commitState();
  const double plastic = problem.materialState().plasticVolumeFraction;
  const long long dofs = static_cast<long long>(problem.dofs().numGlobalDofs());
  if (!root) return 0;
  if (nonlinear)
    std::printf(
        "| %s | %s | %lld | %d | %s | %.0f %% | %.2f | %.2f | %.2f | %.2f | %.1f %% | %.0f |\n",
        o.material.c_str(), o.element.c_str(), dofs, comm->getSize(), mode.c_str(), 100.0 * plastic,
        assemblySeconds, stats.analysisSeconds, stats.factorizationSeconds, stats.solveSeconds,
        ratio, memory);
  else
    std::printf(
        "| %s | %lld | %zu | %d | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.1f %% | %.0f |\n",
        o.element.c_str(), dofs, static_cast<size_t>(problem.tangent()->getGlobalNumEntries()),
        comm->getSize(), meshSeconds, setupSeconds, assemblySeconds, stats.analysisSeconds,
        stats.factorizationSeconds, stats.solveSeconds, ratio, memory);
  return 0;
}
