#pragma once
// The solid problem plus contact zones, as one system R(x, t) = 0 on Tpetra.
//
// Unknowns x = (u, m): the solid's displacements, then the multipliers of the formulations that
// have them (p and, with friction, Lambda at each slave point), one monolithic map whose owned
// part starts with the solid's owned dofs (same local indices), then the multipliers of the
// slave points whose node this rank owns.
//
// Discretization: node-to-segment collocation (the seed's). Each slave node is a contact point
// weighted by its tributary area (row-sum-free HRZ lumping of the slave facets in the
// reference configuration, positive for every facet type); its master is the closest point on
// the master surface (ContactSearch) or on a rigid obstacle. On a master surface the normal is
// the nodal-averaged normal interpolated at that point (continuous across the kinks of a
// faceted, deformed surface, as Code_Aster's normal smoothing). Between two updateGeometry calls
// the pairing, the master point's shape values N_a, the normal n and the tangent basis t_k are
// frozen, so the gap g = n . (x_s - sum_a N_a x_a) and the slip increment
// v_k = t_k . ((u_s - u_s^conv) - sum_a N_a (u_a - u_a^conv)) are linear in u and the tangent
// is exact for the frozen geometry. With geometric terms (geometry in Newton) the tangent adds
// the derivatives of the geometry: the point's displacement columns by central differences of
// its residual with its master point (`pairing`), and also its smoothed normal and tangents
// (`full`, then with the columns of the master nodes around its facet, on which the smoothed
// normal depends), recomputed (geometricColumns).
//
// Mortar (a zone's Discretization): each slave node j is a point with gap
// n_j . (sum_k D_jk x_k - sum_l M_jl x_l) / w_j, w_j = sum_k D_jk, n_j the slave's nodal normal
// (turned towards the slave), D and M integrated over the current slave facets around j
// (integrateMortar) at each updateGeometry; the slip likewise with the increments. The point's
// weight is w_j times its facets' reference-to-current area ratio, so that its multiplier is a
// pressure per reference area as node-to-segment's is. The laws are unchanged. Its
// geometry is a fixed point: no geometric terms (the segmentation's derivatives are not
// linearized), whatever Algorithm/Geometric Terms says.
//
// Parallel: contact surfaces are small. At every evaluation each rank imports the surface
// displacements and all multipliers (a replicated vector), evaluates every contact point (the
// same numbers on every rank, so pairings and statuses agree everywhere) and adds the rows it
// owns. The tangent's graph is the solid's plus the contact couplings and is rebuilt only when
// a pairing changes.
#include "core/contact/ContactSearch.hpp"
#include "core/contact/RigidObstacle.hpp"
#include "core/io/MeshPiece.hpp"
#include "core/problem/NonlinearSystem.hpp"
#include "core/problem/Problem.hpp"
#include "formulations/ContactControls.hpp"
#include "formulations/ContactZone.hpp"

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <unordered_set>
#include <vector>

namespace contactlab {

// One contact point at the last evaluation (every rank holds all of them).
struct ContactPointResult {
  int zone = 0;
  std::int64_t node = -1;            // slave mesh node
  std::array<double, 3> x{};         // current position
  double weight = 0;                 // tributary area
  bool paired = false;               // a master point was found within the search distance
  double gap = 0;                    // > 0 apart
  double pressure = 0;               // >= 0
  std::array<double, 3> traction{};  // tangential traction on the slave
  std::array<double, 3> normal{};
  std::array<double, 3> slip{};  // accumulated slip (sum of converged increments)
  ContactStatus status = ContactStatus::Free;
  // The point carries friction: mu > 0 and, if closed, a threshold above round-off
  // (LawOutput::frictionlessClosed); otherwise a closed point is written as closed without
  // friction, not as stick or slip.
  bool frictional = false;
  int cycling = 0;  // cycling kind detected in the step (CyclingKind), 0 none
};

// contact_status as written to contact.csv and the VTK output, one meaning everywhere: 0 free,
// 1 stick, 2 slip (frictional points), 3 closed without friction (no stick or slip to tell).
constexpr int kOutputClosedFrictionless = 3;
inline int outputStatus(const ContactPointResult& p) {
  if (p.status == ContactStatus::Free) return 0;
  return p.frictional ? static_cast<int>(p.status) : kOutputClosedFrictionless;
}

struct ContactResultants {
  std::array<double, 3> normalForce{};      // sum w p n (force on the slave surfaces)
  std::array<double, 3> tangentialForce{};  // sum w t
  double normalForceMagnitude = 0;          // sum w p
  double maxPressure = 0;
  double maxPenetration = 0;  // max(-gap) over closed points, >= 0
  int contact = 0, stick = 0, slip = 0, closedFrictionless = 0;
};

class ContactProblem : public NonlinearSystem, public ContactControls {
 public:
  // `solid` must outlive this. Throws InputError for a zone whose groups are missing.
  ContactProblem(Problem& solid, std::vector<ContactZone> zones);
  ~ContactProblem() override;

