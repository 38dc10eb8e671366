#include "formulations/ContactProblem.hpp"

#include "base/Elapsed.hpp"
#include "base/InputError.hpp"
#include "core/contact/SurfaceFrames.hpp"
#include "core/contact/TributaryAreas.hpp"
#include "core/problem/LinearConstraints.hpp"
#include "formulations/ContactAssembler.hpp"
#include "formulations/ContactDiscretizationType.hpp"
#include "formulations/ContactPoint.hpp"
#include "formulations/ContactPointFields.hpp"
#include "formulations/ContactPointKernel.hpp"
#include "formulations/ContactSurfaceState.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>

namespace contactlab {

ContactProblem::ContactProblem(Problem& solid, std::vector<ContactZone> zones)
    : solid_(solid), zones_(std::move(zones)), dim_(solid.dim()) {
  const Mesh& mesh = *solid_.model().mesh;
  const DofMap& dofs = solid_.dofs();
  const int rank = dofs.comm()->getRank();
  const GO displacementDofs = dofs.numGlobalDofs();
  ownedDisplacements_ = static_cast<LO>(dofs.ownedMap()->getNodeNumElements());

  // An axisymmetric model's surfaces are rings: areas, mortar integrals and so the contact
  // forces carry 2 pi r, and a multiplier or penalty traction stays a pressure.
  if (solid_.model().axisymmetric)
    for (ContactZone& zone : zones_)
      zone.areaWeight = [](const double* x) { return 2.0 * M_PI * x[0]; };
  std::vector<GO> ownedMultipliers;
  // The solid leaves its symmetry reduction to this problem, which reduces the monolithic system.
  solid_.deferConstraintReduction();
  for (std::size_t z = 0; z < zones_.size(); ++z) {
    const ContactZone& zone = zones_[z];
    if (!zone.law) throw InputError("Contact/" + zone.name + ": no formulation");
    discretizations_.push_back(makeContactDiscretization(zone, mesh, dim_));
    std::map<std::int64_t, std::array<double, 3>> slaveNormals;
    if (zone.law->hasNormalField()) {
      const std::string refusal = contactDiscretizationType(zone.discretization).refusal(*zone.law);
      if (!refusal.empty()) throw InputError("Contact/" + zone.name + ": " + refusal);
      std::vector<std::int64_t> facetNodes;
      for (const CellGroup* g : mesh.findBoundaries(zone.slave))
        facetNodes.insert(facetNodes.end(), g->nodes.begin(), g->nodes.end());
      slaveNormals = nodalNormals(facetsOf(mesh, zone.slave), facetNodes);
    }
    // No Friction Group: nodes whose friction the user removed (code_aster's SANS_GROUP_NO_FR).
    std::vector<std::int64_t> noFriction, noContact;
    if (!zone.noFrictionGroup.empty()) noFriction = mesh.boundaryNodes(zone.noFrictionGroup);
    // No Contact Group: nodes the user left out of the zone (code_aster's SANS_GROUP_NO).
    if (!zone.noContactGroup.empty()) noContact = mesh.boundaryNodes(zone.noContactGroup);
    // Tributary areas by HRZ lumping in the reference configuration.
    const auto weights =
        tributaryAreas(mesh, zone.slave, dim_, referencePositions(mesh), zone.areaWeight);
    for (std::int64_t node : mesh.boundaryNodes(zone.slave)) {
      if (dofs.globalNode(node) < 0) continue;
      const bool frictionless = std::binary_search(noFriction.begin(), noFriction.end(), node);
      const int nt = zone.friction > 0 && !frictionless ? dim_ - 1 : 0;
      const int multipliers = zone.law->pointUnknowns(nt, dim_);
      ContactPoint pt;
      pt.zone = static_cast<int>(z);
      pt.node = node;
      pt.nt = nt;
      pt.unknowns = multipliers;
      pt.excluded = std::binary_search(noContact.begin(), noContact.end(), node);
      // A normal field is tied to the pairing's normal, and to this one before any pairing:
      // the slave's own, turned towards it (as mortar's).
      if (zone.law->hasNormalField()) {
        const auto it = slaveNormals.find(node);
        if (it != slaveNormals.end())
          for (int c = 0; c < 3; ++c)
            pt.normal[c] = -it->second[c];
      }
      const auto w = weights.find(node);
      pt.weight = pt.referenceWeight = w == weights.end() ? 0.0 : w->second;
      if (multipliers > 0) {
        pt.multiplier = displacementDofs + numMultipliers_;
        if (dofs.nodeOwner(node) == rank)
          for (int k = 0; k < multipliers; ++k)
            ownedMultipliers.push_back(pt.multiplier + k);
        numMultipliers_ += multipliers;
      }
      points_.push_back(std::move(pt));
    }
  }

  std::vector<GO> owned(dofs.ownedMap()->getNodeElementList().begin(),
                        dofs.ownedMap()->getNodeElementList().end());
  owned.insert(owned.end(), ownedMultipliers.begin(), ownedMultipliers.end());
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  map_ = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(owned), 0, dofs.comm()));
  std::set<std::int64_t> surfaceNodes;
  for (const ContactPoint& pt : points_)
    surfaceNodes.insert(pt.node);
  for (const auto& discretization : discretizations_) {
    const auto masters = discretization->masterNodes();
    surfaceNodes.insert(masters.begin(), masters.end());
  }
  state_ =
      std::make_unique<ContactSurfaceState>(mesh, dofs, map_, ownedDisplacements_, surfaceNodes,
                                            numMultipliers_, solid_.constrainedDofs());
  // The Dirichlet-constrained dofs of the surface nodes (the whole mesh is on every rank).
  for (const DirichletCondition& bc : solid_.model().dirichlet)
    for (std::int64_t node : mesh.boundaryNodes(bc.group))
      if (surfaceNodes.count(node) && dofs.globalNode(node) >= 0)
        for (int c : bc.components)
          constrainedSurfaceDofs_.insert(dofs.globalNode(node) * dim_ + c);
  kernel_ = std::make_unique<ContactPointKernel>(dim_, zones_, discretizations_, *state_);
  bool inclinedSurface = false;  // a surface node on an inclined symmetry plane
  for (std::int64_t node : solid_.constraints().nodes())
    inclinedSurface = inclinedSurface || surfaceNodes.count(node) > 0;
  kernel_->setSurfaceConstrained(!constrainedSurfaceDofs_.empty() || inclinedSurface);
  // A tie's dependent dof on a surface moves its row and column to its partners: the contact
  // graph follows them.
  ContactAssembler::PartnerDofs partners;
  if (!solid_.constraints().tiedNodes().empty())
    partners = [this](GO gid) { return solid_.constraints().partnerDofs(gid); };
  assembler_ =
      std::make_unique<ContactAssembler>(map_, ownedDisplacements_, *state_, std::move(partners));
}

