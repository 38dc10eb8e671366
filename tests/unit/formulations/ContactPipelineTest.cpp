// The contact pipeline's stages alone, on known answers: tributary areas (HRZ lumping),
// pairing by each discretization on flat surfaces a known gap apart, the point kernel's element
// tangent against finite differences of its residual, and the assembler's insertion.
#include "core/contact/SurfaceFrames.hpp"
#include "core/contact/TributaryAreas.hpp"
#include "core/materials/LinearElastic.hpp"
#include "core/mesh/MeshGenerators.hpp"
#include "core/problem/Problem.hpp"
#include "formulations/ContactAssembler.hpp"
#include "formulations/ContactDiscretizationType.hpp"
#include "formulations/ContactPointKernel.hpp"
#include "formulations/ContactSurfaceState.hpp"
#include "formulations/FormulationRegistry.hpp"
#include "formulations/MasterSurface.hpp"

#include <Tpetra_Core.hpp>

#include <cmath>
#include <gtest/gtest.h>
#include <set>

namespace contactlab {
namespace {

TEST(TributaryAreas, LinearSegmentsGiveHalvesAndQuadraticOnesTheHrzShares) {
  RectangleParams r;
  r.lengths = {3.0, 1.0};
  r.divisions = {3, 1};
  const Mesh linear = generateRectangle(r);
  const auto w = tributaryAreas(linear, "bottom", 2, referencePositions(linear));
  ASSERT_EQ(w.size(), 4u);
  std::multiset<double> values;
  for (const auto& [node, value] : w)
    values.insert(std::round(value * 1e12) / 1e12);
  EXPECT_EQ(values, (std::multiset<double>{0.5, 0.5, 1.0, 1.0}));

  // line3 of length 1: int N^2 is 2/15 at the ends and 8/15 in the middle, so the ends carry
  // 1/6 and the middle 2/3 (the row sums would give 1/6 and 2/3 too; tri6 is where they part).
  r.elementType = "quad8";
  r.lengths = {1.0, 1.0};
  r.divisions = {1, 1};
  const Mesh quadratic = generateRectangle(r);
  const auto wq = tributaryAreas(quadratic, "bottom", 2, referencePositions(quadratic));
  ASSERT_EQ(wq.size(), 3u);
  double sum = 0;
  for (const auto& [node, value] : wq) {
    const double x = quadratic.coords[3 * node];
    EXPECT_NEAR(value, std::abs(x - 0.5) < 1e-12 ? 2.0 / 3.0 : 1.0 / 6.0, 1e-12) << "x " << x;
    sum += value;
  }
  EXPECT_NEAR(sum, 1.0, 1e-12);

  // In a current configuration: the bottom stretched twice doubles every share.
  const auto stretched = [reference = referencePositions(linear)](std::int64_t n) {
    auto x = reference(n);
    x[0] *= 2;
    return x;
  };
  const auto w2 = tributaryAreas(linear, "bottom", 2, stretched);
  for (const auto& [node, value] : w2)
    EXPECT_NEAR(value, 2 * w.at(node), 1e-12);
}

// Two stacked unit blocks (lower 2 x 1 quad4, upper 3 x 1) `gap` apart; the upper block's
// bottom is the slave. The state holds both contact surfaces and no multipliers.
struct StackedSurfaces {
  explicit StackedSurfaces(double gap) : comm(Tpetra::getDefaultComm()) {
    StackedBlocks2DParams b;
    b.lowerDivisions = {2, 1};
    b.upperDivisions = {3, 1};
    b.gap = gap;
    mesh = std::make_shared<Mesh>(generateStackedBlocks2D(b));
    SolidModel model;
    model.mesh = mesh;
    for (const auto& name : mesh->blockNames())
      model.materials[name] = std::make_shared<LinearElastic>(1000.0, 0.0);
    DirichletCondition bottom;
    bottom.name = "bottom";
    bottom.group = "lower-bottom";
    bottom.components = {0, 1};
    model.dirichlet.push_back(bottom);
    solid = std::make_unique<Problem>(model, comm);
    zone.name = "interface";
    zone.slave = "upper-bottom";
    zone.master = "lower-top";
    std::set<std::int64_t> nodes;
    for (const char* g : {"upper-bottom", "lower-top", "lower-bottom"})
      for (std::int64_t n : mesh->boundaryNodes(g))
        nodes.insert(n);
    const auto& dofs = solid->dofs();
    state = std::make_unique<ContactSurfaceState>(
        *mesh, dofs, dofs.ownedMap(), static_cast<LO>(dofs.ownedMap()->getNodeNumElements()), nodes,
        0, solid->constrainedDofs());
    u = solid->createVector();
  }
  // Moves the upper block rigidly by d and imports that state.
  void moveUpper(std::array<double, 2> d) {
    const auto& dofs = solid->dofs();
    auto values = u->getDataNonConst(0);
    for (std::int64_t n : mesh->boundaryNodes("upper-bottom")) {
      for (int c = 0; c < 2; ++c) {
        const LO lid = dofs.ownedMap()->getLocalElement(dofs.globalNode(n) * 2 + c);
        if (lid != Teuchos::OrdinalTraits<LO>::invalid()) values[lid] = d[c];
      }
    }
    values = Teuchos::null;
    state->import(*u);
  }
  std::vector<ContactPoint> slavePoints() const {
    const auto weights = tributaryAreas(*mesh, zone.slave, 2, referencePositions(*mesh));
    std::vector<ContactPoint> points;
    for (std::int64_t n : mesh->boundaryNodes(zone.slave)) {
      ContactPoint pt;
      pt.node = n;
      pt.weight = pt.referenceWeight = weights.at(n);
      points.push_back(pt);
    }
    return points;
  }

