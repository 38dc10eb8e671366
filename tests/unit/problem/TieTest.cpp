// Ties between the dofs of nodes (TieEquations.hpp, LinearConstraints.hpp). Two blocks meshed
// separately with coincident nodes on their interface, tied node to node, are one body: their
// displacement must be the single mesh's to solver precision, in small and finite strain, on
// linear and quadratic elements, 2D and 3D, with the same Newton iterations and a symmetric
// tangent. Run on 1 and 2 ranks: the interface's node pairs straddle the partition.
#include "ProblemTestSupport.hpp"

#include "base/InputError.hpp"
#include "core/materials/NeoHookean.hpp"
#include "core/problem/LinearConstraints.hpp"
#include "core/problem/TieEquations.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <set>

namespace contactlab::test {
namespace {

std::shared_ptr<const Material> material(bool finiteStrain) {
  if (finiteStrain) return std::make_shared<NeoHookean>(NeoHookean::fromYoungPoisson(1e3, 0.3));
  return std::make_shared<LinearElastic>(1e3, 0.3);
}

// A column of height 2, clamped at its foot and sheared at its head: one mesh, or two blocks of
// height 1 whose interfaces (coincident nodes) are tied.
SolidModel shearedColumn(const std::string& element, bool tied, bool finiteStrain) {
  const bool is3d = is3D(element);
  SolidModel model;
  std::string foot = "bottom", head = "top";
  if (tied && is3d) {
    StackedBlocks3DParams p;
    p.lowerDivisions = p.upperDivisions = {2, 2, 3};
    p.elementType = element;
    model.mesh = std::make_shared<Mesh>(generateStackedBlocks3D(p));
  } else if (tied) {
    StackedBlocks2DParams p;
    p.lowerDivisions = p.upperDivisions = {3, 3};
    p.elementType = element;
    model.mesh = std::make_shared<Mesh>(generateStackedBlocks2D(p));
  } else if (is3d) {
    BoxParams p;
    p.lengths = {1, 1, 2};
    p.divisions = {2, 2, 6};
    p.elementType = element;
    model.mesh = std::make_shared<Mesh>(generateBox(p));
    foot = "zmin", head = "zmax";
  } else {
    RectangleParams p;
    p.lengths = {1, 2};
    p.divisions = {3, 6};
    p.elementType = element;
    model.mesh = std::make_shared<Mesh>(generateRectangle(p));
  }
  if (tied) {
    for (const char* block : {"lower", "upper"})
      model.materials[block] = material(finiteStrain);
    foot = "lower-bottom", head = "upper-top";
    TieCondition tie;
    tie.name = "interface";
    tie.groups = {"lower-top", "upper-bottom"};
    tie.coefficients = {1.0, -1.0};
    for (int c = 0; c < model.mesh->dim; ++c)
      tie.components.push_back(c);
    model.ties.push_back(tie);
  } else {
    model.materials["body"] = material(finiteStrain);
  }
  DirichletCondition clamp;
  clamp.name = clamp.group = foot;
  for (int c = 0; c < model.mesh->dim; ++c)
    clamp.components.push_back(c);
  model.dirichlet.push_back(clamp);
  PointLoad shear;
  shear.name = "shear";
  shear.group = head;
  shear.force = {finiteStrain ? 20.0 : 1.0, 0, finiteStrain ? -10.0 : 0.0};
  if (!is3d) shear.force[1] = shear.force[2], shear.force[2] = 0;
  model.pointLoads.push_back(shear);
  return model;
}

// Every node of the tied mesh (both of an interface pair) against the single mesh's node at its
// place (expected to exist): the largest displacement component and the largest difference.
std::pair<double, double> compareAtEveryNode(const Problem& single, const Vector& us,
                                             const Problem& tied, const Vector& ut) {
  const Mesh& a = *single.model().mesh;
  const Mesh& b = *tied.model().mesh;
  double largest = 0, error = 0;
  std::size_t matched = 0;
  for (std::size_t n = 0; n < b.numNodes(); ++n)
    for (std::size_t m = 0; m < a.numNodes(); ++m) {
      double d = 0;
      for (int i = 0; i < 3; ++i)
        d += std::abs(a.coords[3 * m + i] - b.coords[3 * n + i]);
      if (d > 1e-10) continue;
      ++matched;
      const auto x = single.nodeDisplacement(us, static_cast<std::int64_t>(m));
      const auto y = tied.nodeDisplacement(ut, static_cast<std::int64_t>(n));
      for (int i = 0; i < 3; ++i) {
        largest = std::max(largest, std::abs(x[i]));
        error = std::max(error, std::abs(x[i] - y[i]));
      }
    }
  EXPECT_EQ(matched, b.numNodes());
  return {largest, error};
}

class TiedColumn : public ::testing::TestWithParam<std::tuple<std::string, bool>> {};

TEST_P(TiedColumn, IsTheSingleMesh) {
  const auto [element, finiteStrain] = GetParam();
  auto comm = Tpetra::getDefaultComm();
  Problem single(shearedColumn(element, false, finiteStrain), comm);
  Problem tied(shearedColumn(element, true, finiteStrain), comm);
  EXPECT_FALSE(tied.constraints().empty());
  // On 2 ranks the partition cuts the column: some rank assembles elements of one block only,
  // so the pairs' rows meet on their common owner.
  if (comm->getSize() > 1) {
    std::set<int> blocks;
    for (const ElementRef& e : tied.dofs().localElements())
      blocks.insert(e.block);
    int split = blocks.size() == 1 ? 1 : 0, anywhere = 0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, split, Teuchos::outArg(anywhere));
    EXPECT_EQ(anywhere, 1);
  }
  const StaticRun rs = runWithMumps(single, 15), rt = runWithMumps(tied, 15);
  ASSERT_TRUE(rs.report.converged && rt.report.converged) << rs.report.message << rt.report.message;
  EXPECT_EQ(rt.report.iterations, rs.report.iterations);
  const Vector &us = *rs.u, &ut = *rt.u;
  const auto [largest, error] = compareAtEveryNode(single, us, tied, ut);
  EXPECT_GT(largest, finiteStrain ? 0.05 : 1e-3);  // a real deformation
  EXPECT_LT(error, 1e-9 * largest);
  // The clamp's reaction is the single mesh's, and the tie's force on the lower block's top
  // balances it (nothing else loads the lower block).
  // (Within Newton's tolerance: the forces are those of the last residual.)
  ASSERT_EQ(tied.reactions().size(), 2u);
  const double tolerance = finiteStrain ? 1e-7 : 1e-9;  // loads 20 and 1
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(tied.reactions()[0].force[i], single.reactions()[0].force[i], tolerance);
    EXPECT_NEAR(tied.reactions()[1].force[i], -tied.reactions()[0].force[i], tolerance);
  }
}

