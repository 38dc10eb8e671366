// Follower pressure on finite-strain bodies (SurfaceLoadAssembler.hpp): closed-form
// homogeneous states of a neo-Hookean cube (square in plane strain, solid cylinder when
// axisymmetric) under a pressure on three faces, with symmetry conditions on the other three, for
// the follower and the dead pressure; Newton's quadratic convergence. The refusal on small-strain
// blocks is in ModelCheckTest.cpp.
#include "ProblemTestSupport.hpp"

#include "core/materials/NeoHookean.hpp"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <ostream>

namespace contactlab::test {
namespace {

constexpr double kE = 1000.0, kNu = 0.3, kPressure = 150.0;
// Relative residuals below this are round-off (about 1e-12 here), not Newton's.
constexpr double kRoundOff = 1e-11;
// Newton is quadratic when e_(k+1) <= kQuadraticBound e_k^2 in the asymptotic range.
constexpr double kQuadraticBound = 10.0;

// The stretch lambda of the homogeneous state F = diag(lambda, lambda, lambda) (3D) or
// diag(lambda, lambda, 1) (plane strain) of NeoHookean.hpp's law,
//   P_11 = mu J^(-2/3) (lambda - I1 / (3 lambda)) + J U'(J) / lambda,  sigma_11 = P_11 lambda / J,
// under a pressure p on the faces: the follower pressure acts on the current faces, so
// sigma_11 = -p (in 3D sigma = -p I, and then U'(J) = -p: J = 1 - p / K for the quadratic
// energy, J = -p/K + sqrt(1 + (p/K)^2) for Simo-Miehe's); the dead pressure acts on the
// reference faces, so P_11 = -p. Solved by bisection from lambda = 1 down to the first root.
double exactStretch(int dim, NeoHookean::Volumetric volumetric, bool follower, double p) {
  const double mu = kE / (2 * (1 + kNu)), K = kE / (3 * (1 - 2 * kNu));
  auto stress = [&](double lambda) {
    const double J = std::pow(lambda, dim), I1 = dim * lambda * lambda + (3 - dim);
    const double dU =
        volumetric == NeoHookean::Volumetric::Quadratic ? K * (J - 1) : 0.5 * K * (J - 1 / J);
    const double P = mu * std::pow(J, -2.0 / 3) * (lambda - I1 / (3 * lambda)) + J * dU / lambda;
    return (follower ? P * lambda / J : P) + p;
  };
  double hi = 1.0, lo = 1.0;
  while (stress(lo) > 0)
    hi = lo, lo -= 0.01;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (stress(mid) > 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

SolidModel pressurizedCube(const std::string& type, NeoHookean::Volumetric volumetric,
                           SurfaceLoad::Follower follower) {
  SolidModel model;
  model.mesh = unitMesh(type, 2);
  const int dim = model.mesh->dim;
  model.materials["body"] =
      std::make_shared<NeoHookean>(NeoHookean::fromYoungPoisson(kE, kNu, 0.0, volumetric));
  const auto groups = boundaryGroups(dim);  // xmin xmax ymin ymax (zmin zmax), or left right..
  const std::vector<std::string> symmetric = dim == 3
                                                 ? std::vector<std::string>{"xmin", "ymin", "zmin"}
                                                 : std::vector<std::string>{"left", "bottom"};
  const std::vector<std::string> loaded = dim == 3
                                              ? std::vector<std::string>{"xmax", "ymax", "zmax"}
                                              : std::vector<std::string>{"right", "top"};
  for (int c = 0; c < dim; ++c) {
    DirichletCondition bc;
    bc.name = bc.group = symmetric[c];
    bc.components = {c};
    model.dirichlet.push_back(bc);
    SurfaceLoad load;
    load.name = load.group = loaded[c];
    load.pressure = kPressure;
    load.follower = follower;
    model.surfaceLoads.push_back(load);
  }
  return model;
}

struct Solution {
  Teuchos::RCP<Vector> u;
  RunReport report;
  std::vector<std::vector<double>> residuals;  // per load step, Newton's residual norms
};

Solution solveSteps(Problem& problem, int steps, double relativeTolerance = 1e-11) {
  auto solver = makeSolver("mumps", problem.dofs().comm());
  Solution s;
  s.u = problem.createVector();
  StaticSolverOptions options;
  options.steps = steps;
  options.maxIterations = 12;
  options.relativeTolerance = relativeTolerance;
  options.absoluteTolerance = 1e-14;
  s.report = runStatic(problem, nullptr, *solver, options, *s.u, {},
                       [&](const StaticSolver::IterateProgress& p) {
                         if (static_cast<int>(s.residuals.size()) < p.step)
                           s.residuals.emplace_back();
                         if (p.iteration == 0) s.residuals[p.step - 1].clear();
                         s.residuals[p.step - 1].push_back(p.residual);
                       });
  return s;
}

// Newton's constants e_(k+1) / e_k^2 on the relative residuals e_k = |R_k| / |R_0| of one
// load step, where e_k <= 0.1 (the asymptotic range) and e_(k+1) is above round-off.
std::vector<double> quadraticConstants(const std::vector<double>& r) {
  std::vector<double> constants;
  for (std::size_t k = 1; k + 1 < r.size(); ++k) {
    const double ek = r[k] / r[0], next = r[k + 1] / r[0];
    if (ek <= 0.1 && next >= kRoundOff) constants.push_back(next / (ek * ek));
  }
  return constants;
}

std::string relativeHistory(const std::vector<double>& r) {
  std::string history;
  for (double v : r) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, " %.2e", v / r[0]);
    history += buffer;
  }
  return history;
}

// Largest |u_h - (lambda - 1) X| over the nodes.
double stretchError(const Problem& problem, const Vector& u, double lambda) {
  const Mesh& mesh = *problem.model().mesh;
  double maxError = 0;
  for (std::size_t node = 0; node < mesh.numNodes(); ++node) {
    const auto uh = problem.nodeDisplacement(u, static_cast<std::int64_t>(node));
    for (int c = 0; c < mesh.dim; ++c)
      maxError = std::max(maxError, std::fabs(uh[c] - (lambda - 1) * mesh.coords[3 * node + c]));
  }
  return maxError;
}

struct CubeCase {
  std::string type;
  NeoHookean::Volumetric volumetric;
};

void PrintTo(const CubeCase& c, std::ostream* os) {
  *os << c.type
      << (c.volumetric == NeoHookean::Volumetric::Quadratic ? " quadratic" : " simo-miehe");
}

class PressurizedCube : public ::testing::TestWithParam<CubeCase> {};

TEST_P(PressurizedCube, FollowerAndDeadPressureGiveTheirClosedForms) {
  const auto& c = GetParam();
  const bool quadratic = c.volumetric == NeoHookean::Volumetric::Quadratic;
  const int dim = is3D(c.type) ? 3 : 2;
  const int rank = Tpetra::getDefaultComm()->getRank();
  const double follower = exactStretch(dim, c.volumetric, true, kPressure);
  const double dead = exactStretch(dim, c.volumetric, false, kPressure);
  ASSERT_GT(std::fabs(follower - dead), 5e-3);  // the check tells them apart
  if (dim == 3 && quadratic) {                  // U'(J) = K (J - 1) = -p
    EXPECT_NEAR(std::pow(follower, 3), 1 - kPressure * 3 * (1 - 2 * kNu) / kE, 1e-12);
  }

  // Automatic on a finite-strain block is the follower pressure.
  Problem automatic(pressurizedCube(c.type, c.volumetric, SurfaceLoad::Follower::Automatic),
                    Tpetra::getDefaultComm());
  EXPECT_EQ(automatic.followerLoads().size(), static_cast<std::size_t>(dim));
  const auto a = solveSteps(automatic, 3);
  ASSERT_TRUE(a.report.converged) << a.report.message;
  const double followerError = stretchError(automatic, *a.u, follower);
  EXPECT_LT(followerError, 1e-10) << c.type;

  Problem reference(pressurizedCube(c.type, c.volumetric, SurfaceLoad::Follower::No),
                    Tpetra::getDefaultComm());
  EXPECT_TRUE(reference.followerLoads().empty());
  const auto d = solveSteps(reference, 3);
  ASSERT_TRUE(d.report.converged) << d.report.message;
  const double deadError = stretchError(reference, *d.u, dead);
  EXPECT_LT(deadError, 1e-10) << c.type;
  if (rank == 0)
    std::printf("%-5s %-10s lambda follower %.12f (error %.1e), dead %.12f (error %.1e)\n",
                c.type.c_str(), quadratic ? "quadratic" : "simo-miehe", follower, followerError,
                dead, deadError);

  // Newton with the load stiffness: quadratic, e_(k+1) <= C e_k^2 with a C of order 1 (about
  // 0.02 to 0.08 here). Without the load stiffness it is linear with a rate near p / K, and
  // e_(k+1) / e_k^2 grows past kQuadraticBound within three iterations.
  const auto& r = a.residuals.back();
  const auto constants = quadraticConstants(r);
  EXPECT_FALSE(constants.empty()) << c.type << ":" << relativeHistory(r);
  for (double C : constants)
    EXPECT_LT(C, kQuadraticBound) << c.type << ":" << relativeHistory(r);
  if (rank == 0)
    std::printf("%-5s %-10s last step, |R_k| / |R_0|:%s\n", c.type.c_str(),
                quadratic ? "quadratic" : "simo-miehe", relativeHistory(r).c_str());
}

// Facets: line2 (quad4, tri3), line3 (quad8, quad9, tri6), quad4 (hex8), quad8 (hex20), quad9
// (hex27), tri3 (tet4), tri6 (tet10).
INSTANTIATE_TEST_SUITE_P(EveryFacet, PressurizedCube,
                         ::testing::Values(CubeCase{"quad4", NeoHookean::Volumetric::Quadratic},
                                           CubeCase{"tri3", NeoHookean::Volumetric::SimoMiehe},
                                           CubeCase{"quad8", NeoHookean::Volumetric::SimoMiehe},
                                           CubeCase{"quad9", NeoHookean::Volumetric::Quadratic},
                                           CubeCase{"tri6", NeoHookean::Volumetric::Quadratic},
                                           CubeCase{"hex8", NeoHookean::Volumetric::Quadratic},
                                           CubeCase{"hex8", NeoHookean::Volumetric::SimoMiehe},
                                           CubeCase{"hex20", NeoHookean::Volumetric::Quadratic},
                                           CubeCase{"hex27", NeoHookean::Volumetric::SimoMiehe},
                                           CubeCase{"tet4", NeoHookean::Volumetric::SimoMiehe},
                                           CubeCase{"tet10", NeoHookean::Volumetric::Quadratic}),
                         [](const ::testing::TestParamInfo<CubeCase>& info) {
                           return info.param.type +
                                  (info.param.volumetric == NeoHookean::Volumetric::Quadratic
                                       ? "_quadratic"
                                       : "_simo_miehe");
                         });

// The unit square as the axisymmetric solid cylinder 0 <= r <= 1, 0 <= z <= 1: held radially on
// the axis and axially at the bottom, pressed on its side and top. The homogeneous state is
// F = diag(lambda, lambda, lambda) (the hoop stretch (R + u_r) / R = lambda too), so the 3D
// closed forms hold: the follower pressure on the current ring (2 pi r at the current radius)
// gives sigma = -p I, the dead one P = -p I.
TEST(FollowerPressure, AxisymmetricCylinderGivesTheHydrostaticClosedForms) {
  for (const std::string type : {"quad4", "quad8", "tri6"})
    for (auto volumetric : {NeoHookean::Volumetric::Quadratic, NeoHookean::Volumetric::SimoMiehe})
      for (auto follower : {SurfaceLoad::Follower::Automatic, SurfaceLoad::Follower::No}) {
        SolidModel model = pressurizedCube(type, volumetric, follower);
        model.axisymmetric = true;
        Problem problem(model, Tpetra::getDefaultComm());
        const bool follows = follower == SurfaceLoad::Follower::Automatic;
        EXPECT_EQ(problem.followerLoads().size(), follows ? 2u : 0u);
        const auto s = solveSteps(problem, 3);
        ASSERT_TRUE(s.report.converged) << type << ": " << s.report.message;
        const double lambda = exactStretch(3, volumetric, follows, kPressure);
        EXPECT_LT(stretchError(problem, *s.u, lambda), 1e-10) << type << " follower " << follows;
        if (!follows) continue;
        const auto constants = quadraticConstants(s.residuals.back());
        EXPECT_FALSE(constants.empty()) << type << ":" << relativeHistory(s.residuals.back());
        for (double C : constants)
          EXPECT_LT(C, kQuadraticBound) << type << ":" << relativeHistory(s.residuals.back());
      }
}

TEST(FollowerPressure, BentCantileverConvergesQuadratically) {
  // A plane-strain cantilever 4 x 1 (quad8), clamped on the left, under a follower pressure on
  // its top that bends it by about its height: the pressure turns with the facets, and Newton
  // stays quadratic only with the load stiffness in the tangent.
  RectangleParams g;
  g.lengths = {4.0, 1.0};
  g.divisions = {8, 2};
  g.elementType = "quad8";
  SolidModel model;
  model.mesh = std::make_shared<Mesh>(generateRectangle(g));
  model.materials["body"] = std::make_shared<NeoHookean>(NeoHookean::fromYoungPoisson(kE, kNu));
  DirichletCondition clamp;
  clamp.name = clamp.group = "left";
  clamp.components = {0, 1};
  model.dirichlet.push_back(clamp);
  SurfaceLoad load;
  load.name = load.group = "top";
  load.pressure = 3.0;
  model.surfaceLoads.push_back(load);
  Problem problem(model, Tpetra::getDefaultComm());
  const auto s = solveSteps(problem, 4);
  ASSERT_TRUE(s.report.converged) << s.report.message;
  std::int64_t tip = 0;
  auto distance = [&](std::size_t n) {
    return std::hypot(model.mesh->coords[3 * n] - 4.0, model.mesh->coords[3 * n + 1] - 1.0);
  };
  for (std::size_t n = 0; n < model.mesh->numNodes(); ++n)
    if (distance(n) < distance(tip)) tip = static_cast<std::int64_t>(n);
  const auto ut = problem.nodeDisplacement(*s.u, tip);
  EXPECT_LT(ut[1], -0.8);  // a finite deflection
  if (Tpetra::getDefaultComm()->getRank() == 0)
    std::printf("cantilever tip displacement (%.4f, %.4f)\n", ut[0], ut[1]);
  for (std::size_t step = 0; step < s.residuals.size(); ++step) {
    const auto& r = s.residuals[step];
    if (Tpetra::getDefaultComm()->getRank() == 0)
      std::printf("cantilever step %zu, |R_k| / |R_0|:%s\n", step + 1, relativeHistory(r).c_str());
    EXPECT_LE(r.size(), 7u) << relativeHistory(r);
    const auto constants = quadraticConstants(r);
    EXPECT_FALSE(constants.empty()) << "step " << step + 1 << ":" << relativeHistory(r);
    for (double C : constants)
      EXPECT_LT(C, kQuadraticBound) << "step " << step + 1 << ":" << relativeHistory(r);
  }
}

}  // namespace
}  // namespace contactlab::test
