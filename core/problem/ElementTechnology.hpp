#pragma once
// How a block's elements form the strain (or F) their material sees from the shape functions:
// an axis with a registry (elementTechnologyRegistry()): `full` (the plain kernels), `b-bar`,
// `f-bar` and `mixed-up`. A technology says which cells and kinematics it takes (refusal) and
// builds the kernel; the material never knows which one formed its strain. `automatic` (the
// default of a scene's Materials/<block>/Element Technology) is not an entry: chooseAutomatic
// picks one from the material and the cell, and says why.
#include "base/Registry.hpp"
#include "core/materials/Material.hpp"
#include "core/mesh/ElementType.hpp"
#include "core/problem/ElementKernel.hpp"

#include <functional>
#include <memory>
#include <string>

namespace contactlab {

// What a block's elements are: their type, their material's kinematics and the model's 2D
// geometry.
struct ElementSetting {
  ElementType type;
  Kinematics kinematics;
  bool axisymmetric = false;
  bool planeStress = false;
};

class ElementTechnology {
 public:
  using Refusal = std::function<std::string(const ElementSetting&)>;
  using KernelBuilder = std::function<std::unique_ptr<ElementKernel>(const ElementSetting&)>;

  ElementTechnology(std::string name, Refusal refusal, KernelBuilder kernel, bool keepsSymmetry)
      : name_(std::move(name)),
        refusal_(std::move(refusal)),
        kernel_(std::move(kernel)),
        keepsSymmetry_(keepsSymmetry) {}

  const std::string& name() const { return name_; }
  // Why it cannot form the elements of `setting` (a sentence fragment naming what would); empty
  // when it can.
  std::string refusal(const ElementSetting& setting) const { return refusal_(setting); }
  // The kernel of `setting`; std::invalid_argument when refusal() is not empty.
  std::unique_ptr<ElementKernel> kernel(const ElementSetting& setting) const;
  // Whether the element tangent is symmetric whenever the material's is (F-bar's is not).
  bool keepsSymmetry() const { return keepsSymmetry_; }

 private:
  std::string name_;
  Refusal refusal_;
  KernelBuilder kernel_;
  bool keepsSymmetry_;
};

using ElementTechnologyRegistry = Registry<ElementTechnology>;
ElementTechnologyRegistry& elementTechnologyRegistry();
void registerElementTechnologies();

// The technology `automatic` picks, and why (for the run's log and summary.json): where the
// material's volume barely changes (plastic flow, which is isochoric, or nu >= 0.45 at rest) a
// locking-free one — b-bar on quad4 and hex8 in small strain, mixed-up otherwise (f-bar only
// when asked: it is unsymmetric and inverts elements under strong compression) — and full
// integration elsewhere: in plane stress (the thickness takes up the volume change), on linear
// simplices (tri3 and tet4 lock under any of them) and for every compressible elastic law, whose
// blocks keep the plain kernels.
struct AutomaticChoice {
  std::string technology;
  std::string reason;
};
AutomaticChoice chooseAutomatic(const Material& material, const ElementSetting& setting);

// A block's technology: the registry entry `requested` names, or chooseAutomatic's pick for
// "automatic". Throws InputError naming Materials/<block>/Element Technology, what cannot be
// formed and the valid choices, when the technology cannot form the block's elements.
struct BlockTechnology {
  std::string block;
  std::string requested;  // as the scene says: a registry name or "automatic"
  std::string name;       // the technology used
  std::string reason;     // automatic's reason; empty when the scene names the technology
  std::shared_ptr<const ElementTechnology> technology;
};
BlockTechnology resolveBlockTechnology(const std::string& block, const std::string& requested,
                                       const Material& material, const ElementSetting& setting);

// The Poisson ratio below which `automatic` keeps full integration for an elastic law.
constexpr double kNearlyIncompressiblePoisson = 0.45;

}  // namespace contactlab
