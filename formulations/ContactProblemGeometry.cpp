// ContactProblem's geometry: pairing every point at a state and freezing it (updateGeometry),
// and laying out each point's dofs for the assembly. A failure of the geometry on an iterate is
// a failed iterate (contact-geometry-failed), not the end of the run.
#include "base/Elapsed.hpp"
#include "base/InputError.hpp"
#include "core/contact/SurfaceFrames.hpp"
#include "core/problem/LinearConstraints.hpp"
#include "formulations/ContactAssembler.hpp"
#include "formulations/ContactDiscretization.hpp"
#include "formulations/ContactPoint.hpp"
#include "formulations/ContactProblem.hpp"
#include "formulations/ContactSurfaceState.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace contactlab {
namespace {

// " (and n more)" after the first of n + 1 named points; nothing when n = 0.
std::string andMore(std::size_t n) {
  return n > 0 ? " (and " + std::to_string(n) + " more)" : std::string();
}

}  // namespace

bool ContactProblem::updateGeometry(const Vector& x, double t) {
  geometryFailure_.clear();
  // At the reference state an error is the model's (a degenerate facet, a deep penetration).
  if (!frozenOnce_) return pairAndFreeze(x, t);
  // On a Newton iterate (generalized Newton re-pairs every iterate) or a geometry update it is
  // the iterate's: a surface so distorted that the mortar integrals do not exist on it (a dual
  // basis function without positive integral, a projection that does not converge). That is a
  // failed iterate, which the step's cut recovers from, not the end of the run. Every rank
  // pairs the whole surface from the same imported state, so they fail alike; the reduction
  // keeps them agreeing.
  std::string failure;
  bool moved = false;
  try {
    moved = pairAndFreeze(x, t);
  } catch (const std::exception& e) {  // the mortar discretization words them as InputError
    failure = e.what();
  }
  const int local = failure.empty() ? 0 : 1;
  int global = 0;
  Teuchos::reduceAll(*map_->getComm(), Teuchos::REDUCE_MAX, local, Teuchos::outArg(global));
  if (global == 0) return moved;
  geometryFailure_ = failure.empty() ? "the contact geometry failed on another rank" : failure;
  layoutChanged_ = true;  // points half re-paired: lay out and rebuild on the next success
  return true;
}

bool ContactProblem::pairAndFreeze(const Vector& x, double t) {
  PhaseTimer timer(&seconds_.pairing);
  state_->import(x);
  bool moved = false, repaired = false;
  std::vector<std::string> deep;
  for (std::size_t z = 0; z < zones_.size(); ++z) {
    ContactDiscretization& discretization = *discretizations_[z];
    discretization.prepare(*state_, t);
    for (ContactPoint& pt : points_) {
      if (pt.zone != static_cast<int>(z)) continue;
      const auto xs = state_->position(pt.node);
      const ContactPoint old = pt;
      const PointPairing pairing = discretization.pair(pt, xs, *state_, t);
      if (!pt.paired) {
        pt.master.clear();
        pt.N.clear();
      }
      tangentBasisFollowing(dim_, pt.normal, pt.t1, pt.t2);
      if (!frozenOnce_ && pt.paired && pairing.gap < -pairing.size)
        deep.push_back(slaveNodeName(pt) + " is " + std::to_string(-pairing.gap) +
                       " inside its master, more than the facet size " +
                       std::to_string(pairing.size));
      // Repaired: other master nodes (a new graph). Moved: a different normal or master point
      // at this state (Newton must run again); the same point reached through another facet
      // of a shared vertex is not a move.
      if (old.paired != pt.paired) {
        moved = repaired = true;
      } else if (pt.paired) {
        if (old.facet != pt.facet) repaired = true;
        double change = 0;
        for (int c = 0; c < 3; ++c)
          change = std::max(change, std::abs(old.normal[c] - pt.normal[c]));
        const auto before = discretization.masterPoint(old, xs, *state_);
        const auto after = discretization.masterPoint(pt, xs, *state_);
        for (int c = 0; c < 3; ++c)
          change =
              std::max(change, std::abs(before[c] - after[c]) / std::max(pairing.size, 1e-300));
        if (change > 1e-12) moved = true;
      }
    }
  }
  if (!deep.empty())
    throw InputError("initial penetration larger than an element: " + deep.front() +
                     andMore(deep.size() - 1) +
                     ". Check the geometry, the master/slave choice or the obstacle's position "
                     "and normal");
  if (!frozenOnce_) convergedPairing_ = points_;
  frozenOnce_ = true;
  layOutPointDofs();
  // Only a new pairing changes the couplings (and the direct solver's symbolic analysis); the
  // graph waits for the next tangent (a line search's trial points need residuals only).
  if (assembler_->matrix().is_null()) {
    assembler_->buildGraph(*solid_.tangent(), points_);
    graphStale_ = false;
  } else if (repaired || layoutChanged_) {
    assembler_->layOutRows(points_);
    graphStale_ = true;
  }
  layoutChanged_ = false;
  return moved;
}

std::string ContactProblem::slaveNodeName(const ContactPoint& pt) const {
  return "node " + std::to_string(solid_.model().mesh->nodeId(pt.node)) + " of '" +
         zones_[pt.zone].slave + "' (zone " + zones_[pt.zone].name + ")";
}

