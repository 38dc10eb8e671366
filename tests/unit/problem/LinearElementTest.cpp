// Linear elements (Problem.hpp: small strain, a Material::linear() law, no prescribed
// temperature) keep the stiffness integrated at their first assembly and give the force as
// K u; a model of only such elements also keeps the assembled sum of their matrices, from which
// every later tangent starts. The same model with the law flagged non-linear integrates every
// element at every assembly: both must give the same residual and tangent, whether the first
// assembly asked for the tangent or not, at a second state after the first (where the kept
// stiffness is used: the linear law is not evaluated there, the other one is), and a tangent
// alone after a residual alone.
// Distorted meshes of every 2D and 3D element type, and axisymmetric rings, on 1 and 2 ranks.
#include "ProblemTestSupport.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab::test {
namespace {

// LinearElastic flagged linear or not, counting its evaluations (quadrature points visited), so
// that the test sees whether the kept stiffness was used, not only that it is right.
class CountingLaw : public Material {
 public:
  explicit CountingLaw(bool linear) : linear_(linear) {}
  std::string name() const override { return law_.name(); }
  Kinematics kinematics() const override { return law_.kinematics(); }
  bool linear() const override { return linear_; }
  void evaluate(const MaterialInput& in, MaterialOutput& out) const override {
    ++evaluations;
    law_.evaluate(in, out);
  }
  std::optional<double> referenceTemperature() const override {
    return law_.referenceTemperature();
  }
  mutable long evaluations = 0;

 private:
  LinearElastic law_{210.0, 0.3};
  bool linear_;
};

// `name`: an element type, or one followed by " axisymmetric" (the ring kernel, whose radial
// translation strains the hoop: not in K's null space, unlike the axial one).
Problem makeProblem(const std::string& name, const std::shared_ptr<CountingLaw>& law) {
  const bool axisymmetric = name.find(" axisymmetric") != std::string::npos;
  const std::string type = name.substr(0, name.find(' '));
  auto mesh = unitMesh(type, 2);
  distort(*mesh, 2, type.rfind("tet", 0) == 0 ? 0.04 : 0.12);  // tets: a sixth of a cell
  if (axisymmetric)
    for (std::size_t i = 0; i < mesh->numNodes(); ++i)
      mesh->coords[3 * i] += 0.5;  // off the axis
  SolidModel model;
  model.mesh = mesh;
  model.axisymmetric = axisymmetric;
  model.materials["body"] = law;
  DirichletCondition bc;
  bc.name = bc.group = boundaryGroups(mesh->dim).front();
  for (int c = 0; c < mesh->dim; ++c)
    bc.components.push_back(c);
  model.dirichlet.push_back(bc);
  return Problem(std::move(model), Tpetra::getDefaultComm());
}

// A state that depends on the global dof only (the same on any number of ranks).
Teuchos::RCP<Vector> state(const Problem& problem, double scale) {
  auto u = problem.createVector();
  const auto map = u->getMap();
  auto data = u->getDataNonConst(0);
  for (LO i = 0; i < static_cast<LO>(data.size()); ++i)
    data[i] = scale * std::sin(1.7 * static_cast<double>(map->getGlobalElement(i)) + scale);
  return u;
}

double maxDifference(const Vector& a, const Vector& b) {
  Vector d(a, Teuchos::Copy);
  d.update(-1.0, b, 1.0);
  return d.normInf();
}

class LinearElement : public ::testing::TestWithParam<std::string> {};

TEST_P(LinearElement, KeptStiffnessGivesTheIntegratedResidualAndTangent) {
  for (const bool tangentFirst : {true, false}) {
    auto keptLaw = std::make_shared<CountingLaw>(true);
    auto integratedLaw = std::make_shared<CountingLaw>(false);
    Problem kept = makeProblem(GetParam(), keptLaw);
    Problem integrated = makeProblem(GetParam(), integratedLaw);
    auto r1 = kept.createVector(), r2 = integrated.createVector();
    auto first = state(kept, 0.01);
    kept.assemble(*first, 0.0, r1.get(), tangentFirst);
    integrated.assemble(*first, 0.0, r2.get(), tangentFirst);
    EXPECT_LE(maxDifference(*r1, *r2), 1e-12 * r2->normInf()) << "first assembly";
    const long keptBefore = keptLaw->evaluations, integratedBefore = integratedLaw->evaluations;
    auto second = state(kept, 0.03);
    kept.assemble(*second, 0.0, r1.get(), true);
    integrated.assemble(*second, 0.0, r2.get(), true);
    EXPECT_EQ(keptLaw->evaluations, keptBefore) << "the kept stiffness was integrated again";
    EXPECT_GT(integratedLaw->evaluations, integratedBefore);
    ASSERT_GT(r2->normInf(), 0.0);
    EXPECT_LE(maxDifference(*r1, *r2), 1e-12 * r2->normInf()) << "second assembly";
    auto k1 = kept.createVector(), k2 = integrated.createVector();
    kept.tangent()->apply(*second, *k1);
    integrated.tangent()->apply(*second, *k2);
    ASSERT_GT(k2->normInf(), 0.0);
    EXPECT_LE(maxDifference(*k1, *k2), 1e-12 * k2->normInf()) << "tangent";
    // A tangent alone, after a residual alone: the kept model starts it from the element
    // matrices' kept sum (MatrixAssembler::beginFromKept), and it is the tangent as before.
    kept.assemble(*first, 0.0, r1.get(), false);
    kept.assemble(*first, 0.0, nullptr, true);
    integrated.assemble(*first, 0.0, nullptr, true);
    kept.tangent()->apply(*second, *k1);
    integrated.tangent()->apply(*second, *k2);
    EXPECT_LE(maxDifference(*k1, *k2), 1e-12 * k2->normInf()) << "tangent alone";
  }
}

INSTANTIATE_TEST_SUITE_P(EveryType, LinearElement,
                         ::testing::Values("quad4", "quad8", "quad9", "tri3", "tri6", "hex8",
                                           "hex20", "hex27", "tet4", "tet10", "quad8 axisymmetric",
                                           "tri6 axisymmetric"));

}  // namespace
}  // namespace contactlab::test