ContactProblem::~ContactProblem() = default;

std::size_t ContactProblem::numPoints() const {
  return points_.size();
}

const Teuchos::RCP<Matrix>& ContactProblem::tangent() const {
  return assembler_->matrix();
}

namespace {
// The status fixed point is on the contact status (open or closed) only; stick and slip stay in
// the friction law's generalized Newton (as Code_Aster's contact fixed point).
int contactStatusOnly(ContactStatus s) {
  return s == ContactStatus::Free ? 0 : kForcedClosed;
}
}  // namespace

void ContactProblem::freezeStatuses(bool frozen) {
  for (ContactPoint& pt : points_)
    pt.frozenStatus = frozen ? contactStatusOnly(pt.result.status) : -1;
}

void ContactProblem::freezeThresholds(bool frozen) {
  for (ContactPoint& pt : points_)
    pt.frozenThreshold = frozen ? std::max(pt.threshold, 0.0) : -1.0;
}

void ContactProblem::evaluateAll(const Vector& x, double t) {
  state_->import(x);
  std::vector<double> re, ke;
  for (ContactPoint& pt : points_)
    kernel_->evaluate(pt, t, false, re, ke);
}

std::vector<StatusChange> ContactProblem::statusUpdate(const Vector& x, double t) {
  std::vector<int> frozen(points_.size());
  for (std::size_t i = 0; i < points_.size(); ++i) {
    frozen[i] = points_[i].frozenStatus;
    points_[i].frozenStatus = -1;
  }
  evaluateAll(x, t);
  std::vector<StatusChange> changes;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    ContactPoint& pt = points_[i];
    const int law = contactStatusOnly(pt.result.status);
    pt.frozenStatus = frozen[i];
    if (law != frozen[i]) changes.push_back({i, law, std::abs(pt.indicator), pt.forcedStatus >= 0});
  }
  return changes;
}

