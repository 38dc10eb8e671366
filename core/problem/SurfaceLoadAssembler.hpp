#pragma once
// The surface loads of a solid model on one rank: which facets the rank integrates, whether
// each pressure follows the deformation, and their assembly into the external force and, for
// follower pressures, into the tangent.
//
// A facet is integrated by the rank that assembles its parent element, the lowest-numbered
// element holding all the facet's nodes: every facet node is then in that rank's overlap map
// and the facet's matrix entries are in the parent's graph pattern. A pressure follows the
// deformation (SurfaceLoad::Follower) where the parent element is finite-strain, unless the
// load says otherwise; a follower facet integrates -p n da on the current facet and adds its
// load stiffness -df/du to the tangent through the parent element's rows, with the element
// matrices' elimination of constrained dofs. A dead facet (every facet of a small-strain body,
// every traction) has a force that does not depend on u and adds nothing to the tangent.
#include "core/problem/DofMap.hpp"
#include "core/problem/SolidModel.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace contactlab {

class MatrixAssembler;
class SurfaceLoadKernel;

class SurfaceLoadAssembler {
 public:
  // partition: the rank of every element (global order). Throws InputError, the same on every
  // rank (the checks read the whole mesh), when a facet belongs to no element or a load asks
  // for a follower pressure (Follower::Yes) on a facet of a small-strain element.
  SurfaceLoadAssembler(const SolidModel& model, const DofMap& dofs,
                       const std::vector<int>& partition);
  ~SurfaceLoadAssembler();

  // Names of the loads that follow the deformation somewhere (the same on every rank): their
  // load stiffness makes the tangent unsymmetric.
  const std::vector<std::string>& followerLoads() const { return followerLoads_; }

  // f (overlap dofs) += the equivalent nodal forces of the loads at time t, for the overlap
  // displacement u (read by follower facets only).
  void addForces(double t, const double* u, std::vector<double>& f) const;
  // The follower facets' load stiffness -df/du into `assembler`, between its begin() and
  // end(); nothing when there are none.
  void addStiffness(double t, const double* u, MatrixAssembler& assembler,
                    const std::vector<char>& constrained) const;

 private:
  struct Facet {
    int load;  // index in loads_
    ElementType type;
    bool follower;
    std::vector<int> overlapNodes;
    std::vector<double> x;  // reference coordinates, 3 per node
    // Follower facets: the parent's local element index and each facet node's position in the
    // parent's node list.
    int element = -1;
    std::vector<int> elementNodes;
  };
  void locate(const SolidModel& model, const DofMap& dofs, const std::vector<int>& partition);
  // The facet's displacements (dim per node) gathered from the overlap vector u.
  void gather(const Facet& facet, const double* u, std::vector<double>& ue) const;

  int dim_;
  bool axisymmetric_;  // facets weighted by 2 pi r (SolidModel::axisymmetric)
  std::vector<SurfaceLoad> loads_;
  std::vector<Facet> facets_;
  std::vector<std::size_t> followerFacets_;  // indices in facets_
  std::vector<std::string> followerLoads_;
  // One kernel per facet type (they tabulate shape functions).
  std::map<ElementType, std::unique_ptr<SurfaceLoadKernel>> kernels_;
};

}  // namespace contactlab
