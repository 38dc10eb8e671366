#include "formulations/ContactPointKernel.hpp"

#include "formulations/PrescribedSlip.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace contactlab {
namespace {

double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

}  // namespace

ContactPointKernel::ContactPointKernel(int dim, const std::vector<ContactZone>& zones,
                                       const Discretizations& discretizations,
                                       ContactSurfaceState& state)
    : dim_(dim), zones_(zones), discretizations_(discretizations), state_(state) {}

void ContactPointKernel::evaluate(ContactPoint& pt, double t, bool withTangent,
                                  std::vector<double>& re, std::vector<double>& ke) const {
  const ContactZone& zone = zones_[pt.zone];
  const ContactDiscretization& discretization = *discretizations_[pt.zone];
  const ContactLaw& law = *zone.law;
  const int nt = pt.nt, nk = 1 + nt, n = law.size(nt);
  const int nu = pt.displacementDofs(dim_);
  const int nd = static_cast<int>(pt.dofs.size());
  const int nl = nu + (n - nk);  // the dofs the law's variables cover: displacements, multipliers
  auto s = state_.values();
  // The gap's normal: the pairing's, or the normal-field formulation's unknown n_s (the point's
  // last dim unknowns, after the law's multipliers).
  const bool field = law.hasNormalField() && pt.multiplier >= 0;
  std::array<double, 3> gapNormal = pt.normal;
  if (field)
    for (int c = 0; c < dim_; ++c)
      gapNormal[c] = s[state_.multiplierPosition(pt.multiplier) + (n - nk) + c];

  // Operators B_i (i = 0: gap, 1..nt: slip components) on the displacement dofs.
  std::vector<double> B(static_cast<std::size_t>(nk) * nu, 0.0);
  const std::array<double, 3>* dirs[3] = {&gapNormal, &pt.t1, &pt.t2};
  LawInput in;
  in.weight = pt.weight;
  in.mu = zone.friction * frictionScale_;
  in.nt = nt;
  const auto xs = state_.position(pt.node);
  std::array<double, 3> rel{}, slip{};  // x_s - x_m, and the slip increment
  if (pt.paired) {
    const auto us = state_.displacement(pt.node, false);
    const auto usc = state_.displacement(pt.node, true);
    for (int c = 0; c < 3; ++c) {
      rel[c] = pt.self * xs[c];
      slip[c] = pt.self * (us[c] - usc[c]);
    }
    discretization.subtractMasterSide(pt, state_, t, tConverged_, rel, slip);
    for (int i = 0; i < nk; ++i) {
      const auto& d = *dirs[i];
      for (int c = 0; c < dim_; ++c) {
        B[i * nu + c] = pt.self * d[c];
        for (std::size_t a = 0; a < pt.master.size(); ++a)
          B[i * nu + (1 + a) * dim_ + c] = -pt.N[a] * d[c];
      }
    }
    in.gap = dot(gapNormal, rel);
    for (int k = 0; k < nt; ++k)
      in.slip[k] = dot(*dirs[1 + k], slip);
  } else {
    in.gap = discretization.searchDistance();  // apart: no master within reach
  }
  if (pt.multiplier >= 0) {
    const int m = state_.multiplierPosition(pt.multiplier);
    in.p = s[m];
    for (int k = 0; k < nt; ++k)
      in.Lambda[k] = s[m + 1 + k];
  }
  for (int k = 0; k < nt; ++k)
    in.tangentialOld[k] = dot(*dirs[1 + k], pt.resistanceOld);
  in.frozenStatus = pt.forcedStatus >= 0 ? pt.forcedStatus : pt.frozenStatus;
  // Without a master point there is nothing to be closed on, whatever the multiplier says.
  if (!pt.paired) in.frozenStatus = 0;
  in.frozenThreshold = pt.forcedThreshold >= 0 ? pt.forcedThreshold : pt.frozenThreshold;
  in.coefficientScale = pt.coefficientScale;
  in.stiffnessScale = zone.stiffnessScale;
  // A point the user left out, or whose gap the supports fix, is open (PrescribedSlip.hpp).
  pt.gapPrescribed = pt.paired && surfaceConstrained_ && !pt.excluded &&
                     prescribedGap(B, nu, pt.freeDofs, pt.removedDirections);
  if (pt.excluded || pt.gapPrescribed) in.frozenStatus = 0;
  PrescribedSlip prescribed;
  if (pt.paired && pt.multiplier >= 0 && nt > 0 && surfaceConstrained_ && !pt.excluded &&
      !pt.gapPrescribed) {
    std::vector<std::array<double, 2>> symmetric;
    for (const auto& normal : pt.symmetryNormals)
      symmetric.push_back({dot(normal, pt.t1), nt > 1 ? dot(normal, pt.t2) : 0.0});
    prescribed = prescribedSlip(B, nt, nu, pt.freeDofs, pt.removedDirections, symmetric);
  }
  LawOutput out;
  law.evaluate(in, out);
  // A closed point the supports slide along a prescribed direction slips (PrescribedSlip.hpp):
  // the law's slip branch, whatever the stick test says of a slip shorter than 1 / c_t.
  if (prescribedDirectionSlides(prescribed, nt, in.slip, std::sqrt(dot(slip, slip)))) {
    if (out.status == ContactStatus::Stick) {
      in.frozenStatus = 2;
      law.evaluate(in, out);
    }
    prescribed.prescribed = 0;
  }
  pt.prescribedSlip = prescribed.prescribed;
  dropPrescribedFriction(prescribed, nt, pt.weight, in.Lambda, n, out);
  pt.threshold = out.threshold;
  // The multiplier rows as forces (LawOutput::normalRowForce), after any friction direction
  // was dropped (its row then holds its multiplier at 0): the rotation keeps the rows' norm.
  double constraint2 = 0;
  if (law.hasMultipliers()) {
    constraint2 = std::pow(out.r[1 + nt] * out.normalRowForce, 2);
    for (int k = 0; k < nt; ++k)
      constraint2 += std::pow(out.r[2 + nt + k] * out.frictionRowForce, 2);
  }
  pt.constraintResidual = std::sqrt(constraint2);
  pt.indicator = out.indicator;
  pt.frictionIndicator = out.frictionIndicator;

  ContactPointResult& r = pt.result;
  r.zone = pt.zone;
  r.node = pt.node;
  r.x = xs;
  r.weight = pt.weight;
  r.paired = pt.paired;
  r.gap = in.gap;
  // An open point transmits nothing: its multiplier's last bits (1e-75 with lagrange) are not
  // a pressure.
  r.pressure = out.status == ContactStatus::Free ? 0.0 : out.pressure;
  r.normal = pt.normal;
  r.status = out.status;
  r.frictional = pt.nt > 0 && !out.frictionlessClosed;
  r.cycling = pt.cycling;
  r.traction = {0, 0, 0};
  pt.slipIncrement = {0, 0, 0};
  for (int k = 0; k < nt; ++k)
    for (int c = 0; c < 3; ++c) {
      if (out.status != ContactStatus::Free)
        r.traction[c] += out.tangentialTraction[k] * (*dirs[1 + k])[c];
      pt.slipIncrement[c] += in.slip[k] * (*dirs[1 + k])[c];
    }
  for (int c = 0; c < 3; ++c)
    r.slip[c] = pt.slipTotal[c] + pt.slipIncrement[c];

  // Element residual and tangent on (displacement dofs, multipliers).
  re.assign(nd, 0.0);
  for (int d = 0; d < nu; ++d)
    for (int i = 0; i < nk; ++i)
      re[d] += out.r[i] * B[i * nu + d];
  for (int j = nu; j < nl; ++j)
    re[j] = out.r[nk + (j - nu)];
  // The normal field's kinematic rows w kappa_n (n_s - n(u)).
  const double fieldStiffness = field ? pt.weight * law.normalFieldPenalty(pt.length(dim_)) : 0.0;
  if (field) {
    const auto target = discretization.currentNormal(pt, state_, t);
    for (int c = 0; c < dim_; ++c)
      re[nl + c] = fieldStiffness * (gapNormal[c] - target[c]);
  }
  if (!withTangent) return;
  ke.assign(static_cast<std::size_t>(nd) * nd, 0.0);
  auto J = [&](int i, int j) { return out.J[i * n + j]; };
  // Law variable index of element dof column/row j >= nu: nk + (j - nu).
  for (int a = 0; a < nl; ++a) {
    for (int b = 0; b < nl; ++b) {
      double v = 0;
      if (a < nu && b < nu) {
        for (int i = 0; i < nk; ++i) {
          if (B[i * nu + a] == 0.0) continue;
          for (int j = 0; j < nk; ++j)
            v += B[i * nu + a] * J(i, j) * B[j * nu + b];
        }
      } else if (a < nu) {
        for (int i = 0; i < nk; ++i)
          v += B[i * nu + a] * J(i, nk + (b - nu));
      } else if (b < nu) {
        for (int j = 0; j < nk; ++j)
          v += J(nk + (a - nu), j) * B[j * nu + b];
      } else {
        v = J(nk + (a - nu), nk + (b - nu));
      }
      ke[static_cast<std::size_t>(a) * nd + b] = v;
    }
  }
  if (!field) return;
  // The n_s columns: the gap is n_s . rel, and the gap row's operator B_0 = n_s . (self, -N_a)
  // carries n_s too; the slips use the pairing's tangents, free of n_s. Then the kinematic
  // rows' own block w kappa_n I (their u columns: normalFieldColumns).
  for (int a = 0; a < nl; ++a)
    for (int c = 0; c < dim_; ++c) {
      double v = 0;
      if (a < nu) {
        for (int i = 0; i < nk; ++i)
          v += B[i * nu + a] * J(i, 0) * rel[c];
        if (pt.paired && a % dim_ == c) v += out.r[0] * (a < dim_ ? pt.self : -pt.N[a / dim_ - 1]);
      } else {
        v = J(nk + (a - nu), 0) * rel[c];
      }
      ke[static_cast<std::size_t>(a) * nd + nl + c] = v;
    }
  for (int c = 0; c < dim_; ++c)
    ke[static_cast<std::size_t>(nl + c) * nd + nl + c] = fieldStiffness;
}