INSTANTIATE_TEST_SUITE_P(Elements, TiedColumn,
                         ::testing::Combine(::testing::Values("quad4", "quad8", "tri6", "hex8",
                                                              "tet10"),
                                            ::testing::Bool()));

// T^T K T keeps the tangent symmetric with ties (MUMPS' symmetric modes stay usable).
TEST(Ties, KeepTheTangentSymmetric) {
  auto comm = Tpetra::getDefaultComm();
  for (const char* element : {"quad8", "hex8"}) {
    Problem problem(shearedColumn(element, true, true), comm);
    expectSymmetricTangent(problem, element);
  }
}

// A general equation: each node of the column's right side moves sideways twice as far as the
// left side's node at its height, u_r - 2 u_l = 0, and the solution keeps it exactly.
TEST(Ties, KeepAGeneralEquation) {
  auto comm = Tpetra::getDefaultComm();
  SolidModel model = shearedColumn("quad4", false, false);
  TieCondition lever;
  lever.name = "lever";
  lever.groups = {"right", "left"};  // 7 nodes each, a translation apart
  lever.coefficients = {1.0, -2.0};
  lever.components = {0};
  model.ties.push_back(lever);
  Problem problem(std::move(model), comm);
  const StaticRun run = runWithMumps(problem, 3);
  ASSERT_TRUE(run.report.converged) << run.report.message;
  const Vector& u = *run.u;
  const Mesh& m = *problem.model().mesh;
  const auto right = m.boundaryNodes("right"), left = m.boundaryNodes("left");
  double largest = 0;
  ASSERT_EQ(right.size(), left.size());
  for (std::int64_t r : right)
    for (std::int64_t l : left) {
      if (std::abs(m.coords[3 * r + 1] - m.coords[3 * l + 1]) > 1e-12) continue;
      const double ur = problem.nodeDisplacement(u, r)[0];
      const double ul = problem.nodeDisplacement(u, l)[0];
      EXPECT_NEAR(ur, 2 * ul, 1e-12 * std::abs(ur) + 1e-15);
      largest = std::max(largest, std::abs(ur));
    }
  EXPECT_GT(largest, 1e-4);
  // The tie's force: F on the right side's nodes and -2 F on the left's, so the clamp, the load
  // P and the tie balance as clamp + P + F - 2 F = 0 along x.
  const double clamp = problem.reactions()[0].force[0], f = problem.reactions()[1].force[0];
  EXPECT_GT(std::abs(f), 0.05);
  EXPECT_NEAR(f, clamp + 1.0, 1e-9);
}

