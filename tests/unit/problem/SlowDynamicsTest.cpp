// The slow-dynamics inertia in Problem: its tangent is the derivative of its residual, the
// inertia force vanishes at the implicit-Euler predictor u* = u_n + dt v_n, and 'tangent-only'
// leaves the residual static.
#include "ProblemTestSupport.hpp"

#include "base/InputError.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab::test {
namespace {

Field zero = [](const double*, double* u) { u[0] = u[1] = u[2] = 0; };

// A plate held on its bottom only (the other dofs free), with density and the regularization.
SolidModel plate(bool enabled, bool inResidual) {
  auto model = elasticModel(unitMesh("quad8", 3), 10.0, 0.3, zero, {});
  model.materials["body"] = std::make_shared<LinearElastic>(10.0, 0.3, 2.0);
  model.dirichlet.resize(1);  // one condition, on the bottom only
  model.dirichlet[0].name = model.dirichlet[0].group = "bottom";
  model.slowDynamics.enabled = enabled;
  model.slowDynamics.alpha = 0.7;
  model.slowDynamics.timeScale = 0.5;
  model.slowDynamics.inertiaInResidual = inResidual;
  return model;
}

// A field with every free owned dof set from `f`, zero on the constrained ones.
Teuchos::RCP<Vector> freeField(const Problem& p, double (*f)(int)) {
  auto v = p.createVector();
  auto d = v->getDataNonConst(0);
  for (int i = 0; i < static_cast<int>(d.size()); ++i)
    d[i] = p.constrainedDofs()[i] ? 0.0 : f(i);
  return v;
}

double norm(const Vector& v) {
  return v.norm2();
}

struct Fixture {
  Problem dynamic, reference;
  Teuchos::RCP<Vector> u1, u2;
  Fixture(bool inResidual)
      : dynamic(plate(true, inResidual), Tpetra::getDefaultComm()),
        reference(plate(false, true), Tpetra::getDefaultComm()) {
    u1 = freeField(dynamic, [](int i) { return 1e-3 * std::sin(1.0 + i); });
    u2 = freeField(dynamic, [](int i) { return 2e-3 * std::cos(0.5 * i); });
    for (Problem* p : {&dynamic, &reference}) {
      p->commitState(*u1, 0.1);
      p->commitState(*u2, 0.3);
    }
  }
};

TEST(SlowDynamics, TangentIsTheResidualsDerivative) {
  Fixture f(true);
  const double t = 0.45;
  auto u = freeField(f.dynamic, [](int i) { return 1e-3 * std::cos(2.0 + i); });
  auto v = freeField(f.dynamic, [](int i) { return std::sin(0.3 * i * i); });
  auto r0 = f.dynamic.createVector(), r1 = f.dynamic.createVector();
  f.dynamic.assemble(*u, t, r0.get(), true);
  auto uv = f.dynamic.createVector();
  uv->update(1.0, *u, 1.0, *v, 0.0);
  f.dynamic.assemble(*uv, t, r1.get(), false);
  auto Kv = f.dynamic.createVector();
  f.dynamic.tangent()->apply(*v, *Kv);
  // Linear material: R(u + v) - R(u) = K v to round-off.
  r1->update(1.0, *r0, 1.0, *Kv, -1.0);
  EXPECT_LT(norm(*r1), 1e-10 * norm(*Kv));
}

TEST(SlowDynamics, InertiaForceVanishesAtThePredictorAndIsCMOffIt) {
  Fixture f(true);
  const double t = 0.45, dt = t - 0.3;
  // u* = u2 + dt (u2 - u1) / (0.3 - 0.1).
  auto star = f.dynamic.createVector();
  star->update(1.0 + dt / 0.2, *f.u2, -dt / 0.2, *f.u1, 0.0);
  auto rd = f.dynamic.createVector(), rs = f.dynamic.createVector();
  f.dynamic.assemble(*star, t, rd.get(), true);
  f.reference.assemble(*star, t, rs.get(), true);
  rd->update(-1.0, *rs, 1.0);
  EXPECT_LT(norm(*rd), 1e-12 * norm(*rs));

  // Off the predictor the difference is c M v, and c M = K_dynamic - K_static is c times a
  // positive mass: v^T (c M) v > 0.
  auto v = freeField(f.dynamic, [](int i) { return std::cos(0.7 * i); });
  auto uv = f.dynamic.createVector();
  uv->update(1.0, *star, 1.0, *v, 0.0);
  f.dynamic.assemble(*uv, t, rd.get(), false);
  f.reference.assemble(*uv, t, rs.get(), false);
  rd->update(-1.0, *rs, 1.0);
  auto Kd = f.dynamic.createVector(), Ks = f.dynamic.createVector();
  f.dynamic.tangent()->apply(*v, *Kd);
  f.reference.tangent()->apply(*v, *Ks);
  Kd->update(-1.0, *Ks, 1.0);  // c M v
  EXPECT_GT(v->dot(*Kd), 0.0);
  rd->update(-1.0, *Kd, 1.0);
  EXPECT_LT(norm(*rd), 1e-10 * norm(*Kd));
}

TEST(SlowDynamics, TangentOnlyKeepsTheStaticResidual) {
  Fixture f(false);
  const double t = 0.45;
  auto u = freeField(f.dynamic, [](int i) { return 1e-3 * std::cos(2.0 + i); });
  auto rd = f.dynamic.createVector(), rs = f.dynamic.createVector();
  f.dynamic.assemble(*u, t, rd.get(), true);
  f.reference.assemble(*u, t, rs.get(), true);
  rd->update(-1.0, *rs, 1.0);
  EXPECT_EQ(norm(*rd), 0.0);
  auto v = freeField(f.dynamic, [](int i) { return std::cos(0.7 * i); });
  auto Kd = f.dynamic.createVector(), Ks = f.dynamic.createVector();
  f.dynamic.tangent()->apply(*v, *Kd);
  f.reference.tangent()->apply(*v, *Ks);
  EXPECT_GT(v->dot(*Kd), v->dot(*Ks));  // + c v^T M v
}

TEST(SlowDynamics, NeedsADensity) {
  auto model = plate(true, true);
  model.materials["body"] = std::make_shared<LinearElastic>(10.0, 0.3);
  try {
    Problem p(model, Tpetra::getDefaultComm());
    FAIL() << "a model without mass was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("density 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace contactlab::test