int ContactPointKernel::widenToGeometryColumns(const ContactPoint& pt,
                                               std::vector<double>& ke) const {
  const int nd = static_cast<int>(pt.dofs.size()), ng = static_cast<int>(pt.geometryDofs.size());
  const int nc = nd + ng;
  std::vector<double> full(static_cast<std::size_t>(nd) * nc, 0.0);
  for (int i = 0; i < nd; ++i)
    for (int j = 0; j < nd; ++j)
      full[static_cast<std::size_t>(i) * nc + j] = ke[static_cast<std::size_t>(i) * nd + j];
  ke.swap(full);
  return nc;
}

int ContactPointKernel::columnPosition(const ContactPoint& pt, int column) const {
  const int nd = static_cast<int>(pt.dofs.size());
  return column < nd ? pt.surfacePos[column] : pt.geometrySurfacePos[column - nd];
}

void ContactPointKernel::differenceColumns(const ContactPoint& pt, int firstRow, double scale,
                                           const std::function<void(std::vector<double>&)>& rowsAt,
                                           std::vector<double>& ke) const {
  const int nd = static_cast<int>(pt.dofs.size()), nu = pt.displacementDofs(dim_);
  const int nc = widenToGeometryColumns(pt, ke);
  const double length = pt.length(dim_);
  auto s = state_.mutableValues();
  std::vector<double> plus, minus;
  for (int j = 0; j < nc; ++j) {
    if (j >= nu && j < nd) continue;  // the point's unknowns: their columns stay exact
    const int pos = columnPosition(pt, j);
    const double saved = s[pos];
    // The step grows with the displacement it perturbs, and the quotient takes the step the
    // doubles actually made: 1e-7 of a 5 mm facet on a node an iterate threw 6.7e5 mm (a
    // frozen-open body under load control) was rounded to 4 digits and the residual's own
    // round-off there is 1e-4 of the difference, so the tangent was 1e-4 off and generalized
    // Newton's next iterate landed 67 mm off the obstacle, open again (code_aster SSNV503).
    const double h = 1e-7 * std::max(length, std::abs(saved));
    const double up = saved + h, down = saved - h;
    s[pos] = up;
    rowsAt(plus);
    s[pos] = down;
    rowsAt(minus);
    s[pos] = saved;
    for (std::size_t i = 0; i < plus.size(); ++i)
      ke[static_cast<std::size_t>(firstRow + static_cast<int>(i)) * nc + j] =
          scale * (plus[i] - minus[i]) / (up - down);
  }
}