// The column turned 30 degrees about z, its x-min side (and y-min in 3D) a roller on an inclined
// plane: at the interface's ends a tied node lies on one plane (two along the 3D edge), whose
// equations are then eliminated with the ties'. Tied, the two blocks are the single mesh: the
// same displacement, iterations and clamp reaction, and the planes' reactions summed.
SolidModel onInclinedRollers(const std::string& element, bool tied) {
  SolidModel model = shearedColumn(element, tied, false);
  Mesh turned = *model.mesh;
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  for (std::size_t n = 0; n < turned.numNodes(); ++n) {
    const double x = turned.coords[3 * n], y = turned.coords[3 * n + 1];
    turned.coords[3 * n] = c * x - s * y;
    turned.coords[3 * n + 1] = s * x + c * y;
  }
  model.mesh = std::make_shared<Mesh>(std::move(turned));
  std::vector<std::string> sides;
  if (!is3D(element))
    sides = {"left"};
  else
    sides = {"xmin", "ymin"};
  for (const std::string& side : sides)
    for (const char* block : {"lower-", "upper-"}) {
      if (!tied && block == std::string("upper-")) continue;
      SymmetryCondition roller;
      roller.name = (tied ? block : "") + side;
      roller.group = roller.name;
      model.symmetries.push_back(roller);
    }
  return model;
}

TEST(Ties, OnAnInclinedSymmetryPlaneAreTheSingleMesh) {
  auto comm = Tpetra::getDefaultComm();
  for (const char* element : {"quad4", "quad8", "hex8"}) {
    Problem single(onInclinedRollers(element, false), comm);
    Problem tied(onInclinedRollers(element, true), comm);
    const StaticRun rs = runWithMumps(single, 5), rt = runWithMumps(tied, 5);
    ASSERT_TRUE(rs.report.converged && rt.report.converged)
        << element << ": " << rs.report.message << rt.report.message;
    EXPECT_EQ(rt.report.iterations, rs.report.iterations) << element;
    const auto [largest, error] = compareAtEveryNode(single, *rs.u, tied, *rt.u);
    EXPECT_GT(largest, 1e-4) << element;
    EXPECT_LT(error, 1e-9 * largest) << element;
    // Reactions: the clamp, then the rollers (single: one per side; tied: lower and upper per
    // side), then the tie.
    const auto& r1 = single.reactions();
    const auto& r2 = tied.reactions();
    const std::size_t sides = is3D(element) ? 2 : 1;
    ASSERT_EQ(r1.size(), 1 + sides) << element;
    ASSERT_EQ(r2.size(), 2 + 2 * sides) << element;
    double scale = 0;
    for (int i = 0; i < 3; ++i)
      scale = std::max(scale, std::abs(r1[0].force[i]));
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(r2[0].force[i], r1[0].force[i], 1e-9 * scale) << element;
      for (std::size_t k = 0; k < sides; ++k)
        EXPECT_NEAR(r2[1 + 2 * k].force[i] + r2[2 + 2 * k].force[i], r1[1 + k].force[i],
                    1e-9 * scale)
            << element << " side " << k;
    }
  }
}

