// Springs to ground and point loads (NodalAssembler.hpp): a bar pulled at its end against a
// spring, whose end displacement is the series formula u = F / (k_total + E A / L) (nu = 0, and
// one element across, whose end nodes' equal shares are the consistent load of a uniform
// traction: the state is uniaxial and every element represents it exactly), and the tangent of a
// finite-strain body with springs against central differences of its residual. Run on 1 and 2
// ranks: a spring node on a partition boundary must count once.
#include "ProblemTestSupport.hpp"

#include "core/materials/NeoHookean.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab::test {
namespace {

constexpr double kE = 1000.0, kLength = 2.0, kHeight = 0.5, kSpring = 7.0, kForce = 3.0;

std::shared_ptr<Mesh> bar(int dim) {
  if (dim == 3) {
    BoxParams p;
    p.lengths = {kLength, kHeight, kHeight};
    p.divisions = {6, 1, 1};
    return std::make_shared<Mesh>(generateBox(p));
  }
  RectangleParams p;
  p.lengths = {kLength, kHeight};
  p.divisions = {8, 1};
  return std::make_shared<Mesh>(generateRectangle(p));
}

DirichletCondition roller(const std::string& group, int component) {
  DirichletCondition bc;
  bc.name = bc.group = group;
  bc.components = {component};
  return bc;
}

// Symmetry rollers on the three (two) lower faces, a spring in x on every node of the far end
// and a point load in x on it.
SolidModel pulledBar(int dim, PointLoad::Distribution distribution, double force) {
  SolidModel model;
  model.mesh = bar(dim);
  model.materials["body"] = std::make_shared<LinearElastic>(kE, 0.0);
  if (dim == 3)
    model.dirichlet = {roller("xmin", 0), roller("ymin", 1), roller("zmin", 2)};
  else
    model.dirichlet = {roller("left", 0), roller("bottom", 1)};
  const std::string end = dim == 3 ? "xmax" : "right";
  model.springs.push_back({"anchor", end, {0}, kSpring});
  PointLoad load;
  load.name = "pull";
  load.group = end;
  load.force = {force, 0, 0};
  load.distribution = distribution;
  model.pointLoads.push_back(load);
  return model;
}

class PulledBar : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(PulledBar, EndDisplacementIsTheSeriesFormula) {
  const auto [dim, perNode] = GetParam();
  auto comm = Tpetra::getDefaultComm();
  const auto distribution =
      perNode ? PointLoad::Distribution::PerNode : PointLoad::Distribution::Total;
  SolidModel model = pulledBar(dim, distribution, kForce);
  const std::string end = model.springs[0].group;
  const auto endNodes = model.mesh->boundaryNodes(end);
  const double nodes = static_cast<double>(endNodes.size());
  Problem problem(std::move(model), comm);
  auto solver = makeSolver("mumps", comm);
  auto u = solve(problem, *solver);

  const double area = dim == 3 ? kHeight * kHeight : kHeight;
  const double total = perNode ? kForce * nodes : kForce;
  const double expected = total / (kSpring * nodes + kE * area / kLength);
  for (auto node : endNodes)
    EXPECT_NEAR(problem.nodeDisplacement(*u, node)[0], expected, 1e-12 * expected);
  // The springs carry k_total u, the support the rest.
  EXPECT_NEAR(problem.springForces()[0].force[0], -kSpring * nodes * expected, 1e-10 * total);
  EXPECT_NEAR(problem.reactions()[0].force[0], -(total - kSpring * nodes * expected),
              1e-10 * total);
}

INSTANTIATE_TEST_SUITE_P(TwoAndThreeD, PulledBar,
                         ::testing::Combine(::testing::Values(2, 3), ::testing::Bool()));

// Central differences of R along a direction v against K v, at a random displacement of a
// neo-Hookean body with springs in every component on one side and a Dirichlet side.
class SpringTangent : public ::testing::TestWithParam<int> {};

TEST_P(SpringTangent, MatchesCentralDifferences) {
  const int dim = GetParam();
  auto comm = Tpetra::getDefaultComm();
  SolidModel model = pulledBar(dim, PointLoad::Distribution::Total, kForce);
  model.materials["body"] = std::make_shared<NeoHookean>(NeoHookean::fromYoungPoisson(kE, 0.3));
  model.springs[0].components = dim == 3 ? std::vector<int>{0, 1, 2} : std::vector<int>{0, 1};
  model.springs[0].stiffness = 50.0 * kE;  // the springs dominate the rows they act on
  Problem problem(std::move(model), comm);

  auto u = problem.createVector(), v = problem.createVector();
  u->randomize(-1e-2, 1e-2);
  v->randomize(-1.0, 1.0);
  problem.applyDirichlet(1.0, *u);
  problem.applyDirichlet(0.0, *v);  // zero on the constrained dofs (ramps start at 0)
  problem.assemble(*u, 1.0, nullptr, true);
  auto kv = problem.createVector();
  problem.tangent()->apply(*v, *kv);

  const double h = 1e-6;
  auto plus = problem.createVector(), minus = problem.createVector();
  auto rPlus = problem.createVector(), rMinus = problem.createVector();
  plus->update(1.0, *u, h, *v, 0.0);
  minus->update(1.0, *u, -h, *v, 0.0);
  problem.assemble(*plus, 1.0, rPlus.get(), false);
  problem.assemble(*minus, 1.0, rMinus.get(), false);
  auto difference = problem.createVector();
  difference->update(0.5 / h, *rPlus, -0.5 / h, *rMinus, 0.0);
  difference->update(-1.0, *kv, 1.0);
  // The springs (50 E per node) dominate K v on their rows: a tangent without them, or with
  // them counted twice on a partition boundary, is off by far more than this.
  EXPECT_LT(difference->norm2(), 1e-7 * kv->norm2());
}

INSTANTIATE_TEST_SUITE_P(TwoAndThreeD, SpringTangent, ::testing::Values(2, 3));

}  // namespace
}  // namespace contactlab::test
