// A contact geometry that cannot be integrated on a Newton iterate (generalized Newton re-pairs
// every iterate; a wild one can collapse a mortar slave facet) is a failed iterate, which the
// step's cut recovers from: ContactProblem::updateGeometry records it, assemble() returns NaN
// and assemblyFailure() names it. At the reference state it stays the model's error. The tube
// expansion at mu = 0.1 under generalized Newton ended without results on such an iterate.
#include "core/materials/LinearElastic.hpp"
#include "core/mesh/MeshGenerators.hpp"
#include "formulations/ContactProblem.hpp"
#include "formulations/FormulationRegistry.hpp"

#include <Tpetra_Core.hpp>

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

// Two stacked hex8 blocks touching, mortar, frictionless augmented Lagrangian.
struct StackedMortar {
  StackedMortar() : comm(Tpetra::getDefaultComm()), solid(model(), comm), contact(solid, zones()) {}

  static SolidModel model() {
    StackedBlocks3DParams b;
    b.lowerDivisions = {3, 3, 1};
    b.upperDivisions = {2, 2, 1};
    b.gap = -1e-6;
    SolidModel m;
    m.mesh = std::make_shared<Mesh>(generateStackedBlocks3D(b));
    for (const auto& name : m.mesh->blockNames())
      m.materials[name] = std::make_shared<LinearElastic>(1000.0, 0.3);
    DirichletCondition bottom;
    bottom.name = "bottom";
    bottom.group = "lower-bottom";
    bottom.components = {0, 1, 2};
    m.dirichlet.push_back(bottom);
    DirichletCondition top = bottom;
    top.name = "top";
    top.group = "upper-top";
    top.value = 0.0;
    m.dirichlet.push_back(top);
    return m;
  }
  static std::vector<ContactZone> zones() {
    registerFormulations();
    Teuchos::ParameterList p = *formulationRegistry().get("augmented-lagrangian").validParameters();
    p.set("Normal Augmentation", 1e4);
    ContactZone zone;
    zone.name = "interface";
    zone.slave = "upper-bottom";
    zone.master = "lower-top";
    zone.law = formulationRegistry().get("augmented-lagrangian").build(p);
    zone.discretization = "mortar";
    return {zone};
  }
  // x with every slave surface node displaced onto one point: every slave facet collapses.
  Teuchos::RCP<Vector> collapsedSlave() const {
    auto x = contact.createVector();
    const Mesh& mesh = *solid.model().mesh;
    for (std::int64_t node : mesh.boundaryNodes("upper-bottom"))
      for (int c = 0; c < 3; ++c) {
        const GO gid = solid.dofs().globalNode(node) * 3 + c;
        if (x->getMap()->isNodeGlobalElement(gid))
          x->replaceGlobalValue(gid, 0.5 - mesh.coords[3 * node + c]);
      }
    return x;
  }
  Teuchos::RCP<const Comm> comm;
  Problem solid;
  ContactProblem contact;
};

bool allNaN(const Vector& v) {
  const auto data = v.getData(0);
  for (const double value : data)
    if (!std::isnan(value)) return false;
  return true;
}

TEST(ContactGeometryFailure, AnIterateWhoseMortarIntegralsDoNotExistIsAFailedIterate) {
  StackedMortar m;
  auto x = m.contact.createVector();
  m.contact.updateGeometry(*x, 0.0);  // the reference: fine
  auto residual = m.contact.createVector();
  m.contact.assemble(*x, 0.0, residual.get(), true);
  ASSERT_TRUE(m.contact.assemblyFailure().code.empty());

  const auto wild = m.collapsedSlave();
  EXPECT_NO_THROW(m.contact.updateGeometry(*wild, 0.0));
  m.contact.assemble(*wild, 0.0, residual.get(), true);
  const AssemblyFailure failure = m.contact.assemblyFailure();
  EXPECT_EQ(failure.code, "contact-geometry-failed");
  EXPECT_NE(failure.message.find("degenerate"), std::string::npos) << failure.message;
  EXPECT_TRUE(allNaN(*residual));

  // Back at a sound state (the step's cut restarts from the converged one): all is well again.
  m.contact.updateGeometry(*x, 0.0);
  m.contact.assemble(*x, 0.0, residual.get(), true);
  EXPECT_TRUE(m.contact.assemblyFailure().code.empty());
  EXPECT_FALSE(allNaN(*residual));
  EXPECT_TRUE(std::isfinite(residual->norm2()));
}

TEST(ContactGeometryFailure, AtTheReferenceStateItIsTheModelsError) {
  StackedMortar m;
  EXPECT_ANY_THROW(m.contact.updateGeometry(*m.collapsedSlave(), 0.0));
}

}  // namespace
}  // namespace contactlab