void ContactProblem::applyStatuses(const std::vector<StatusChange>& changes) {
  for (const StatusChange& change : changes)
    points_.at(change.point).frozenStatus = change.status;
}

double ContactProblem::updateThresholds(const Vector& x, double t) {
  std::vector<double> old(points_.size());
  for (std::size_t i = 0; i < points_.size(); ++i) {
    old[i] = points_[i].frozenThreshold;
    points_[i].frozenThreshold = -1.0;
  }
  evaluateAll(x, t);
  double change = 0, largest = 0;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    ContactPoint& pt = points_[i];
    // A negative threshold (mu p^ of a point closed in tension) freezes at zero: a negative
    // frozen threshold would mean "not frozen", its friction following the iterate.
    pt.frozenThreshold = std::max(pt.threshold, 0.0);
    change = std::max(change, std::abs(pt.frozenThreshold - std::max(old[i], 0.0)));
    largest = std::max(largest, pt.threshold);
  }
  return largest > 0 ? change / largest : 0.0;
}

std::vector<ContactPointState> ContactProblem::pointStates() const {
  std::vector<ContactPointState> states(points_.size());
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const ContactPoint& pt = points_[i];
    ContactPointState& s = states[i];
    const bool open = pt.indicator < 0;
    s.zone = !pt.paired ? 0 : open ? (pt.result.gap > 0 ? 1 : 2) : (pt.result.gap <= 0 ? 3 : 4);
    s.status = static_cast<int>(pt.result.status);
    s.gap = pt.result.gap;
    s.length = pt.length(dim_);
    s.traction = pt.result.traction;
    s.contactIndicator = pt.paired ? pt.indicator : -1.0;
    s.frictionIndicator = pt.frictionIndicator;
  }
  return states;
}

void ContactProblem::forceStatus(std::size_t point, int status) {
  ContactPoint& pt = points_.at(point);
  pt.forcedStatus = status;
  // A point held closed keeps the friction threshold it has now: with the threshold following
  // a pressure that changes sign, its friction would switch on and off and cycle in turn.
  if (status == kForcedClosed) pt.forcedThreshold = std::max(pt.threshold, 0.0);
}

void ContactProblem::computeLocalStiffness() {
  // Mean diagonal stiffness of the slave node's dofs over its tributary area: E/h up to a
  // constant of the element. Rows live on their owners; the sum over ranks gives every rank
  // the same values (treatment decisions are replicated).
  const auto& K = solid_.tangent();
  const DofMap& dofs = solid_.dofs();
  std::vector<double> local(points_.size(), 0.0), global(points_.size(), 0.0);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const ContactPoint& pt = points_[i];
    for (int c = 0; c < dim_; ++c) {
      const GO dof = pt.dofs[c];
      const LO row = K->getRowMap()->getLocalElement(dof);
      if (row == Teuchos::OrdinalTraits<LO>::invalid()) continue;
      typename Matrix::local_inds_host_view_type cols;
      typename Matrix::values_host_view_type values;
      K->getLocalRowView(row, cols, values);
      for (std::size_t j = 0; j < cols.extent(0); ++j)
        if (K->getColMap()->getGlobalElement(cols(j)) == dof)
          local[i] += std::abs(values(j)) / (dim_ * pt.weight);
    }
  }
  Teuchos::reduceAll(*dofs.comm(), Teuchos::REDUCE_SUM, static_cast<int>(local.size()),
                     local.data(), global.data());
  localStiffness_ = std::move(global);
}

bool ContactProblem::scaleCoefficients(std::size_t point, double factor) {
  // The coefficient stays within [1e-2, 1e2] times the local stiffness E/h: below, the status
  // is decided by the multiplier alone; above, the system is as ill-conditioned as a stiff
  // penalty.
  if (localStiffness_.size() != points_.size()) computeLocalStiffness();
  ContactPoint& pt = points_.at(point);
  const double nominal = zones_[pt.zone].law->normalCoefficient();
  const double lo = 1e-2 * localStiffness_[point], hi = 1e2 * localStiffness_[point];
  const double wanted = std::clamp(nominal * pt.coefficientScale * factor, lo, hi);
  const double scale = wanted / nominal;
  if (std::abs(scale - pt.coefficientScale) <= 1e-12 * pt.coefficientScale) return false;
  pt.coefficientScale = scale;
  return true;
}

bool ContactProblem::scalingChangesForces(std::size_t point) const {
  return zones_[points_.at(point).zone].law->coefficientsEnterForces();
}

