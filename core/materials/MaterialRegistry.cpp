#include "core/materials/MaterialRegistry.hpp"

#include "core/materials/J2SmallStrain.hpp"
#include "core/materials/LinearElastic.hpp"
#include "core/materials/NeoHookean.hpp"
#include "core/materials/SaintVenantKirchhoff.hpp"
#include "core/materials/SimoMiehe.hpp"

#include <Teuchos_Array.hpp>

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
  materialRegistry().add(
      {"saint-venant-kirchhoff",
       "Saint Venant-Kirchhoff hyperelasticity, finite strain: S = lambda tr(E) I + 2 mu E with "
       "the Green-Lagrange strain E (large rotations, small strains).",
       [] {
         auto p = Teuchos::rcp(new Teuchos::ParameterList("saint-venant-kirchhoff"));
         p->set("E", 1.0, "Young's modulus (> 0), in the scene's stress unit");
         p->set("nu", 0.3, "Poisson's ratio, in (-1, 0.5)");
         p->set("density", 0.0, "Mass density (>= 0), used by body forces given per mass");
         return Teuchos::RCP<const Teuchos::ParameterList>(p);
       },
       [](const Teuchos::ParameterList& p) -> std::unique_ptr<Material> {
         return std::make_unique<SaintVenantKirchhoff>(p.get<double>("E"), p.get<double>("nu"),
                                                       p.get<double>("density"));
       }});
  materialRegistry().add(
      {"neo-hookean",
       "Compressible neo-Hookean hyperelasticity, finite strain: W = C10 (I1bar - 3) + U(J), "
       "U = (J - 1)^2 / D1 (Abaqus / code_aster form) or K/4 (J^2 - 1 - 2 ln J). Give either E "
       "and nu or C10 and D1.",
       [] {
         auto p = Teuchos::rcp(new Teuchos::ParameterList("neo-hookean"));
         p->set("E", 0.0,
                "Young's modulus (> 0), in the scene's stress unit; with nu it sets C10 = mu / 2 "
                "and D1 = 2 / K. 0 means not given: then give C10 and D1");
         p->set("nu", NeoHookean::kDefaultPoissonRatio,
                "Poisson's ratio, in (-1, 0.5); used only with E");
         p->set("C10", 0.0,
                "Coefficient C10 = mu / 2 (> 0), in the scene's stress unit. 0 means not given: "
                "then give E (and nu)");
         p->set("D1", 0.0,
                "Coefficient D1 = 2 / K (> 0), in 1 / (the scene's stress unit); given with C10");
         p->set("Volumetric Energy", "quadratic",
                "U(J): 'quadratic' (J - 1)^2 / D1 (Abaqus, code_aster) or 'simo-miehe' "
                "K/4 (J^2 - 1 - 2 ln J) (Simo & Miehe 1991, deal.II); the same at small strain");
         p->set("density", 0.0, "Mass density (>= 0), used by body forces given per mass");
         return Teuchos::RCP<const Teuchos::ParameterList>(p);
       },
       [](const Teuchos::ParameterList& p) -> std::unique_ptr<Material> {
         return std::make_unique<NeoHookean>(NeoHookean::fromParameters(
             p.get<double>("E"), p.get<double>("nu"), p.get<double>("C10"), p.get<double>("D1"),
             p.get<double>("density"),
             NeoHookean::volumetricFromName(p.get<std::string>("Volumetric Energy"))));
       }});
  materialRegistry().add(
      {"j2-small-strain",
       "Von Mises plasticity, small strain (plane strain in 2D): radial return with linear "
       "isotropic and linear kinematic (Prager) hardening, consistent tangent.",
       [] {
         auto p = Teuchos::rcp(new Teuchos::ParameterList("j2-small-strain"));
         p->set("E", 1.0, "Young's modulus (> 0), in the scene's stress unit");
         p->set("nu", 0.3, "Poisson's ratio, in (-1, 0.5)");
         p->set("Yield Stress", 0.0,
                "Initial uniaxial yield stress sigma_y0 (> 0, must be given), in the scene's "
                "stress unit");
         p->set("Isotropic Hardening Modulus", 0.0,
                "Linear isotropic hardening H_iso (>= 0), in the scene's stress unit: the yield "
                "stress is sigma_y0 + H_iso p, p the equivalent plastic strain");
         p->set("Kinematic Hardening Modulus", 0.0,
                "Linear kinematic (Prager) hardening H_kin (>= 0), in the scene's stress unit: "
                "d alpha = (2/3) H_kin d eps_p. In uniaxial stress the plastic modulus is "
                "H_iso + H_kin");
         p->set("density", 0.0, "Mass density (>= 0), used by body forces given per mass");
         return Teuchos::RCP<const Teuchos::ParameterList>(p);
       },
       [](const Teuchos::ParameterList& p) -> std::unique_ptr<Material> {
         J2SmallStrain::Parameters j2;
         j2.youngModulus = p.get<double>("E");
         j2.poissonRatio = p.get<double>("nu");
         j2.yieldStress = p.get<double>("Yield Stress");
         j2.isotropicHardening = p.get<double>("Isotropic Hardening Modulus");
         j2.kinematicHardening = p.get<double>("Kinematic Hardening Modulus");
         j2.density = p.get<double>("density");
         return std::make_unique<J2SmallStrain>(j2);
       }});
  materialRegistry().add(
      {"simo-miehe",
       "Von Mises plasticity, finite strain (plane strain in 2D): F = Fe Fp, Hencky elasticity "
       "in logarithmic strains, exponential-map radial return (Simo 1992; de Souza Neto et al. "
       "ch. 14), isotropic hardening linear or tabulated, consistent tangent.",
       [] {
         auto p = Teuchos::rcp(new Teuchos::ParameterList("simo-miehe"));
         p->set("E", 1.0,
                "Young's modulus (> 0), in the scene's stress unit; with nu the Hencky bulk and "
                "shear moduli K = E / (3 (1 - 2 nu)), G = E / (2 (1 + nu))");
         p->set("nu", 0.3, "Poisson's ratio, in (0, 0.5)");
         p->set("Yield Stress", 0.0,
                "Initial uniaxial yield stress sigma_y0 (> 0, must be given), in the scene's "
                "stress unit: the von Mises Kirchhoff stress at first yield");
         p->set("Isotropic Hardening Modulus", 0.0,
                "Linear isotropic hardening H (>= 0), in the scene's stress unit: the yield "
                "stress is sigma_y0 + H alpha, alpha the equivalent plastic strain; 0 is "
                "perfectly plastic. Leave at 0 when a hardening curve is given");
         p->set("Hardening Strains", Teuchos::Array<double>(),
                "Optional tabulated hardening: equivalent plastic strains alpha_i of the curve's "
                "points, starting at 0 and strictly increasing, e.g. [0, 0.02, 0.1]; with "
                "Hardening Stresses. The yield stress is piecewise linear in alpha and continues "
                "beyond the last point with the last segment's slope. Empty: linear hardening");
         p->set("Hardening Stresses", Teuchos::Array<double>(),
                "Yield stresses sigma_i at Hardening Strains (as many entries), starting at the "
                "Yield Stress and never decreasing, e.g. [250, 300, 340]");
         p->set("density", 0.0, "Mass density (>= 0), used by body forces given per mass");
         return Teuchos::RCP<const Teuchos::ParameterList>(p);
       },
       [](const Teuchos::ParameterList& p) -> std::unique_ptr<Material> {
         SimoMiehe::Parameters sm;
         sm.youngModulus = p.get<double>("E");
         sm.poissonRatio = p.get<double>("nu");
         sm.yieldStress = p.get<double>("Yield Stress");
         sm.isotropicHardening = p.get<double>("Isotropic Hardening Modulus");
         sm.hardeningStrains = p.get<Teuchos::Array<double>>("Hardening Strains").toVector();
         sm.hardeningStresses = p.get<Teuchos::Array<double>>("Hardening Stresses").toVector();
         sm.density = p.get<double>("density");
         return std::make_unique<SimoMiehe>(sm);
       }});
}

}  // namespace contactlab
