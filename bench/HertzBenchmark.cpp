// Benchmark: 3D Hertz, an elastic half sphere (R = 1, E = 1, nu = 0.3) pressed on a rigid plane
// by lowering its flat face, for each contact formulation. Prints one Markdown row per
// formulation: dofs, contact points, Newton iterations, seconds per iteration split into the
// solid's assembly, pairing, contact terms and linear solve, the share of pairing + contact,
// and the pressure error against Hertz for the computed load (in % of p0, r <= 0.9 a).
//
//   bench_hertz ELEMENT SIZE_CONTACT [--header]
#include "algorithms/RunStatic.hpp"
#include "core/materials/LinearElastic.hpp"
#include "core/mesh/MeshBroadcast.hpp"
#include "core/mesh/MeshGenerators.hpp"
#include "formulations/ContactProblem.hpp"
#include "formulations/FormulationRegistry.hpp"
#include "linear/LinearSolverRegistry.hpp"

#include <Tpetra_Core.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

using namespace contactlab;

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  if (argc < 3) {
    if (root) std::cerr << "usage: bench_hertz ELEMENT SIZE_CONTACT [--header]\n";
    return 2;
  }
  const std::string type = argv[1];
  const double h = std::stod(argv[2]);
  if (argc > 3 && std::string(argv[3]) == "--header" && root)
    std::cout << "| formulation | element | dofs | contact points | ranks | Newton iterations | "
                 "assembly s/it | pairing s/it | contact s/it | linear solve s/it | "
                 "(pairing + contact) / total | a/h | pressure error / p0, max (rms) |\n"
                 "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  const double E = 1.0, nu = 0.3, R = 1.0;
  auto mesh = std::make_shared<Mesh>();
  if (root) {
    HalfSphereParams p;
    p.centre = {0, 0, R};
    p.radius = R;
    p.elementType = type;
    p.grading = {h, 0.15, 0.2, 0.6};
    *mesh = generateHalfSphere(p);
  }
  broadcastMesh(*mesh, rawMpiComm(comm), 0);
  SolidModel model;
  model.mesh = mesh;
  model.materials["body"] = std::make_shared<LinearElastic>(E, nu);
  DirichletCondition press;
  press.name = "press";
  press.group = "flat";
  press.components = {2};
  press.value = -0.012;
  model.dirichlet.push_back(press);
  DirichletCondition hold = press;
  hold.name = "hold";
  hold.components = {0, 1};
  hold.value = 0;
  model.dirichlet.push_back(hold);

  registerFormulations();
  registerLinearSolvers();
  for (const std::string name : {"penalty", "lagrange", "augmented-lagrangian"}) {
    Teuchos::ParameterList params = *formulationRegistry().get(name).validParameters();
    if (name == "penalty") params.set("Normal Penalty", 100.0 * E / h);
    if (name == "lagrange") params.set("Normal Complementarity Constant", E / h);
    if (name == "augmented-lagrangian") params.set("Normal Augmentation", E / h);
    ContactZone zone;
    zone.name = "floor";
    zone.slave = "curved";
    RigidObstacleSpec plane;
    plane.direction = {0, 0, 1};
    zone.obstacle = plane;
    zone.searchDistance = 0.05;
    zone.law = formulationRegistry().get(name).build(params);
    Problem solid(model, comm);
    ContactProblem contact(solid, {zone});
    auto solver = linearSolverRegistry().get("mumps").build(Teuchos::ParameterList(), comm);
    StaticSolverOptions options;
    options.steps = 1;
    options.maxIterations = 30;
    auto x = contact.createVector();
    const RunReport report = runStatic(contact, &contact, *solver, options, *x);
    const ContactResultants r = contact.resultants();
    const double Estar = E / (1 - nu * nu);
    const double P = r.normalForceMagnitude;
    const double a = std::cbrt(3 * P * R / (4 * Estar));
    const double p0 = 3 * P / (2 * M_PI * a * a);
    // Pressure error over the points with r <= 0.9 a (the edge, where p_H has an infinite
    // slope, is left out): max and root mean square, in units of p0.
    double error = 0, squares = 0;
    int inside = 0;
    for (const auto& pt : contact.results()) {
      const double rr = std::hypot(pt.x[0], pt.x[1]);
      if (rr > 0.9 * a) continue;
      const double e = std::abs(pt.pressure - p0 * std::sqrt(1 - rr * rr / (a * a))) / p0;
      error = std::max(error, e);
      squares += e * e;
      ++inside;
    }
    const double rms = std::sqrt(squares / std::max(inside, 1));
    const int it = std::max(report.iterations, 1);
    const ContactPhaseSeconds seconds = contact.phaseSeconds();
    const double total =
        seconds.solid + seconds.pairing + seconds.contact + report.seconds.linearSolve;
    if (root) {
      std::printf(
          "| %s | %s | %lld | %zu | %d | %d%s | %.3f | %.4f | %.4f | %.3f | %.1f %% | %.1f | "
          "%.1f %% (%.1f %%) |\n",
          name.c_str(), type.c_str(),
          static_cast<long long>(solid.dofs().numGlobalDofs() + contact.numMultipliers()),
          contact.numPoints(), comm->getSize(), report.iterations,
          report.converged ? "" : (" (" + report.failure + ")").c_str(), seconds.solid / it,
          seconds.pairing / it, seconds.contact / it, report.seconds.linearSolve / it,
          100 * (seconds.pairing + seconds.contact) / total, a / h, 100 * error, 100 * rms);
      std::fflush(stdout);
    }
  }
  return 0;
}