void ContactProblem::seedInitialStatuses(Vector& x, double t) {
  const bool any = std::any_of(zones_.begin(), zones_.end(), [](const ContactZone& z) {
    return z.initialContact != InitialContact::interpenetrated;
  });
  const bool field = std::any_of(zones_.begin(), zones_.end(),
                                 [](const ContactZone& z) { return z.law->hasNormalField(); });
  if (!any && !field) return;
  if (!frozenOnce_) updateGeometry(x, t);
  auto values = x.getDataNonConst(0);
  // Normal fields start at their pairing's normals (zero would close every point: g = 0).
  for (const ContactPoint& pt : points_) {
    if (!hasNormalField(pt)) continue;
    const GO first = pt.multiplier + pt.unknowns - dim_;
    for (int c = 0; c < dim_; ++c) {
      const LO lid = map_->getLocalElement(first + c);
      if (lid != Teuchos::OrdinalTraits<LO>::invalid()) values[lid] = pt.normal[c];
    }
  }
  if (!any) return;
  values = Teuchos::null;
  evaluateAll(x, t);  // the gaps at x
  values = x.getDataNonConst(0);
  for (const ContactPoint& pt : points_) {
    const InitialContact initial = zones_[pt.zone].initialContact;
    if (initial == InitialContact::interpenetrated || pt.multiplier < 0 || !pt.paired) continue;
    const LO lid = map_->getLocalElement(pt.multiplier);
    if (lid == Teuchos::OrdinalTraits<LO>::invalid()) continue;
    // The laws with multipliers close a point when p - c g >= 0: put p just inside the asked
    // status. The margin only picks the cone Newton starts in; the first iterate's pressure
    // comes from equilibrium. Below the touching threshold (ContactLaw.hpp), it carries no
    // friction.
    const double c = zones_[pt.zone].law->normalCoefficient() * pt.coefficientScale;
    const double length = pt.length(dim_);
    const double margin = 0.1 * kTouchingGap * c * length;
    values[lid] = c * pt.result.gap + (initial == InitialContact::all ? margin : -margin);
  }
}

void ContactProblem::releaseTreatments() {
  for (ContactPoint& pt : points_) {
    pt.forcedStatus = -1;
    pt.forcedThreshold = -1.0;
    pt.coefficientScale = 1.0;
    pt.cycling = 0;
    pt.result.cycling = 0;
  }
}

void ContactProblem::releaseForcedStatuses() {
  for (ContactPoint& pt : points_) {
    pt.forcedStatus = -1;
    pt.forcedThreshold = -1.0;
  }
}

void ContactProblem::setFrictionScale(double scale) {
  kernel_->setFrictionScale(scale);
}

bool ContactProblem::stepSolidAlone(Vector& x, double t, GO minimumDofs, const SolidSolve& solve) {
  if (solid_.dofs().numGlobalDofs() < minimumDofs) return false;
  // The inclined planes' elimination is applied to the monolithic system (deferred in the
  // solid): the solid's tangent alone is not reduced.
  if (!solid_.constraints().empty()) return false;
  // Every rank evaluates every point: the answer agrees. A closed point at zero pressure (the
  // touching point of an undeformed state) carries nothing yet.
  for (const ContactPoint& pt : points_)
    if (pt.result.pressure != 0 || pt.result.traction != std::array<double, 3>{}) return false;
  auto u = displacement(x);
  auto rhs = solid_.createVector();
  solid_.assemble(*u, t, rhs.get(), true);
  if (!solid_.assemblyFailure().code.empty()) return false;
  rhs->scale(-1.0);
  auto du = solid_.createVector();
  if (!solve(solid_.tangent(), *rhs, *du, dim_)) return false;
  auto src = du->getData(0);
  auto dst = x.getDataNonConst(0);
  for (LO i = 0; i < ownedDisplacements_; ++i)
    dst[i] += src[i];
  return true;
}

bool ContactProblem::fullTermsAddToPairing() const {
  for (const auto& d : discretizations_)
    if (d->fullTermsAddToPairing()) return true;
  return false;
}

void ContactProblem::setGeometricTerms(GeometricTerms terms) {
  if (terms != geometricTerms_) layoutChanged_ = true;  // columns change at the next pairing
  geometricTerms_ = terms;
}

void ContactProblem::markCycling(std::size_t point, int kind) {
  points_.at(point).cycling = kind;
  points_.at(point).result.cycling = kind;
}

