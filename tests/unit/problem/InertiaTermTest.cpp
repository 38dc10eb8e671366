// Problem's inertia term (NonlinearSystem::setInertia, what the slow-dynamics regularization
// hands it): its tangent is the derivative of its residual, the inertia force vanishes at the
// reference and is c M (u - reference) off it, a term without reference leaves the residual
// static, and a model without density refuses a nonzero coefficient.
#include "ProblemTestSupport.hpp"

#include "base/InputError.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab::test {
namespace {

Field zero = [](const double*, double* u) { u[0] = u[1] = u[2] = 0; };

// A plate held on its bottom only (the other dofs free), with density 2 (or without).
SolidModel plate(double density = 2.0) {
  auto model = elasticModel(unitMesh("quad8", 3), 10.0, 0.3, zero, {});
  model.materials["body"] = std::make_shared<LinearElastic>(10.0, 0.3, density);
  model.dirichlet.resize(1);  // one condition, on the bottom only
  model.dirichlet[0].name = model.dirichlet[0].group = "bottom";
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

constexpr double kCoefficient = 3.7;

// `dynamic` carries c M (u - reference) (or c M in the tangent only), `reference` is static.
struct Fixture {
  Problem dynamic, reference;
  Teuchos::RCP<Vector> star;
  explicit Fixture(bool inResidual)
      : dynamic(plate(), Tpetra::getDefaultComm()), reference(plate(), Tpetra::getDefaultComm()) {
    star = freeField(dynamic, [](int i) { return 1e-3 * std::sin(1.0 + i); });
    InertiaTerm term;
    term.coefficient = kCoefficient;
    if (inResidual) term.reference = star;
    dynamic.setInertia(term);
  }
};

TEST(InertiaTerm, TangentIsTheResidualsDerivative) {
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

TEST(InertiaTerm, InertiaForceVanishesAtTheReferenceAndIsCMOffIt) {
  Fixture f(true);
  const double t = 0.45;
  const auto& star = f.star;
  auto rd = f.dynamic.createVector(), rs = f.dynamic.createVector();
  f.dynamic.assemble(*star, t, rd.get(), true);
  f.reference.assemble(*star, t, rs.get(), true);
  rd->update(-1.0, *rs, 1.0);
  EXPECT_LT(norm(*rd), 1e-12 * norm(*rs));

  // Off the reference the difference is c M v, and c M = K_dynamic - K_static is c times a
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

// The dynamic system minus the static one at u, t: the residuals' difference norm, and the
// tangents' difference applied to a fixed v, with v.
struct Difference {
  double residual;
  Teuchos::RCP<Vector> v, tangentTimesV;
};
Difference difference(Fixture& f, const Vector& u, double t) {
  auto rd = f.dynamic.createVector(), rs = f.dynamic.createVector();
  f.dynamic.assemble(u, t, rd.get(), true);
  f.reference.assemble(u, t, rs.get(), true);
  rd->update(-1.0, *rs, 1.0);
  Difference d{norm(*rd), freeField(f.dynamic, [](int i) { return std::cos(0.7 * i); }),
               f.dynamic.createVector()};
  auto Ks = f.dynamic.createVector();
  f.dynamic.tangent()->apply(*d.v, *d.tangentTimesV);
  f.reference.tangent()->apply(*d.v, *Ks);
  d.tangentTimesV->update(-1.0, *Ks, 1.0);
  return d;
}

TEST(InertiaTerm, WithoutReferenceTheResidualStaysStatic) {
  Fixture f(false);
  auto u = freeField(f.dynamic, [](int i) { return 1e-3 * std::cos(2.0 + i); });
  const Difference d = difference(f, *u, 0.45);
  EXPECT_EQ(d.residual, 0.0);
  EXPECT_GT(d.v->dot(*d.tangentTimesV), 0.0);  // c v^T M v
}

TEST(InertiaTerm, NeedsADensity) {
  Problem p(plate(0.0), Tpetra::getDefaultComm());
  EXPECT_NE(p.massUnavailable().find("density 0"), std::string::npos) << p.massUnavailable();
  EXPECT_EQ(Problem(plate(), Tpetra::getDefaultComm()).massUnavailable(), "");
  InertiaTerm term;
  term.coefficient = 1.0;
  try {
    p.setInertia(term);
    FAIL() << "a model without mass took an inertia";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("density 0"), std::string::npos) << e.what();
  }
  p.setInertia({});  // no inertia: accepted
}

// The term is removed by a zero coefficient: residual and tangent are the static ones again.
TEST(InertiaTerm, ZeroCoefficientRemovesIt) {
  Fixture f(true);
  f.dynamic.setInertia({});
  auto u = freeField(f.dynamic, [](int i) { return 1e-3 * std::cos(2.0 + i); });
  const Difference d = difference(f, *u, 0.2);
  EXPECT_EQ(d.residual, 0.0);
  EXPECT_EQ(norm(*d.tangentTimesV), 0.0);
}

}  // namespace
}  // namespace contactlab::test