  Teuchos::RCP<const Comm> comm;
  std::shared_ptr<Mesh> mesh;
  std::unique_ptr<Problem> solid;
  ContactZone zone;
  std::unique_ptr<ContactSurfaceState> state;
  Teuchos::RCP<Vector> u;
};

TEST(ContactDiscretization, NodeToSegmentPairsEachSlaveNodeAboveItsMasterPoint) {
  StackedSurfaces s(0.1);
  s.moveUpper({0.01, -0.15});  // 0.05 into the lower block, 0.01 past its end (2 % of a facet)
  auto d = makeContactDiscretization(s.zone, *s.mesh, 2);
  d->prepare(*s.state, 1.0);
  for (ContactPoint pt : s.slavePoints()) {
    const auto xs = s.state->position(pt.node);
    const PointPairing p = d->pair(pt, xs, *s.state, 1.0);
    ASSERT_TRUE(pt.paired) << "node " << pt.node;
    EXPECT_NEAR(p.gap, -0.05, 1e-12);
    EXPECT_NEAR(pt.normal[1], 1.0, 1e-12);  // from the master towards the slave
    // The master point is under the slave (the shape values interpolate its x), clamped to the
    // master surface's end for the slave node moved past it (within 5 % of the facet).
    const auto xm = d->masterPoint(pt, xs, *s.state);
    EXPECT_NEAR(xm[0], std::min(xs[0], 1.0), 1e-12);
    EXPECT_NEAR(xm[1], 1.0, 1e-12);
    EXPECT_EQ(pt.master.size(), 2u);
  }
}

// A slave node beyond the free end of the master surface faces no master (NAFEMS CGS-4 with the
// longer incline as slave: its nodes past the block's ends were closed against the block bottom's
// extension, their forces applied at its corners 0.5 away, and Newton converged linearly). Moved
// 0.05 past the end (10 % of the facet), on the master's line or below it, it is not paired.
TEST(ContactDiscretization, NodeToSegmentLeavesASlaveNodeBeyondTheMastersFreeEndUnpaired) {
  for (double down : {0.1, 0.15}) {  // on the master's line; 0.05 below it
    StackedSurfaces s(0.1);
    s.moveUpper({0.05, -down});
    auto d = makeContactDiscretization(s.zone, *s.mesh, 2);
    d->prepare(*s.state, 1.0);
    int paired = 0;
    for (ContactPoint pt : s.slavePoints()) {
      const auto xs = s.state->position(pt.node);
      d->pair(pt, xs, *s.state, 1.0);
      EXPECT_EQ(pt.paired, xs[0] <= 1.0) << "slave node at x = " << xs[0] << ", down " << down;
      paired += pt.paired;
    }
    EXPECT_EQ(paired, 3);  // x = 0.05, 0.383, 0.717
  }
}

// The free boundary of a master surface: its ends in 2D, the edges of its outline in 3D; the
// vertex or edge two facets share is a kink, not a boundary.
TEST(MasterSurface, FreeBoundaryIsTheOutlineNotTheKinks) {
  RectangleParams r;
  r.lengths = {2.0, 1.0};
  r.divisions = {2, 1};
  const MasterSurface line(generateRectangle(r), "top");  // two line2 facets
  int ends = 0, kinks = 0;
  for (int f = 0; f < 2; ++f) {
    for (double xi : {-1.0, 1.0}) {
      const double at[2] = {xi, 0.0};
      (line.onFreeBoundary(f, at) ? ends : kinks) += 1;
    }
    const double middle[2] = {0.3, 0.0};
    EXPECT_FALSE(line.onFreeBoundary(f, middle));
  }
  EXPECT_EQ(ends, 2);   // the surface's two ends
  EXPECT_EQ(kinks, 2);  // the shared vertex, seen from each facet

  BoxParams b;
  b.divisions = {2, 2, 1};
  const MasterSurface top(generateBox(b), "zmax");  // 2 x 2 quad4 facets
  int outline = 0, shared = 0;
  for (int f = 0; f < 4; ++f) {
    for (const std::array<double, 2> xi :
         {std::array<double, 2>{0.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}}) {
      (top.onFreeBoundary(f, xi.data()) ? outline : shared) += 1;
    }
    const double centre[2] = {0.0, 0.0};
    EXPECT_FALSE(top.onFreeBoundary(f, centre));
  }
  EXPECT_EQ(outline, 8);  // each facet has two edges on the outline and two shared
  EXPECT_EQ(shared, 8);
}

TEST(ContactDiscretization, MortarGapIsTheDistanceAndTheWeightsCoverTheInterface) {
  StackedSurfaces s(0.1);
  s.zone.discretization = "mortar";
  s.state->import(*s.u);
  auto d = makeContactDiscretization(s.zone, *s.mesh, 2);
  d->prepare(*s.state, 1.0);
  double covered = 0;
  for (ContactPoint pt : s.slavePoints()) {
    const PointPairing p = d->pair(pt, s.state->position(pt.node), *s.state, 1.0);
    ASSERT_TRUE(pt.paired) << "node " << pt.node;
    EXPECT_NEAR(p.gap, 0.1, 1e-12);
    double sum = pt.self;  // the gap's coefficients sum to 0 (a rigid motion opens nothing)
    for (std::size_t a = 0; a < pt.master.size(); ++a)
      sum -= pt.N[a];
    EXPECT_NEAR(sum, 0.0, 1e-12);
    covered += pt.weight;
  }
  EXPECT_NEAR(covered, 1.0, 1e-12);
}

TEST(ContactDiscretization, ObstacleGapAndMasterSideFollowItsTranslation) {
  StackedSurfaces s(0.0);
  s.state->import(*s.u);
  RigidObstacleSpec plane;
  plane.direction = {0, 1, 0};
  plane.displacement = {0.3, -0.5, 0};
  s.zone.master.clear();
  s.zone.obstacle = plane;
  s.zone.searchDistance = 5;
  auto d = makeContactDiscretization(s.zone, *s.mesh, 2);
  const RigidObstacle obstacle(plane, 2);
  const double t = 0.5;
  for (ContactPoint pt : s.slavePoints()) {
    const auto xs = s.state->position(pt.node);
    const PointPairing p = d->pair(pt, xs, *s.state, t);
    ASSERT_TRUE(pt.paired);
    EXPECT_NEAR(p.gap, 1.0 - obstacle.translation(t)[1], 1e-12);
    std::array<double, 3> rel = xs, slip{};
    d->subtractMasterSide(pt, *s.state, t, 0.0, rel, slip);
    EXPECT_NEAR(rel[1], p.gap, 1e-12);
    EXPECT_NEAR(slip[0], -obstacle.translation(t)[0], 1e-12);  // the obstacle moved under it
  }
}

// The slave points paired by node-to-segment with their element dofs laid out as ContactProblem
// does (no multipliers: penalty).
std::vector<ContactPoint> pairedPoints(StackedSurfaces& s, ContactDiscretization& d) {
  d.prepare(*s.state, 1.0);
  std::vector<ContactPoint> points = s.slavePoints();
  for (ContactPoint& pt : points) {
    d.pair(pt, s.state->position(pt.node), *s.state, 1.0);
    tangentBasis(2, pt.normal, pt.t1, pt.t2);
    for (std::int64_t n : std::vector<std::int64_t>{pt.node})
      for (int c = 0; c < 2; ++c) {
        pt.dofs.push_back(s.solid->dofs().globalNode(n) * 2 + c);
        pt.surfacePos.push_back(s.state->dofPosition(n, c));
      }
    for (std::int64_t n : pt.master)
      for (int c = 0; c < 2; ++c) {
        pt.dofs.push_back(s.solid->dofs().globalNode(n) * 2 + c);
        pt.surfacePos.push_back(s.state->dofPosition(n, c));
      }
    pt.freeDofs.assign(pt.dofs.size(), 1);
  }
  return points;
}

std::shared_ptr<const ContactLaw> penalty() {
  registerFormulations();
  Teuchos::ParameterList p = *formulationRegistry().get("penalty").validParameters();
  p.set("Normal Penalty", 1e4);
  p.set("Tangential Penalty", 1e3);
  return formulationRegistry().get("penalty").build(p);
}

TEST(ContactPointKernel, ElementTangentIsTheDerivativeOfItsResidual) {
  StackedSurfaces s(0.1);
  s.zone.law = penalty();
  s.zone.friction = 0.3;
  s.moveUpper({0.0, -0.12});  // closed
  std::vector<ContactZone> zones{s.zone};
  ContactPointKernel::Discretizations ds;
  ds.push_back(makeContactDiscretization(s.zone, *s.mesh, 2));
  std::vector<ContactPoint> points = pairedPoints(s, *ds[0]);
  s.state->commit();           // slip increments from this state
  s.moveUpper({1e-3, -0.12});  // and a little slip
  const ContactPointKernel kernel(2, zones, ds, *s.state);
  for (ContactPoint& pt : points) {
    pt.nt = 1;
    std::vector<double> re, ke, rp, rm, unused;
    kernel.evaluate(pt, 1.0, true, re, ke);
    ASSERT_NE(pt.result.status, ContactStatus::Free);
    const int nd = static_cast<int>(pt.dofs.size());
    const double h = 1e-7;
    auto values = s.state->mutableValues();
    for (int j = 0; j < nd; ++j) {
      const double saved = values[pt.surfacePos[j]];
      values[pt.surfacePos[j]] = saved + h;
      ContactPoint plus = pt, minus = pt;
      kernel.evaluate(plus, 1.0, false, rp, unused);
      values[pt.surfacePos[j]] = saved - h;
      kernel.evaluate(minus, 1.0, false, rm, unused);
      values[pt.surfacePos[j]] = saved;
      for (int i = 0; i < nd; ++i)
        EXPECT_NEAR(ke[i * nd + j], (rp[i] - rm[i]) / (2 * h), 1e-5 * 1e4)
            << "node " << pt.node << " entry " << i << "," << j;
    }
  }
}

TEST(ContactAssembler, InsertsThePointTermsOnFreeRowsAndColumnsOnly) {
  StackedSurfaces s(0.0);
  s.solid->assemble(*s.u, 0.0, nullptr, true);
  auto d = makeContactDiscretization(s.zone, *s.mesh, 2);
  s.state->import(*s.u);
  std::vector<ContactPoint> points = pairedPoints(s, *d);
  ContactAssembler assembler(s.solid->dofs().ownedMap(),
                             static_cast<LO>(s.solid->dofs().ownedMap()->getNodeNumElements()),
                             *s.state);
  assembler.buildGraph(*s.solid->tangent(), points);
  EXPECT_TRUE(assembler.takePatternChanged());
  EXPECT_FALSE(assembler.takePatternChanged());
  auto ru = s.solid->createVector();
  ru->putScalar(2.0);
  auto residual = s.solid->createVector();
  assembler.begin(residual.get(), ru.get(), s.solid->tangent().get());
  const ContactPoint& pt = points.front();
  const int nd = static_cast<int>(pt.dofs.size());
  std::vector<double> re(nd, 1.0), ke(static_cast<std::size_t>(nd) * nd, 0.5);
  assembler.add(pt, re, ke, false);
  assembler.end();
  // The slave's y row: the solid's residual plus the point's; its coupling to the master node
  // (absent from the solid's graph) is the point's value.
  const auto& map = *s.solid->dofs().ownedMap();
  const LO row = map.getLocalElement(pt.dofs[1]);
  ASSERT_NE(row, Teuchos::OrdinalTraits<LO>::invalid());
  EXPECT_DOUBLE_EQ(residual->getData(0)[row], 3.0);
  const Matrix& A = *assembler.matrix();
  typename Matrix::local_inds_host_view_type cols;
  typename Matrix::values_host_view_type values;
  A.getLocalRowView(row, cols, values);
  const LO masterCol = A.getColMap()->getLocalElement(pt.dofs[2]);
  bool found = false;
  for (std::size_t j = 0; j < cols.extent(0); ++j)
    if (cols(j) == masterCol) {
      found = true;
      EXPECT_DOUBLE_EQ(values(j), 0.5);
    }
  EXPECT_TRUE(found);
  // The graph again from the same pairing: the same matrix (and the solver keeps its
  // analysis); from another (the last point dropped), a new one whose couplings say so.
  const Matrix* before = assembler.matrix().get();
  assembler.buildGraph(*s.solid->tangent(), points);
  EXPECT_EQ(assembler.matrix().get(), before);
  EXPECT_FALSE(assembler.takePatternChanged());
  const std::size_t entries = before->getGlobalNumEntries();
  points.pop_back();
  assembler.buildGraph(*s.solid->tangent(), points);
  EXPECT_NE(assembler.matrix().get(), before);
  EXPECT_TRUE(assembler.takePatternChanged());
  EXPECT_LT(assembler.matrix()->getGlobalNumEntries(), entries);
  // Every solid entry has its place: the solid's tangent alone, assembled, is the solid's.
  assembler.begin(nullptr, nullptr, s.solid->tangent().get());
  assembler.end();
  const Matrix& K = *s.solid->tangent();
  const Matrix& B = *assembler.matrix();
  for (LO r = 0; r < static_cast<LO>(K.getNodeNumRows()); ++r) {
    typename Matrix::local_inds_host_view_type kCols, bCols;
    typename Matrix::values_host_view_type kValues, bValues;
    K.getLocalRowView(r, kCols, kValues);
    B.getLocalRowView(r, bCols, bValues);
    double kSum = 0, bSum = 0;
    for (std::size_t j = 0; j < kValues.extent(0); ++j)
      kSum +=
          std::abs(kValues(j)) * static_cast<double>(K.getColMap()->getGlobalElement(kCols(j)) + 1);
    for (std::size_t j = 0; j < bValues.extent(0); ++j)
      bSum +=
          std::abs(bValues(j)) * static_cast<double>(B.getColMap()->getGlobalElement(bCols(j)) + 1);
    EXPECT_DOUBLE_EQ(bSum, kSum) << "row " << r;
  }
}

}  // namespace
}  // namespace contactlab
