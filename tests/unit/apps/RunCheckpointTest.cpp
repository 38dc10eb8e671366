// RunCheckpoint: a state written to checkpoint.h5 and read into a freshly built model of the same
// scene comes back exactly (displacements and contact unknowns, internal variables, friction
// history, the points' tangent frames), and the file's layout is the documented one (doc/scenes.md, "Checkpoints").
#include "apps/RunCheckpoint.hpp"
#include "apps/SceneModel.hpp"
#include "base/InputError.hpp"
#include "core/io/Hdf5Reader.hpp"
#include "core/problem/Problem.hpp"
#include "formulations/ContactProblem.hpp"

#include <Tpetra_Core.hpp>

#include <filesystem>
#include <gtest/gtest.h>
#include <memory>
#include <unistd.h>

namespace contactlab {
namespace {

// A J2 block pressed onto a rigid floor with Coulomb friction: internal variables, multipliers
// (p and Lambda per point) and a friction history, all in one small model.
const char* kScene = R"(contactlab:
  Name: checkpoint-unit
  Mesh:
    Type: rectangle
    rectangle: {Lx: 2.0, Ly: 1.0, nx: 4, ny: 2, Element: quad4}
  Materials:
    body:
      Type: j2-small-strain
      j2-small-strain: {E: 100.0, nu: 0.3, Yield Stress: 1.0}
  Dirichlet:
    fix: {Group: top, Components: xy}
  Contact:
    floor:
      Slave: bottom
      Obstacle: {Type: plane, Point: [0.0, 0.0], Normal: [0.0, 1.0]}
      Friction: 0.3
      Formulation:
        Type: augmented-lagrangian
        augmented-lagrangian: {Normal Augmentation: 100.0, Tangential Augmentation: 100.0}
)";

struct Model {
  SceneModel sm;
  std::unique_ptr<Problem> problem;
  std::unique_ptr<ContactProblem> contact;
  Teuchos::RCP<Vector> x;
  Model() {
    auto comm = Tpetra::getDefaultComm();
    sm = loadScene(readSceneText(kScene, "checkpoint-unit.yaml"), comm);
    problem = std::make_unique<Problem>(sm.model, comm);
    contact = std::make_unique<ContactProblem>(*problem, sm.contact);
    x = contact->createVector();
    contact->updateGeometry(*x, 0.0);
  }
};

// A value for every entry that no two entries share (a swapped or dropped entry shows).
double pattern(std::size_t i, double scale) {
  return scale * (1.0 + 1e-3 * i + 1e-7 * i * i);
}

std::string scratch(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("contactlab-" + std::to_string(::getpid()) + "-" + name))
      .string();
}