std::string ContactProblem::passedThrough(const Vector& x) {
  // Every rank pairs every point from the same imported state, so the ranks agree, also on
  // skipping the import where no point lost its pairing (most steps).
  bool unpaired = false;
  for (std::size_t i = 0; i < points_.size() && i < convergedPairing_.size(); ++i)
    unpaired = unpaired || (convergedPairing_[i].paired && !points_[i].paired);
  if (!unpaired) return {};
  state_->import(x);
  std::size_t count = 0;
  std::string first;
  for (std::size_t i = 0; i < points_.size() && i < convergedPairing_.size(); ++i) {
    const ContactPoint& now = points_[i];
    const ContactPoint& then = convergedPairing_[i];
    const ContactDiscretization& discretization = *discretizations_[now.zone];
    if (!then.paired || now.paired) continue;
    // The converged pairing's master point where the master is now, and its normal then: a
    // node-to-segment point's gap, a mortar point's weighted gap (its coefficients sum to 0,
    // so a rigid motion leaves it). An obstacle unpairs only the points in front of it.
    const auto xs = state_->position(now.node);
    const auto master = discretization.masterPoint(then, xs, *state_);
    double gap = 0;
    for (int c = 0; c < 3; ++c)
      gap += then.normal[c] * (xs[c] - master[c]);
    if (!(gap < -discretization.searchDistance())) continue;
    if (count++ == 0)
      first = slaveNodeName(now) + " is " + std::to_string(-gap) +
              " behind the master point it was paired with";
  }
  if (count == 0) return {};
  return "slave nodes passed through their master surface since the last converged step: " + first +
         andMore(count - 1) +
         ", beyond the search distance, so unpaired and free of contact: a body thrown through "
         "its obstacle by an iterate, not a solution";
}

void ContactProblem::addRemovedDirections(const std::vector<std::array<double, 3>>& normals,
                                          std::size_t first, ContactPoint& pt) const {
  // The planes' normals on the node's free components, orthonormalized (Gram-Schmidt), as
  // directions over the point's displacement dofs (the node's at `first`); a normal that the
  // Dirichlet components and the earlier normals already span adds nothing.
  std::vector<std::array<double, 3>> basis;
  for (std::array<double, 3> n : normals) {
    for (int c = 0; c < dim_; ++c)
      if (!pt.freeDofs[first + c]) n[c] = 0;
    for (const auto& b : basis) {
      const double d = n[0] * b[0] + n[1] * b[1] + n[2] * b[2];
      for (int c = 0; c < 3; ++c)
        n[c] -= d * b[c];
    }
    const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (norm < 1e-8) continue;
    for (double& v : n)
      v /= norm;
    basis.push_back(n);
  }
  for (const auto& b : basis) {
    pt.removedDirections.emplace_back();  // sized when the point's dofs are complete
    auto& direction = pt.removedDirections.back();
    direction.assign(first, 0.0);
    direction.insert(direction.end(), b.begin(), b.begin() + dim_);
  }
}

void ContactProblem::layOutPointDofs() {
  // Element dofs of each point: slave, master nodes, multipliers; with `full` geometric terms
  // also the nodes its normal depends on, as columns.
  const DofMap& dofs = solid_.dofs();
  for (ContactPoint& pt : points_) {
    pt.dofs.clear();
    pt.freeDofs.clear();
    pt.surfacePos.clear();
    pt.removedDirections.clear();
    auto addNode = [&](std::int64_t node) {
      const std::size_t first = pt.dofs.size();
      for (int c = 0; c < dim_; ++c) {
        pt.dofs.push_back(dofs.globalNode(node) * dim_ + c);
        pt.freeDofs.push_back(constrainedSurfaceDofs_.count(pt.dofs.back()) == 0);
        pt.surfacePos.push_back(state_->dofPosition(node, c));
      }
      addRemovedDirections(solid_.constraints().planeNormals(node), first, pt);
    };
    addNode(pt.node);
    pt.symmetryNormals = solid_.constraints().allPlaneNormals(pt.node);
    for (std::int64_t m : pt.master)
      addNode(m);
    for (auto& direction : pt.removedDirections)
      direction.resize(pt.dofs.size(), 0.0);
    for (int k = 0; k < pt.unknowns; ++k) {
      pt.dofs.push_back(pt.multiplier + k);
      pt.surfacePos.push_back(state_->multiplierPosition(pt.multiplier + k));
    }
    pt.geometryDofs.clear();
    pt.geometrySurfacePos.clear();
    // The nodes the normal depends on: for the full geometric terms, and for a normal field,
    // whose kinematic rows depend on them whatever the algorithm.
    if ((geometricTerms_ != GeometricTerms::full && !hasNormalField(pt)) || !pt.paired) continue;
    for (std::int64_t node : discretizations_[pt.zone]->normalNodes(pt)) {
      if (node == pt.node || std::find(pt.master.begin(), pt.master.end(), node) != pt.master.end())
        continue;
      for (int c = 0; c < dim_; ++c) {
        pt.geometryDofs.push_back(dofs.globalNode(node) * dim_ + c);
        pt.geometrySurfacePos.push_back(state_->dofPosition(node, c));
      }
    }
  }
}

}  // namespace contactlab