// A right side: the column's two blocks, clamped at the foot and the head, with their interface
// nodes held a shim's thickness apart, u(upper-bottom) - u(lower-top) = delta along y (Value
// -delta on [1, -1] from lower-top). Mirror symmetry about the interface puts each side at
// delta / 2, the blocks in equal compression: the foot's and the head's reactions are equal and
// opposite, and the tie's force is the foot's. Half way along the ramp, half the shim.
TEST(Ties, PrescribeARelativeMotion) {
  auto comm = Tpetra::getDefaultComm();
  const double delta = 0.01;
  SolidModel model = shearedColumn("quad4", true, false);
  model.pointLoads.clear();
  model.ties[0].components = {0};
  TieCondition shim = model.ties[0];
  shim.name = "shim";
  shim.components = {1};
  shim.value = -delta;
  model.ties.push_back(shim);
  DirichletCondition clampHead = model.dirichlet[0];
  clampHead.name = clampHead.group = "upper-top";
  model.dirichlet.push_back(clampHead);
  Problem problem(std::move(model), comm);
  const Mesh& m = *problem.model().mesh;
  const auto lower = m.boundaryNodes("lower-top"), upper = m.boundaryNodes("upper-bottom");
  ASSERT_EQ(lower.size(), upper.size());
  auto pairs = [&](const Vector& u, const std::function<void(const std::array<double, 3>&,
                                                             const std::array<double, 3>&)>& f) {
    int n = 0;
    for (std::int64_t l : lower)
      for (std::int64_t r : upper)
        if (std::abs(m.coords[3 * l] - m.coords[3 * r]) < 1e-12)
          f(problem.nodeDisplacement(u, l), problem.nodeDisplacement(u, r)), ++n;
    EXPECT_EQ(n, static_cast<int>(lower.size()));
  };
  // The state at t = 0.5 before any solve: the dependents carry half the right side.
  auto start = problem.createVector();
  problem.applyDirichlet(0.5, *start);
  pairs(*start, [&](const auto& ul, const auto& uu) {
    EXPECT_NEAR(uu[1] - ul[1], 0.5 * delta, 1e-15);
    EXPECT_EQ(uu[0] - ul[0], 0.0);
  });
  const StaticRun run = runWithMumps(problem, 3);
  ASSERT_TRUE(run.report.converged) << run.report.message;
  pairs(*run.u, [&](const auto& ul, const auto& uu) {
    EXPECT_NEAR(uu[1] - ul[1], delta, 1e-14);
    EXPECT_NEAR(ul[1], -0.5 * delta, 1e-10);
    EXPECT_NEAR(uu[1], 0.5 * delta, 1e-10);
    EXPECT_NEAR(uu[0], ul[0], 1e-15);
  });
  const auto& reactions = problem.reactions();  // foot, head, interface (x), shim (y)
  ASSERT_EQ(reactions.size(), 4u);
  const double foot = reactions[0].force[1], head = reactions[1].force[1];
  EXPECT_GT(std::abs(foot), 1.0);  // E = 1e3, a 1 % strain over a width of 1, lateral restraint
  EXPECT_NEAR(foot, -head, 1e-9 * std::abs(foot));
  EXPECT_NEAR(std::abs(reactions[3].force[1]), std::abs(foot), 1e-9 * std::abs(foot));
}