TEST(RunCheckpoint, WriteThenReadRestoresTheStateExactly) {
  Model a;
  // Every unknown, internal variable and history value set to a distinct number.
  auto values = a.x->getDataNonConst(0);
  for (std::size_t i = 0; i < static_cast<std::size_t>(values.size()); ++i)
    values[i] = pattern(i, 1e-3);
  values = Teuchos::null;
  ElementStates states = a.problem->gatherElementStates();
  ASSERT_FALSE(states.values.empty()) << "J2 has internal variables";
  for (std::size_t i = 0; i < states.values.size(); ++i)
    states.values[i] = pattern(i, 1e-4);
  a.problem->setElementStates(states);
  ContactHistory history = a.contact->convergedHistory(*a.x);
  ASSERT_GT(history.node.size(), 0u);
  for (std::size_t i = 0; i < history.resistance.size(); ++i) {
    history.resistance[i] = pattern(i, 0.5);
    history.slip[i] = pattern(i, -2e-3);
    history.frame[i] = pattern(i, 0.25);  // the tangential unknowns' frames (t1)
  }
  history.everInContact = true;
  a.contact->restoreHistory(history, *a.x, 0.375);

  CheckpointInfo info;
  info.scenePath = "/somewhere/checkpoint-unit.yaml";
  info.overrides = {"Mesh/rectangle/nx=4", "Load Steps/Steps=3"};
  info.sceneHash = sceneHash(*a.sm.scene.params);
  info.time = 0.375;
  info.step = 3;
  info.stepSize = 0.0625;
  info.stepsRows = 3;
  info.vtkFrames = 4;
  info.totals = {17, 19, 1, 5, 7, 3, {}};
  for (std::size_t k = 0; k < info.totals.cycling.size(); ++k)
    info.totals.cycling[k] = static_cast<int>(10 + k);
  const std::string path = scratch("checkpoint.h5");
  writeCheckpoint(path, info, *a.problem, a.contact.get(), *a.x);

  Model b;
  const CheckpointInfo read = restoreCheckpoint(path, *b.problem, b.contact.get(), *b.x);
  EXPECT_EQ(read.scenePath, info.scenePath);
  EXPECT_EQ(read.overrides, info.overrides);
  EXPECT_EQ(read.sceneHash, info.sceneHash);
  EXPECT_EQ(read.time, info.time);
  EXPECT_EQ(read.step, info.step);
  EXPECT_EQ(read.stepSize, info.stepSize);
  EXPECT_EQ(read.stepsRows, info.stepsRows);
  EXPECT_EQ(read.vtkFrames, info.vtkFrames);
  EXPECT_EQ(read.totals.iterations, info.totals.iterations);
  EXPECT_EQ(read.totals.linearSolves, info.totals.linearSolves);
  EXPECT_EQ(read.totals.cuts, info.totals.cuts);
  EXPECT_EQ(read.totals.statusIterations, info.totals.statusIterations);
  EXPECT_EQ(read.totals.thresholdIterations, info.totals.thresholdIterations);
  EXPECT_EQ(read.totals.geometryIterations, info.totals.geometryIterations);
  EXPECT_EQ(read.totals.cycling, info.totals.cycling);
  // Bitwise: the same doubles, not close ones.
  auto expected = a.x->getData(0), got = b.x->getData(0);
  ASSERT_EQ(expected.size(), got.size());
  for (std::size_t i = 0; i < static_cast<std::size_t>(got.size()); ++i)
    EXPECT_EQ(got[i], expected[i]) << "unknown " << i;
  const ElementStates restored = b.problem->gatherElementStates();
  EXPECT_EQ(restored.offsets, states.offsets);
  EXPECT_EQ(restored.values, states.values);
  const ContactHistory h = b.contact->convergedHistory(*b.x);
  EXPECT_EQ(h.node, history.node);
  EXPECT_EQ(h.unknowns, history.unknowns);
  EXPECT_EQ(h.resistance, history.resistance);
  EXPECT_EQ(h.slip, history.slip);
  EXPECT_EQ(h.facet, history.facet);
  EXPECT_EQ(h.frame, history.frame);
  EXPECT_TRUE(h.everInContact);

  // The layout doc/scenes.md documents: ids and displacement rows, one row per node.
  const Hdf5Reader file(path);
  EXPECT_EQ(file.stringAttribute("format"), "contactlab checkpoint 1");
  EXPECT_EQ(file.integers("nodes/id").size(), a.sm.model.mesh->numNodes());
  EXPECT_EQ(file.doubles("nodes/displacement").size(), 2 * a.sm.model.mesh->numNodes());
  EXPECT_EQ(file.integers("elements/id").size(), a.sm.model.mesh->numElements());
  EXPECT_EQ(file.doubles("contact/slip").size(), 3 * history.node.size());
  EXPECT_EQ(file.doubles("contact/frame").size(), 3 * history.node.size());
  std::filesystem::remove(path);
}

TEST(RunCheckpoint, AMissingFileIsInputError) {
  Model m;
  EXPECT_THROW(restoreCheckpoint(scratch("none.h5"), *m.problem, m.contact.get(), *m.x),
               InputError);
  EXPECT_THROW(readCheckpointInfo(scratch("none.h5")), InputError);
}

}  // namespace
}  // namespace contactlab