  Teuchos::RCP<Vector> createVector() const override;
  void applyDirichlet(double t, Vector& x) const override;
  void assemble(const Vector& x, double t, Vector* residual, bool withTangent) override;
  const Teuchos::RCP<Matrix>& tangent() const override { return matrix_; }
  AssemblyFailure assemblyFailure() const override { return solid_.assemblyFailure(); }
  bool takePatternChanged() override;
  // Re-pairs every slave point at x, t. The first call also checks the initial penetration
  // (InputError, on every rank, when a slave point is deeper than its master facet's size).
  bool updateGeometry(const Vector& x, double t) override;
  void commitState(const Vector& x, double t) override;

  // ContactControls: the seam for the algorithms (fixed points, cycling treatments).
  void freezeStatuses(bool frozen) override;
  void freezeThresholds(bool frozen) override;
  int updateStatuses(const Vector& x, double t) override;
  double updateThresholds(const Vector& x, double t) override;
  int statusChanges() const override { return statusChanges_; }
  std::vector<ContactPointState> pointStates() const override;
  void forceStatus(std::size_t point, int status) override;
  bool scaleCoefficients(std::size_t point, double factor) override;
  bool scalingChangesForces(std::size_t point) const override;
  void releaseTreatments() override;
  void releaseForcedStatuses() override;
  void seedInitialStatuses(Vector& x, double t) override;
  void markCycling(std::size_t point, int kind) override;
  void setGeometricTerms(GeometricTerms terms) override;
  void setFrictionScale(double scale) override { frictionScale_ = scale; }

  // The displacement part of x on the solid's owned map.
  Teuchos::RCP<Vector> displacement(const Vector& x) const;
  const Problem& solid() const { return solid_; }
  const std::vector<ContactZone>& zones() const { return zones_; }
  std::size_t numPoints() const;
  GO numMultipliers() const { return numMultipliers_; }
  // Results of the last assemble() (or commit).
  std::vector<ContactPointResult> results() const;
  // Slave nodes of a zone where, at the last evaluation, the Dirichlet conditions prescribed a
  // friction direction, whose multiplier was dropped (PrescribedSlip.hpp). Collective.
  std::vector<std::int64_t> prescribedSlipNodes(std::size_t zone) const;
  ContactResultants resultants() const;
  // Whether any point has been closed at a converged step (surfaces that never meet: false).
  bool everInContact() const { return everInContact_; }
  // Adds contact_pressure, tangential_traction, gap, slip, contact_status to a piece made by
  // solid().outputPiece (points in the solid's overlap-node order).
  void addPointData(MeshPiece& piece) const;
  // Wall time spent so far in pairing (updateGeometry) and in the contact terms (evaluation and
  // insertion of the contact points in assemble; the solid's assembly is not counted).
  double pairingSeconds() const { return pairingSeconds_; }
  double contactSeconds() const { return contactSeconds_; }