// A right side on an equation that makes nothing dependent (the same tie twice, or a tie whose
// every dof is prescribed) could contradict the others: refused, either order.
TEST(Ties, RefuseARightSideWithNothingToEliminate) {
  for (const bool valueFirst : {true, false}) {
    SolidModel model = shearedColumn("quad4", true, false);
    TieCondition twice = model.ties[0];
    twice.name = "twice";
    (valueFirst ? model.ties[0] : twice).value = 0.1;
    model.ties.push_back(twice);
    expectRefused(std::move(model), "leaves no dof to make dependent");
  }
  SolidModel held = shearedColumn("quad4", true, false);
  held.ties[0].value = 0.1;
  for (const char* group : {"lower-top", "upper-bottom"}) {
    DirichletCondition d = held.dirichlet[0];
    d.name = d.group = group;
    held.dirichlet.push_back(d);
  }
  expectRefused(std::move(held), "has a right side");
}

// Gauss-Jordan over the equations: chains resolve to independent dofs, a prescribed dof is never
// dependent, an implied equation makes nothing dependent, the largest coefficient is the pivot.
TEST(TieEquations, EliminationResolvesChains) {
  const MeshDof a{0, 0}, b{1, 0}, c{2, 0};
  auto equation = [](MeshDof x, double cx, MeshDof y, double cy) {
    TieEquation e;
    e.dofs = {x, y};
    e.coefficients = {cx, cy};
    return e;
  };
  using Terms = std::vector<std::pair<MeshDof, double>>;
  // a = b, b = c: a and b both in c.
  auto chain = eliminateTies({equation(a, 1, b, -1), equation(b, 1, c, -1)}, {});
  ASSERT_EQ(chain.size(), 2u);
  EXPECT_EQ(chain[0].dof, a);
  EXPECT_EQ(chain[0].terms, (Terms{{c, 1.0}}));
  EXPECT_EQ(chain[1].dof, b);
  EXPECT_EQ(chain[1].terms, (Terms{{c, 1.0}}));
  // a prescribed: b and c follow it; c = a again is implied.
  auto held =
      eliminateTies({equation(a, 1, b, -1), equation(b, 1, c, -1), equation(c, 1, a, -1)}, {a});
  ASSERT_EQ(held.size(), 2u);
  EXPECT_EQ(held[0].dof, b);
  EXPECT_EQ(held[0].terms, (Terms{{a, 1.0}}));
  EXPECT_EQ(held[1].dof, c);
  EXPECT_EQ(held[1].terms, (Terms{{a, 1.0}}));
  // 2 a + 3 b = 0: b = -2/3 a. Both prescribed: nothing.
  auto scaled = eliminateTies({equation(a, 2, b, 3)}, {});
  ASSERT_EQ(scaled.size(), 1u);
  EXPECT_EQ(scaled[0].dof, b);
  ASSERT_EQ(scaled[0].terms.size(), 1u);
  EXPECT_DOUBLE_EQ(scaled[0].terms[0].second, -2.0 / 3.0);
  EXPECT_TRUE(eliminateTies({equation(a, 2, b, 3)}, {a, b}).empty());
  // Linked nodes: {0, 1, 2} from the chain, {5, 7} apart.
  auto sets =
      linkedNodes({equation(a, 1, b, -1), equation({7, 1}, 1, {5, 1}, 1), equation(c, 1, b, -1)});
  EXPECT_EQ(sets, (std::vector<std::vector<std::int64_t>>{{0, 1, 2}, {5, 7}}));
}

TEST(Ties, RefuseWhatTheyCannotTie) {
  auto refused = [](const std::function<void(TieCondition&)>& change, const std::string& words) {
    SolidModel model = shearedColumn("quad4", true, false);
    change(model.ties[0]);
    expectRefused(std::move(model), words);
  };
  refused([](TieCondition& t) { t.groups[1] = "upper-left"; }, "no partner in group 'upper-left'");
  refused([](TieCondition& t) { t.groups[1] = "lower-top"; }, "tie it to itself");
  refused([](TieCondition& t) { t.groups[1] = "nowhere"; }, "nowhere");
  refused([](TieCondition& t) { t.coefficients = {1.0}; }, "1 coefficients for 2 groups");
  refused([](TieCondition& t) { t.coefficients = {0.0, 0.0}; }, "every coefficient is zero");
  refused([](TieCondition& t) { t.groups.pop_back(), t.coefficients.pop_back(); },
          "two groups or more");
}

}  // namespace
}  // namespace contactlab::test