bool ContactPointKernel::closedFormNormalColumns(
    const ContactPoint& pt, int firstRow, double scale,
    const std::map<std::int64_t, std::array<double, 9>>& blocks, std::vector<double>& ke) const {
  const int nd = static_cast<int>(pt.dofs.size()), nu = pt.displacementDofs(dim_);
  const int nc = nd + static_cast<int>(pt.geometryDofs.size());
  // Every (node, component) the normal depends on must be a column of the point.
  std::vector<std::pair<int, double>> entries;  // (row i * nc + column, value)
  for (const auto& [node, block] : blocks)
    for (int c = 0; c < dim_; ++c) {
      const int pos = state_.dofPosition(node, c);
      int column = -1;
      for (int j = 0; j < nc && column < 0; ++j)
        if ((j < nu || j >= nd) && columnPosition(pt, j) == pos) column = j;
      if (column < 0) return false;
      for (int i = 0; i < dim_; ++i)
        entries.emplace_back((firstRow + i) * nc + column, scale * block[i * 3 + c]);
    }
  widenToGeometryColumns(pt, ke);
  for (int i = 0; i < dim_; ++i)
    for (int j = 0; j < nc; ++j)
      if (j < nu || j >= nd) ke[static_cast<std::size_t>(firstRow + i) * nc + j] = 0.0;
  for (const auto& [at, value] : entries)
    ke[static_cast<std::size_t>(at)] += value;
  return true;
}

