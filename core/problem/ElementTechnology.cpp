#include "core/problem/ElementTechnology.hpp"

#include "base/InputError.hpp"
#include "base/NumberText.hpp"
#include "core/materials/ReferenceStiffness.hpp"
#include "core/problem/FBarKernel.hpp"
#include "core/problem/ProjectedDilatationKernel.hpp"
#include "core/problem/ProjectedJacobianKernel.hpp"

#include <stdexcept>

namespace contactlab {
namespace {

bool isLinearQuadOrHex(ElementType type) {
  return type == ElementType::Quad4 || type == ElementType::Hex8;
}

bool isLinearSimplex(ElementType type) {
  return type == ElementType::Tri3 || type == ElementType::Tet4;
}

std::string typeName(ElementType type) {
  return info(type).name;
}

// The refusals every locking-free technology shares.
std::string lockingFreeRefusal(const ElementSetting& s) {
  if (s.planeStress)
    return "plane stress does not lock (the thickness takes up the volume change): use full";
  return "";
}

std::unique_ptr<ElementTechnology> full() {
  return std::make_unique<ElementTechnology>(
      "full", [](const ElementSetting&) { return std::string(); },
      [](const ElementSetting& s) {
        return makeElementKernel(s.type, s.kinematics, -1, s.axisymmetric);
      },
      true);
}

// b-bar's and f-bar's refusals: one kinematics, quad4 and hex8 only.
std::string linearCellRefusal(const char* technology, Kinematics kinematics,
                              const ElementSetting& s) {
  const bool small = kinematics == Kinematics::SmallStrain;
  if (s.kinematics != kinematics)
    return std::string(technology) + " is for " + (small ? "small" : "finite") +
           "-strain materials; a " + (small ? "finite" : "small") + "-strain one takes " +
           (small ? "f-bar" : "b-bar") + " or mixed-up";
  if (!isLinearQuadOrHex(s.type))
    return std::string(technology) + " takes quad4 and hex8 elements, not " + typeName(s.type) +
           (isLinearSimplex(s.type) ? "" : "; quadratic elements take mixed-up");
  return lockingFreeRefusal(s);
}

std::unique_ptr<ElementTechnology> bBar() {
  return std::make_unique<ElementTechnology>(
      "b-bar",
      [](const ElementSetting& s) {
        return linearCellRefusal("b-bar", Kinematics::SmallStrain, s);
      },
      [](const ElementSetting& s) {
        return std::make_unique<ProjectedDilatationKernel>(s.type, 0, s.axisymmetric);
      },
      true);
}

std::unique_ptr<ElementTechnology> fBar() {
  return std::make_unique<ElementTechnology>(
      "f-bar",
      [](const ElementSetting& s) {
        return linearCellRefusal("f-bar", Kinematics::FiniteStrain, s);
      },
      [](const ElementSetting& s) { return std::make_unique<FBarKernel>(s.type, s.axisymmetric); },
      false);
}

std::unique_ptr<ElementTechnology> mixedUp() {
  return std::make_unique<ElementTechnology>(
      "mixed-up",
      [](const ElementSetting& s) -> std::string {
        if (isLinearSimplex(s.type))
          return "mixed-up needs a pressure space the displacements can satisfy, which " +
                 typeName(s.type) +
                 " cells (constant strain) do not give: use tri6/tet10 or quadrilaterals/"
                 "hexahedra";
        return lockingFreeRefusal(s);
      },
      [](const ElementSetting& s) -> std::unique_ptr<ElementKernel> {
        const int degree = isLinearQuadOrHex(s.type) ? 0 : 1;
        if (s.kinematics == Kinematics::SmallStrain)
          return std::make_unique<ProjectedDilatationKernel>(s.type, degree, s.axisymmetric);
        return std::make_unique<ProjectedJacobianKernel>(s.type, degree, s.axisymmetric);
      },
      true);
}

void add(const std::string& name, const std::string& doc,
         std::unique_ptr<ElementTechnology> (*make)()) {
  elementTechnologyRegistry().add({name, doc,
                                   [] { return Teuchos::rcp(new Teuchos::ParameterList()); },
                                   [make](const Teuchos::ParameterList&) { return make(); }});
}

}  // namespace

std::unique_ptr<ElementKernel> ElementTechnology::kernel(const ElementSetting& setting) const {
  const std::string why = refusal(setting);
  if (!why.empty()) throw std::invalid_argument(why);
  return kernel_(setting);
}

ElementTechnologyRegistry& elementTechnologyRegistry() {
  static ElementTechnologyRegistry registry("element technology");
  return registry;
}

void registerElementTechnologies() {
  add("full",
      "Full integration of the displacement element (every cell type); locks under isochoric "
      "plastic flow and near incompressibility on quad4/hex8 and linear simplices",
      &full);
  add("b-bar",
      "Small strain, quad4 and hex8 (and the quad4 ring): the dilatation replaced by its mean "
      "over the element (Hughes 1980; mean dilatation, Nagtegaal, Parks & Rice 1974); the same "
      "element as mixed-up there; symmetric tangent",
      &bBar);
  add("f-bar",
      "Finite strain, quad4 and hex8 (and the quad4 ring): F's volumetric part taken from the "
      "element's centre (de Souza Neto et al. 1996); unsymmetric tangent, so MUMPS runs in "
      "general (LU) mode",
      &fBar);
  add("mixed-up",
      "Displacement-pressure element with a discontinuous pressure condensed element by "
      "element (no new unknowns): Q1/P0 on quad4/hex8, P1 pressures on tri6, quad8, quad9, "
      "tet10, hex20 and hex27; small strain (three-field B-bar) and finite strain (Simo, "
      "Taylor & Pister 1985); symmetric tangent when the material's is",
      &mixedUp);
}

AutomaticChoice chooseAutomatic(const Material& material, const ElementSetting& setting) {
  std::string why;
  if (material.isochoricFlow()) {
    why = material.name() + " flows plastically at constant volume";
  } else {
    double nu = 0.0;
    try {
      nu = referencePoissonRatio(material);
    } catch (const std::invalid_argument&) {
      nu = 0.0;  // the model check reports such a law; it does not lock here
    }
    if (nu >= kNearlyIncompressiblePoisson)
      why = material.name() + " is nearly incompressible (nu = " + numberText(nu) +
            " >= " + numberText(kNearlyIncompressiblePoisson) + ")";
  }
  if (why.empty()) return {"full", "compressible and elastic"};
  if (setting.planeStress) return {"full", why + ", but plane stress does not lock"};
  if (isLinearSimplex(setting.type))
    return {"full", why + ", but " + typeName(setting.type) +
                        " cells lock under every technology here: prefer tri6/tet10 or "
                        "quadrilaterals/hexahedra"};
  // Finite strain takes the three-field mixed-up (Q1/P0) rather than f-bar: symmetric, and f-bar
  // inverts elements of a block squeezed by a third (scenes/polyurethane-block-2d.yaml).
  if (!isLinearQuadOrHex(setting.type) || setting.kinematics != Kinematics::SmallStrain)
    return {"mixed-up", why};
  return {"b-bar", why};
}

BlockTechnology resolveBlockTechnology(const std::string& block, const std::string& requested,
                                       const Material& material, const ElementSetting& setting) {
  registerElementTechnologies();
  const ElementTechnologyRegistry& registry = elementTechnologyRegistry();
  const std::string key = "Materials/" + block + "/Element Technology";
  BlockTechnology result;
  result.block = block;
  result.requested = requested;
  if (requested == "automatic") {
    const AutomaticChoice choice = chooseAutomatic(material, setting);
    result.name = choice.technology;
    result.reason = choice.reason;
  } else if (registry.has(requested)) {
    result.name = requested;
  } else {
    throw InputError(key + ": unknown element technology '" + requested +
                     "'; valid choices: automatic, " + registry.joinedNames());
  }
  result.technology = registry.get(result.name).build(Teuchos::ParameterList());
  const std::string why = result.technology->refusal(setting);
  if (!why.empty()) {
    std::string valid;
    for (const auto& name : registry.names())
      if (registry.get(name).build(Teuchos::ParameterList())->refusal(setting).empty())
        valid += (valid.empty() ? "" : ", ") + name;
    throw InputError(key + ": " + why + " (block '" + block + "': " + typeName(setting.type) +
                     ", " + material.name() + "; valid here: automatic, " + valid + ")");
  }
  return result;
}

}  // namespace contactlab
