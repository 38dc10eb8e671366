// The centrifugal load (CentrifugalLoad in Loads.hpp, CentrifugalLoadKernel): the assembled
// nodal forces of a block sum to rho omega^2 int P (x - c) dV, known in closed form for a
// rectangle and an annular sector (curved quad8 edges); a follower load's stiffness matches
// central differences of its residual, and a dead load has none; the 3D axis projects out the
// axial component.
#include "ProblemTestSupport.hpp"

#include "core/materials/SaintVenantKirchhoff.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab::test {
namespace {

constexpr double kDensity = 7.8e-9, kOmega = 12000.0;

CentrifugalLoad spin(std::array<double, 3> centre) {
  CentrifugalLoad load;
  load.name = "spin";
  load.density = kDensity;
  load.angularVelocity = kOmega;
  load.centre = centre;
  load.function.kind = LoadFunction::Kind::Constant;
  return load;
}

// The sum over the owned dofs of each component of the external force -R(u = 0) (no support,
// no other load: the internal force vanishes at u = 0).
std::array<double, 3> resultant(Problem& problem) {
  auto u = problem.createVector();
  auto r = problem.createVector();
  problem.assemble(*u, 1.0, r.get(), false);
  const int dim = problem.model().mesh->dim;
  auto data = r->getData(0);
  std::array<double, 3> local{}, global{};
  for (std::size_t i = 0; i < static_cast<std::size_t>(data.size()); ++i)
    local[i % dim] -= data[i];
  Teuchos::reduceAll(*problem.dofs().comm(), Teuchos::REDUCE_SUM, 3, local.data(), global.data());
  return global;
}

Teuchos::RCP<const Comm> worldComm() {
  return Tpetra::getDefaultComm();
}

TEST(CentrifugalLoad, RectangleForcesSumToTheMassTimesTheCentroidsAcceleration) {
  for (const char* type : {"quad4", "tri6", "quad8"}) {
    RectangleParams rect;
    rect.origin = {2.0, 30.0};
    rect.lengths = {4.0, 6.0};
    rect.divisions = {3, 5};
    rect.elementType = type;
    SolidModel model;
    model.mesh = std::make_shared<Mesh>(generateRectangle(rect));
    model.materials["body"] = std::make_shared<LinearElastic>(2e5, 0.3);
    model.centrifugalLoads.push_back(spin({1.0, -5.0, 0.0}));
    Problem problem(model, worldComm());
    const auto f = resultant(problem);
    const double mass = kDensity * 24.0, w2 = kOmega * kOmega;
    // Centroid (4, 33) from the centre (1, -5).
    EXPECT_NEAR(f[0], mass * w2 * 3.0, 1e-12 * mass * w2 * 38) << type;
    EXPECT_NEAR(f[1], mass * w2 * 38.0, 1e-12 * mass * w2 * 38) << type;
  }
}

TEST(CentrifugalLoad, AnnularSectorForcesSumToTheClosedForm) {
  // int x dA = (b^3 - a^3) / 3 sin(theta), int y dA = (b^3 - a^3) / 3 (1 - cos(theta)) over the
  // sector a <= r <= b, 0 <= phi <= theta about the centre; quad8 edges on the arcs are
  // parabolas, so the area moments carry a geometric error of about (h / R)^4.
  RingSectorParams ring;
  ring.innerRadius = 40.0;
  ring.outerRadius = 100.0;
  ring.angle = 60.0;
  ring.radialDivisions = 6;
  ring.circumferentialDivisions = 8;
  ring.elementType = "quad8";
  SolidModel model;
  model.mesh = std::make_shared<Mesh>(generateRingSector(ring));
  model.materials["body"] = std::make_shared<LinearElastic>(2e5, 0.3);
  model.centrifugalLoads.push_back(spin({0.0, 0.0, 0.0}));
  Problem problem(model, worldComm());
  const auto f = resultant(problem);
  const double theta = M_PI / 3, moment = (1e6 - 64e3) / 3;
  const double scale = kDensity * kOmega * kOmega;
  EXPECT_NEAR(f[0], scale * moment * std::sin(theta), 1e-6 * scale * moment);
  EXPECT_NEAR(f[1], scale * moment * (1 - std::cos(theta)), 1e-6 * scale * moment);
}

TEST(CentrifugalLoad, AxialComponentIsProjectedOut) {
  // A box spun about the axis through (0, 0, 0) along (1, 1, 0) / sqrt(2): the force is
  // rho omega^2 (x - (x.a) a), of zero component along a, and
  // rho omega^2 V (centroid - (centroid.a) a) in total.
  BoxParams box;
  box.origin = {1.0, 2.0, 3.0};
  box.lengths = {2.0, 1.0, 4.0};
  box.divisions = {2, 2, 2};
  box.elementType = "hex20";
  SolidModel model;
  model.mesh = std::make_shared<Mesh>(generateBox(box));
  model.materials["body"] = std::make_shared<LinearElastic>(2e5, 0.3);
  auto load = spin({0.0, 0.0, 0.0});
  load.axis = {M_SQRT1_2, M_SQRT1_2, 0.0};
  model.centrifugalLoads.push_back(load);
  Problem problem(model, worldComm());
  const auto f = resultant(problem);
  const double scale = kDensity * kOmega * kOmega * 8.0;
  const double c[3] = {2.0, 2.5, 5.0}, along = (c[0] + c[1]) * M_SQRT1_2;
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(f[i], scale * (c[i] - along * load.axis[i]), 1e-12 * scale * 10) << i;
}

// K v against (R(u + e v) - R(u - e v)) / 2e for a finite-strain block, with and without the
// load: the difference is the load's stiffness alone (the material's is tested elsewhere).
double tangentMismatch(SurfaceLoad::Follower follower, double* loadStiffness) {
  auto mesh = unitMesh("quad8", 2);
  for (std::size_t n = 0; n < mesh->numNodes(); ++n)
    mesh->coords[3 * n + 1] += 50.0;  // 50 above the axis
  auto build = [&](bool loaded) {
    SolidModel model;
    model.mesh = mesh;
    model.materials["body"] = std::make_shared<SaintVenantKirchhoff>(2e5, 0.3);
    if (loaded) {
      auto load = spin({0.2, 0.1, 0.0});
      load.follower = follower;
      model.centrifugalLoads.push_back(load);
    }
    return std::make_unique<Problem>(model, worldComm());
  };
  auto with = build(true), without = build(false);
  auto u = with->createVector(), v = with->createVector();
  u->randomize(-1e-3, 1e-3);
  v->randomize(-1e-2, 1e-2);
  auto applyDifference = [&](Vector& out) {  // (K_with - K_without) v
    auto a = with->createVector(), b = with->createVector();
    with->assemble(*u, 1.0, nullptr, true);
    with->tangent()->apply(*v, *a);
    without->assemble(*u, 1.0, nullptr, true);
    without->tangent()->apply(*v, *b);
    out.update(1.0, *a, -1.0, *b, 0.0);
  };
  auto residualDifference = [&](double e, Vector& out) {  // R_with - R_without at u + e v
    auto x = with->createVector(), a = with->createVector(), b = with->createVector();
    x->update(1.0, *u, e, *v, 0.0);
    with->assemble(*x, 1.0, a.get(), false);
    without->assemble(*x, 1.0, b.get(), false);
    out.update(1.0, *a, -1.0, *b, 0.0);
  };
  auto kv = with->createVector(), plus = with->createVector(), minus = with->createVector();
  applyDifference(*kv);
  // The load is linear in u, so any step is exact; a large one keeps round-off small.
  const double e = 1.0;
  residualDifference(e, *plus);
  residualDifference(-e, *minus);
  auto fd = with->createVector();
  fd->update(0.5 / e, *plus, -0.5 / e, *minus, 0.0);
  *loadStiffness = kv->norm2();
  fd->update(-1.0, *kv, 1.0);
  return fd->norm2();
}

TEST(CentrifugalLoad, FollowerStiffnessMatchesCentralDifferences) {
  double stiffness = 0;
  const double mismatch = tangentMismatch(SurfaceLoad::Follower::Automatic, &stiffness);
  EXPECT_GT(stiffness, 0.0);
  EXPECT_LT(mismatch, 1e-7 * stiffness);
}

TEST(CentrifugalLoad, DeadLoadHasNoStiffnessAndNoDependenceOnU) {
  double follower = 0, dead = 0;
  tangentMismatch(SurfaceLoad::Follower::Automatic, &follower);
  const double mismatch = tangentMismatch(SurfaceLoad::Follower::No, &dead);
  EXPECT_EQ(dead, 0.0);
  EXPECT_LT(mismatch, 1e-7 * follower);
}

}  // namespace
}  // namespace contactlab::test
