// The geometric columns (the geometry's derivatives, by central differences of the re-paired
// residual) far from the model: a block thrown 1e6 of its size through a rigid plane, as a
// load-controlled body held by soft springs is by the first iterate from an open gap. A plane's
// projection adds nothing to the tangent there, so the columns with the geometry in Newton must
// equal the frozen-geometry ones. With a difference step fixed at 1e-7 of the facet they were
// 1e-4 off (the step rounded on coordinates of 1e6 and the residual's round-off over it), which
// sent generalized Newton's next iterate 67 mm off the obstacle on code_aster's SSNV503.
#include "ContactTestZones.hpp"

#include "core/materials/LinearElastic.hpp"
#include "core/mesh/MeshGenerators.hpp"
#include "formulations/ContactProblem.hpp"

#include <Tpetra_Core.hpp>

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

TEST(GeometricColumns, HoldOnAnIterateThrownFarThroughAPlane) {
  RectangleParams r;
  r.divisions = {4, 2};
  r.origin = {0.0, 0.1};
  SolidModel model;
  model.mesh = std::make_shared<Mesh>(generateRectangle(r));
  for (const auto& name : model.mesh->blockNames())
    model.materials[name] = std::make_shared<LinearElastic>(1000.0, 0.0);
  Problem solid(model, Tpetra::getDefaultComm());
  ContactProblem contact(solid, {test::floorZone(0.3, "augmented-lagrangian")});

  auto x = contact.createVector();
  contact.updateGeometry(*x, 1.0);  // the first pairing, at rest (it refuses deep penetrations)
  {  // every displacement 1e6 down and 1e3 along the plane: closed and slipping
    auto data = x->getDataNonConst(0);
    for (LO i = 0; i < static_cast<LO>(data.size()); ++i) {
      const GO gid = x->getMap()->getGlobalElement(i);
      data[i] = gid < solid.dofs().numGlobalDofs() ? (gid % 2 ? -1e6 : 1e3) : 1.0;
    }
  }
  auto d = contact.createVector(), frozen = contact.createVector(),
       repaired = contact.createVector(), r0 = contact.createVector();
  d->randomize();
  contact.updateGeometry(*x, 1.0);
  contact.assemble(*x, 1.0, r0.get(), true);
  contact.tangent()->apply(*d, *frozen);
  contact.setGeometricTerms(GeometricTerms::pairing);
  contact.updateGeometry(*x, 1.0);
  contact.assemble(*x, 1.0, r0.get(), true);
  contact.tangent()->apply(*d, *repaired);
  repaired->update(-1.0, *frozen, 1.0);
  EXPECT_LT(repaired->normInf(), 1e-8 * frozen->normInf());
}

}  // namespace
}  // namespace contactlab
