#include "core/materials/MaterialRegistry.hpp"

#include "core/materials/LinearElastic.hpp"

namespace contactlab {

MaterialRegistry& materialRegistry() {
  static MaterialRegistry registry("material");
  return registry;
}

void registerMaterials() {
  materialRegistry().add(
      {"linear-elastic", "Isotropic linear elasticity, small strain (plane strain in 2D).",
       [] {
         auto p = Teuchos::rcp(new Teuchos::ParameterList("linear-elastic"));
         p->set("E", 1.0, "Young's modulus (> 0), in the scene's stress unit");
         p->set("nu", 0.3, "Poisson's ratio, in (-1, 0.5)");
         p->set("density", 0.0, "Mass density (>= 0), used by body forces given per mass");
         return Teuchos::RCP<const Teuchos::ParameterList>(p);
       },
       [](const Teuchos::ParameterList& p) -> std::unique_ptr<Material> {
         return std::make_unique<LinearElastic>(p.get<double>("E"), p.get<double>("nu"),
                                                p.get<double>("density"));
       }});
}

}  // namespace contactlab
