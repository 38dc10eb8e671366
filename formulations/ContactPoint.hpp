#pragma once
// One contact point (a slave node) as the contact stages share it: what pairing froze (master
// nodes and shape values, normal and tangents), its history, what the algorithms froze or
// forced, its last evaluation, and where its element dofs live. Plain data: the stages
// (ContactDiscretization pairs it, ContactPointKernel evaluates it, ContactAssembler inserts
// it) each fill their part.
#include "base/LinearAlgebra.hpp"
#include "formulations/ContactPointResult.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace contactlab {

struct ContactPoint {
  int zone = 0;
  std::int64_t node = -1;
  double weight = 0;           // of the contact conditions (mortar: sum_k D_jk, nominal)
  double referenceWeight = 0;  // tributary area in the reference configuration
  GO multiplier = -1;          // first GID of the point's unknowns (-1: none)
  int unknowns = 0;  // the formulation's unknowns at the point (ContactLaw::pointUnknowns)
  int nt = 0;        // friction directions (0: frictionless)
  // Frozen geometry. The gap is n . (self x_s - sum_a N_a x_a): node-to-segment has self = 1 and
  // `master` the master facet's nodes; mortar has self = D_jj / w_j and `master` the other slave
  // nodes (N = -D_jk / w_j) then the master nodes (N = M_jl / w_j).
  double self = 1.0;
  bool paired = false;
  int facet = -1;  // master facet (mortar: a hash of the coupled nodes)
  std::vector<std::int64_t> master;
  std::vector<double> N;      // their coefficients (node-to-segment: shape values)
  double xi[2] = {0.0, 0.0};  // the master point's local coordinates
  std::array<double, 3> normal{}, t1{}, t2{}, obstaclePoint{};  // obstacle: minus translation
  // History.
  std::array<double, 3> resistanceOld{}, slipTotal{};
  // Frozen by an algorithm (-1: follows the iterate).
  int frozenStatus = -1;
  double frozenThreshold = -1.0;
  double threshold = 0.0;           // of the last evaluation
  double constraintResidual = 0.0;  // of the last evaluation: its multiplier rows as forces
  double indicator = 0.0;           // of the last evaluation (closed when >= 0)
  double frictionIndicator = 0.0;   // of the last evaluation (slip when > 0)
  // Cycling treatments for the current step (-1 / 1: none).
  int forcedStatus = -1;
  double forcedThreshold = -1.0;
  double coefficientScale = 1.0;
  int cycling = 0;
  // Left out of the contact by the user (the zone's No Contact Group): always open.
  bool excluded = false;
  // Whether the supports fix the gap at the last evaluation (prescribedGap, PrescribedSlip.hpp):
  // the point was opened.
  bool gapPrescribed = false;
  // Friction directions the Dirichlet conditions prescribe at the last evaluation (their
  // multiplier component dropped: PrescribedSlip.hpp).
  int prescribedSlip = 0;
  // Last evaluation.
  ContactPointResult result;
  std::array<double, 3> slipIncrement{};
  // Element dofs (GIDs), our column LIDs, owned row LIDs (-1) and positions in the surface state.
  std::vector<GO> dofs;
  std::vector<char> freeDofs;  // per displacement dof of `dofs`: not Dirichlet-constrained
  // Orthonormal directions over the displacement dofs of `dofs` that inclined symmetry planes
  // remove from the free ones (PrescribedSlip.hpp); empty without such a plane.
  std::vector<std::vector<double>> removedDirections;
  // Unit normals of the symmetry planes through the slave node (any: inclined or normal to an
  // axis), whose friction direction symmetry drops (PrescribedSlip.hpp).
  std::vector<std::array<double, 3>> symmetryNormals;
  std::vector<LO> cols, rows;
  std::vector<int> surfacePos;
  // Geometric linearization: the displacement dofs of the master nodes around the facet that
  // are not already in `dofs` (the smoothed normal depends on them), as columns only.
  std::vector<GO> geometryDofs;
  std::vector<LO> geometryCols;
  std::vector<int> geometrySurfacePos;

  // Displacement dofs of the element: the slave's and its master nodes'.
  int displacementDofs(int dim) const { return static_cast<int>(1 + master.size()) * dim; }
  // The point's size: its tributary length (2D) or the root of its area (3D).
  double length(int dim) const { return dim == 3 ? std::sqrt(weight) : weight; }
};

}  // namespace contactlab