Teuchos::RCP<Vector> ContactProblem::createVector() const {
  return Teuchos::rcp(new Vector(map_));
}

Teuchos::RCP<Vector> ContactProblem::displacement(const Vector& x) const {
  auto u = solid_.createVector();
  auto src = x.getData(0);
  auto dst = u->getDataNonConst(0);
  for (LO i = 0; i < ownedDisplacements_; ++i)
    dst[i] = src[i];
  return u;
}

void ContactProblem::applyDirichlet(double t, Vector& x) const {
  auto u = displacement(x);
  solid_.applyDirichlet(t, *u);
  auto src = u->getData(0);
  auto dst = x.getDataNonConst(0);
  for (LO i = 0; i < ownedDisplacements_; ++i)
    dst[i] = src[i];
}

bool ContactProblem::takePatternChanged() {
  return assembler_->takePatternChanged();
}

void ContactProblem::assemble(const Vector& x, double t, Vector* residual, bool withTangent) {
  if (assembler_->matrix().is_null()) updateGeometry(x, t);
  if (withTangent && graphStale_) {
    PhaseTimer timer(&seconds_.pairing);  // the pairing's graph, built when a tangent needs it
    assembler_->buildGraph(*solid_.tangent(), points_);
    graphStale_ = false;
  }
  if (!geometryFailure_.empty()) {
    // The NaN stops every Newton variant; assemblyFailure() says why.
    if (residual) residual->putScalar(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  auto u = displacement(x);
  Teuchos::RCP<Vector> ru = residual ? solid_.createVector() : Teuchos::null;
  {
    PhaseTimer timer(&seconds_.solid);
    solid_.assemble(*u, t, ru.get(), withTangent);
  }
  PhaseTimer contactTimer(&seconds_.contact);  // the rest of this function
  state_->import(x);
  assembler_->begin(residual, ru.get(), withTangent ? solid_.tangent().get() : nullptr);
  // The contact forces on the solid's dofs, for the reactions: at a support's node contact
  // pushes on the support, not on the body.
  Teuchos::RCP<Vector> contactForces = residual ? solid_.createVector() : Teuchos::null;
  assembler_->collectContactForces(contactForces.get());
  std::vector<double> re, ke;
  statusChanges_ = 0;
  double constraint2 = 0;
  for (ContactPoint& pt : points_) {
    // Closed without friction (a threshold at round-off: the surfaces just touching) and stick
    // are two branches of the law: a point that leaves the first for the second has had no
    // friction in the solve that moved it. Counted as a change, Newton solves once more: else a
    // first iterate from zero pressure, whose solve slid the surface freely, passed as a
    // converged stick state (code_aster SSNV128 with lagrange: one iteration, stick points
    // 10 um slipped under no friction, the stick rows' residual w c_t v far below the target).
    const int before = outputStatus(pt.result);
    kernel_->evaluate(pt, t, withTangent, re, ke);
    if (outputStatus(pt.result) != before) ++statusChanges_;
    constraint2 += pt.constraintResidual * pt.constraintResidual;
    const bool geometric = withTangent && geometricTerms_ != GeometricTerms::none && pt.paired &&
                           discretizations_[pt.zone]->linearizesGeometry();
    const bool field = withTangent && !geometric && pt.paired && hasNormalField(pt);
    if (geometric) kernel_->geometricColumns(pt, t, geometricTerms_, ke);
    if (field) kernel_->normalFieldColumns(pt, t, ke);
    assembler_->add(pt, re, ke, geometric || field);
  }
  assembler_->end();
  constraintResidual_ = std::sqrt(constraint2);  // every rank evaluates every point
  if (contactForces) solid_.addToReactions(*contactForces);
  solid_.constraints().reduce(withTangent ? assembler_->matrix().get() : nullptr, residual);
}

AssemblyFailure ContactProblem::assemblyFailure() const {
  if (!geometryFailure_.empty())
    return {"contact-geometry-failed", "the contact geometry of this iterate: " + geometryFailure_};
  return solid_.assemblyFailure();
}

void ContactProblem::completeIncrement(Vector& dx) const {
  solid_.constraints().project(dx.getDataNonConst(0).getRawPtr());
}

double ContactProblem::largestDisplacement(const Vector& dx) const {
  return solid_.largestDisplacement(*displacement(dx));
}

void ContactProblem::commitState(const Vector& x, double t) {
  state_->import(x);
  std::vector<double> re, ke;
  for (ContactPoint& pt : points_) {
    kernel_->evaluate(pt, t, false, re, ke);
    for (int c = 0; c < 3; ++c) {
      pt.resistanceOld[c] = -pt.result.traction[c];
      pt.slipTotal[c] += pt.slipIncrement[c];
    }
    pt.result.slip = pt.slipTotal;
    pt.slipIncrement = {0, 0, 0};
    if (pt.result.status != ContactStatus::Free) everInContact_ = true;
  }
  recovered_ = recoveredFields(*solid_.model().mesh, zones_, lawResults());
  convergedPairing_ = points_;
  state_->commit();
  kernel_->setConvergedTime(t);
  solid_.commitState(*displacement(x), t);
}

void ContactProblem::setInertia(const InertiaTerm& inertia) {
  InertiaTerm solidTerm = inertia;
  if (inertia.reference) solidTerm.reference = displacement(*inertia.reference);
  solid_.setInertia(solidTerm);
}

std::vector<std::int64_t> ContactProblem::prescribedSlipNodes(std::size_t zone) const {
  return pointNodes(zone, [](const ContactPoint& pt) { return pt.prescribedSlip > 0; });
}

std::vector<std::int64_t> ContactProblem::prescribedGapNodes(std::size_t zone) const {
  return pointNodes(zone, [](const ContactPoint& pt) { return pt.gapPrescribed; });
}

std::vector<std::int64_t> ContactProblem::pointNodes(
    std::size_t zone, const std::function<bool(const ContactPoint&)>& which) const {
  // Points are evaluated on their owners: the union over the ranks.
  std::vector<int> local(points_.size(), 0), global(points_.size(), 0);
  for (std::size_t i = 0; i < points_.size(); ++i)
    local[i] = points_[i].zone == static_cast<int>(zone) && which(points_[i]);
  Teuchos::reduceAll(*solid_.dofs().comm(), Teuchos::REDUCE_MAX, static_cast<int>(local.size()),
                     local.data(), global.data());
  std::vector<std::int64_t> nodes;
  for (std::size_t i = 0; i < points_.size(); ++i)
    if (global[i]) nodes.push_back(points_[i].node);
  return nodes;
}

bool ContactProblem::hasNormalField(const ContactPoint& pt) const {
  return zones_[pt.zone].law->hasNormalField() && pt.multiplier >= 0;
}

std::vector<ContactPointResult> ContactProblem::lawResults() const {
  std::vector<ContactPointResult> out;
  out.reserve(points_.size());
  for (const ContactPoint& pt : points_)
    out.push_back(pt.result);
  return out;
}

double ContactProblem::outputPressure(std::size_t i) const {
  const bool recovered = i < recovered_.pressure.size() && !std::isnan(recovered_.pressure[i]);
  return recovered ? recovered_.pressure[i] : points_[i].result.pressure;
}

std::vector<ContactPointResult> ContactProblem::results() const {
  std::vector<ContactPointResult> out = lawResults();
  const auto values = state_->values();
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i].pressure = outputPressure(i);
    if (i < recovered_.traction.size() && !std::isnan(recovered_.traction[i][0]))
      out[i].traction = recovered_.traction[i];
    const ContactPoint& pt = points_[i];
    if (pt.multiplier < 0) continue;
    const auto names = zones_[pt.zone].law->pointUnknownNames(pt.nt, dim_);
    for (int k = 0; k < pt.unknowns && k < static_cast<int>(names.size()); ++k)
      out[i].unknowns.emplace_back(names[k], values[state_->multiplierPosition(pt.multiplier + k)]);
  }
  return out;
}

ContactResultants ContactProblem::resultants() const {
  std::vector<double> output(points_.size());
  for (std::size_t i = 0; i < output.size(); ++i)
    output[i] = outputPressure(i);
  return contactResultants(lawResults(), output);
}

bool ContactProblem::tangentSymmetric(bool geometricTerms) const {
  const int nt = dim_ - 1;
  for (std::size_t z = 0; z < zones_.size(); ++z) {
    if (!zones_[z].law->symmetricJacobian(zones_[z].friction > 0 ? nt : 0)) return false;
    if (geometricTerms && discretizations_[z]->linearizesGeometry()) return false;
  }
  return true;
}

void ContactProblem::addPointData(MeshPiece& piece) const {
  addContactPointData(solid_.dofs().overlapNodes(), results(), piece);
}

}  // namespace contactlab
