#pragma once
// The assembly stage of the contact pipeline: the monolithic tangent's graph (the solid's plus
// each contact point's couplings, rebuilt after a new pairing only, and kept when it comes out
// the same, since the direct solver redoes its symbolic analysis on a new one), and the
// insertion of the solid's residual and tangent and of each point's element terms on the rows
// this rank owns. Dirichlet-constrained rows get no contact terms and constrained columns are
// zeroed (the solid's rows there are identity rows).
#include "base/LinearAlgebra.hpp"
#include "formulations/ContactPoint.hpp"
#include "formulations/ContactSurfaceState.hpp"

#include <functional>
#include <vector>

namespace contactlab {

class ContactAssembler {
 public:
  // The dofs a dependent dof's row and column move to (LinearConstraints::partnerDofs; empty for
  // any other dof).
  using PartnerDofs = std::function<std::vector<GO>(GO)>;

  // `map`: the monolithic map, its first `ownedDisplacements` entries the solid's owned dofs.
  ContactAssembler(Teuchos::RCP<const Map> map, LO ownedDisplacements,
                   const ContactSurfaceState& state, PartnerDofs partners = {});

  // Each point's local rows (what a residual needs), after a new pairing.
  void layOutRows(std::vector<ContactPoint>& points) const;
  // The graph of the solid's tangent plus every point's dofs x (dofs, geometryDofs), widened by
  // the partners of a dependent dof among them (their columns in the point's rows, the point's
  // columns in their rows: what the constraints' reduction moves there); sets each point's rows
  // and column indices. Only a tangent needs it: a residual-only evaluation at a new pairing (a
  // line search's trial point under generalized Newton) does without.
  void buildGraph(const Matrix& solidTangent, std::vector<ContactPoint>& points);
  const Teuchos::RCP<Matrix>& matrix() const { return matrix_; }
  // Whether the graph changed since the last call.
  bool takePatternChanged();

  // An assembly: begin() copies the solid's residual (null: none wanted) and tangent (null: no
  // tangent) in, add() inserts one point's terms (`geometric`: ke carries the geometryDofs'
  // columns too), end() completes the matrix.
  void begin(Vector* residual, const Vector* solidResidual, const Matrix* solidTangent);
  void add(const ContactPoint& pt, const std::vector<double>& re, const std::vector<double>& ke,
           bool geometric);
  // Until end(), also sums each point's force on the solid's owned dofs into `forces` (shaped
  // as the solid's vectors), constrained rows included: the supports' share of the reactions.
  void collectContactForces(Vector* forces);
  void end();

 private:
  Teuchos::RCP<const Map> map_;
  LO ownedDisplacements_;
  const ContactSurfaceState& state_;
  PartnerDofs partners_;
  Teuchos::RCP<Matrix> matrix_;
  std::vector<std::size_t> solidOffsets_;  // solid CRS entry -> our CRS entry
  bool patternChanged_ = true;
  // The assembly in progress.
  Teuchos::ArrayRCP<double> residual_, contactForces_;
  bool withTangent_ = false;
  std::vector<double> row_;
  std::vector<LO> columns_;
};

}  // namespace contactlab