 private:
  struct Point;
  // A mortar contact point's row: sum_k D_jk x_k - sum_l M_jl x_l over the slave facets around
  // slave node j, and the slave's nodal normal there.
  struct MortarRow {
    std::map<std::int64_t, double> slave, master;
    std::array<double, 3> normal{};
    bool quadratic = false;  // on quadratic slave facets
  };
  // The mortar rows of zone z's slave nodes at the current positions (the slave facets against
  // the master facets `search` finds within the search distance).
  std::map<std::int64_t, MortarRow> mortarRows(std::size_t z, const ContactSearch& search) const;
  void buildSurfaceMaps();
  // HRZ-lumped tributary areas of zone z's slave nodes at the given positions.
  std::map<std::int64_t, double> tributaryAreas(
      std::size_t z, const std::function<std::array<double, 3>(std::int64_t)>& position) const;
  void computeWeights();
  void buildGraph();
  void importSurface(const Vector& x);
  void evaluateAll(const Vector& x, double t);
  void computeLocalStiffness();
  void evaluatePoint(Point& pt, double t, bool withTangent, std::vector<double>& re,
                     std::vector<double>& ke) const;
  // Geometric linearization: the point's geometry recomputed on its facet (or obstacle) from
  // the current surface positions, and the columns of its element matrix for its displacement
  // dofs and those its normal depends on, by central differences of its residual with the
  // geometry recomputed and its status piece kept.
  void refreshGeometry(Point& pt, double t) const;
  // Shared by updateGeometry and refreshGeometry: the obstacle's normal and point for a slave
  // at xs (returns its gap), the smoothed normal at the point's master point (fallback: the
  // facet's own), a master facet at the current positions, and the facets around the point's.
  double placeOnObstacle(Point& pt, const std::array<double, 3>& xs, double t) const;
  void setSmoothedNormal(Point& pt, const std::map<std::int64_t, std::array<double, 3>>& nodal,
                         const double* facetNormal) const;
  Facet currentFacet(int zone, int facet) const;
  std::vector<int> facetsAround(const Point& pt) const;
  void geometricColumns(const Point& pt, double t, std::vector<double>& ke) const;
  std::array<double, 3> surfacePosition(std::int64_t node) const;
  // The point the slave at xs is paired with: x_s - masterPosition = self x_s - sum_a N_a x_a
  // (node-to-segment: the master point; mortar: the weighted master side).
  std::array<double, 3> masterPosition(const Point& pt, const std::array<double, 3>& xs) const;
  std::array<double, 3> surfaceDisplacement(std::int64_t node, bool converged) const;

  Problem& solid_;
  // The output pressure of points on tri6 node-to-segment slaves (NaN elsewhere: the
  // law's), recovered from the nodal forces at each commit (SurfacePressure.hpp).
  void recoverPressures();
  double outputPressure(std::size_t point) const;
  std::vector<double> recoveredPressure_;
  std::vector<ContactZone> zones_;
  std::unordered_set<GO> constrainedSurfaceDofs_;            // Dirichlet dofs of the surface nodes
  std::vector<std::unique_ptr<RigidObstacle>> obstacles_;    // per zone (null: two bodies)
  std::vector<std::vector<std::int64_t>> masterFacetNodes_;  // per zone, flat
  std::vector<ElementType> masterFacetType_;
  std::vector<double> searchDistance_;  // per zone, resolved
  std::vector<Point> points_;
  int dim_;
  GO numMultipliers_ = 0;
  LO ownedDisplacements_ = 0;
  Teuchos::RCP<const Map> map_, surfaceMap_;
  Teuchos::RCP<Import> surfaceImporter_;
  Teuchos::RCP<Vector> surface_;          // replicated surface dofs then all multipliers
  std::vector<double> surfaceConverged_;  // surface dofs at the last converged step
  std::vector<char> surfaceConstrained_;
  std::vector<int> surfaceIndex_;  // mesh node -> surface node index (-1)
  std::size_t surfaceDofs_ = 0;
  double tConverged_ = 0;
  Teuchos::RCP<Matrix> matrix_;
  std::vector<std::size_t> solidOffsets_;  // solid CRS entry -> our CRS entry
  std::vector<int> signature_;             // master facet (or -2 obstacle, -1 none) per point
  bool patternChanged_ = true, frozenOnce_ = false, everInContact_ = false;
  double pairingSeconds_ = 0, contactSeconds_ = 0;
  int statusChanges_ = 0;
  std::vector<double> localStiffness_;  // per point: solid stiffness per area (~E/h), lazily
  GeometricTerms geometricTerms_ = GeometricTerms::none;
  double frictionScale_ = 1.0;
  bool layoutChanged_ = false;
  // Per zone with a master surface: the master facets around each master node.
  std::vector<std::map<std::int64_t, std::vector<int>>> nodeFacets_;
};

}  // namespace contactlab