void ContactPointKernel::normalFieldColumns(const ContactPoint& pt, double t,
                                            std::vector<double>& ke) const {
  const ContactDiscretization& discretization = *discretizations_[pt.zone];
  const double stiffness = pt.weight * zones_[pt.zone].law->normalFieldPenalty(pt.length(dim_));
  const int firstRow = static_cast<int>(pt.dofs.size()) - dim_;
  std::map<std::int64_t, std::array<double, 9>> blocks;
  if (discretization.currentNormalDerivative(pt, state_, t, blocks) &&
      closedFormNormalColumns(pt, firstRow, -stiffness, blocks, ke))
    return;
  differenceColumns(
      pt, firstRow, -stiffness,
      [&](std::vector<double>& rows) {
        const auto n = discretization.currentNormal(pt, state_, t);
        rows.assign(n.begin(), n.begin() + dim_);
      },
      ke);
}

void ContactPointKernel::geometricColumns(const ContactPoint& pt, double t, GeometricTerms terms,
                                          std::vector<double>& ke) const {
  // Every displacement column is a central difference of the residual with the geometry
  // recomputed. The status piece is kept (the generalized Jacobian of that piece, as the
  // frozen-geometry tangent).
  const ContactDiscretization& discretization = *discretizations_[pt.zone];
  std::vector<double> unused;
  differenceColumns(
      pt, 0, 1.0,
      [&](std::vector<double>& rows) {
        ContactPoint copy = pt;
        copy.forcedStatus = static_cast<int>(pt.result.status);
        discretization.refreshGeometry(copy, state_, t, terms);
        evaluate(copy, t, false, rows, unused);
      },
      ke);
}

}  // namespace contactlab
