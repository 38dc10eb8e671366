#include "core/materials/MaterialRegistry.hpp"

#include "core/materials/J2SmallStrain.hpp"
#include "core/materials/LinearElastic.hpp"
#include "core/materials/NeoHookean.hpp"
#include "core/materials/SaintVenantKirchhoff.hpp"
#include "core/materials/SimoMiehe.hpp"

#include <Teuchos_Array.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace contactlab {
namespace {

using Teuchos::ParameterList;

// The thermal parameters of a law: alpha and T_ref, and a `Temperature Tables`
// sublist with one temperature grid and an optional column per parameter in `tabulated`
// (keys of p) and for alpha. One grid per law, because data sheets (RCC-M, the EN 10028 and
// ASME II-D tables) list every property at the same temperatures.
void addThermalParameters(ParameterList& p, const std::vector<std::string>& tabulated) {
  p.set("Thermal Expansion", 0.0,
        "Secant coefficient of thermal expansion alpha, in 1/K, measured from Reference "
        "Temperature: the thermal strain is alpha (T - T_ref) in every normal direction (the "
        "hoop one too in axisymmetry; finite-strain laws: F = F_e F_theta with the stretch "
        "F_theta = (1 + alpha (T - T_ref)) I); T is the block's Temperature entry (0: no "
        "thermal strain)");
  p.set("Reference Temperature", 20.0,
        "Stress-free temperature T_ref, in degC: no thermal strain at it, and the block's "
        "temperature when the scene's Temperature section does not name the block (its "
        "tables are then read at T_ref)");
  // sublist(name, false, doc): Teuchos keeps a sublist's doc string only when made this way.
  ParameterList& tables = p.sublist("Temperature Tables", false,
                                    "Parameters as functions of the temperature, on one grid of "
                                    "Temperatures");
  tables.set("Temperatures", Teuchos::Array<double>(),
             "Temperatures of the table's rows, in degC, strictly increasing, e.g. [20, 100, "
             "200, 304]; each parameter given below is piecewise linear between them and holds "
             "its first and last values beyond them. Empty: no table");
  for (const std::string& key : tabulated)
    tables.set(key, Teuchos::Array<double>(),
               key + " at each of Temperatures (as many entries), replacing the constant " + key +
                   " (leave that out). Empty: the constant");
  tables.set("Thermal Expansion", Teuchos::Array<double>(),
             "alpha at each of Temperatures (secant, from Reference Temperature), replacing the "
             "constant Thermal Expansion. Empty: the constant");
}

// Parameter `key` of a law: the constant p[key], or its column of `Temperature Tables`. A
// column and a constant other than the default (`valid`'s) would be two values for one thing.
TemperatureDependent temperatureDependent(const ParameterList& p, const ParameterList& valid,
                                          const std::string& key) {
  const double constant = p.get<double>(key);
  const ParameterList& tables = p.sublist("Temperature Tables");
  const auto& column = tables.get<Teuchos::Array<double>>(key);
  if (column.empty()) return constant;
  if (constant != valid.get<double>(key))
    throw std::invalid_argument(valid.name() + ": give " + key + " or Temperature Tables/" + key +
                                ", not both");
  const auto& temperatures = tables.get<Teuchos::Array<double>>("Temperatures");
  return TemperatureDependent(temperatures.toVector(), column.toVector(),
                              "Temperature Tables/" + key);
}

// Also refuses a grid of Temperatures without any column: a table that tabulates nothing is a
// mistake (a column misspelt would have been refused by the validation, one forgotten not).
ThermalExpansion thermalExpansion(const ParameterList& p, const ParameterList& valid) {
  const ParameterList& tables = p.sublist("Temperature Tables");
  bool anyColumn = false;
  for (auto it = tables.begin(); it != tables.end(); ++it)
    if (tables.name(it) != "Temperatures")
      anyColumn = anyColumn || !tables.get<Teuchos::Array<double>>(tables.name(it)).empty();
  if (!tables.get<Teuchos::Array<double>>("Temperatures").empty() && !anyColumn)
    throw std::invalid_argument(valid.name() +
                                ": Temperature Tables has Temperatures but no parameter column "
                                "(e.g. E: [...]); give one or remove the table");
  ThermalExpansion expansion;
  expansion.coefficient = temperatureDependent(p, valid, "Thermal Expansion");
  expansion.referenceTemperature = p.get<double>("Reference Temperature");
  return expansion;
}

Teuchos::RCP<const ParameterList> validLinearElastic() {
  auto p = Teuchos::rcp(new ParameterList("linear-elastic"));
  p->set("E", 1.0, "Young's modulus (> 0), in the scene's stress unit");
  p->set("nu", 0.3, "Poisson's ratio, in (-1, 0.5)");
  p->set("density", 0.0, "Mass density (>= 0), used by body forces given per mass");
  addThermalParameters(*p, {"E", "nu"});
  return p;
}

Teuchos::RCP<const ParameterList> validJ2SmallStrain() {
  auto p = Teuchos::rcp(new ParameterList("j2-small-strain"));
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
  addThermalParameters(*p, {"E", "nu", "Yield Stress", "Isotropic Hardening Modulus",
                            "Kinematic Hardening Modulus"});
  return p;
}

Teuchos::RCP<const ParameterList> validSaintVenantKirchhoff() {
  auto p = Teuchos::rcp(new ParameterList("saint-venant-kirchhoff"));
  p->set("E", 1.0, "Young's modulus (> 0), in the scene's stress unit");
  p->set("nu", 0.3, "Poisson's ratio, in (-1, 0.5)");
  p->set("density", 0.0, "Mass density (>= 0), used by body forces given per mass");
  addThermalParameters(*p, {});
  return p;
}

Teuchos::RCP<const ParameterList> validNeoHookean() {
  auto p = Teuchos::rcp(new ParameterList("neo-hookean"));
  p->set("E", 0.0,
         "Young's modulus (> 0), in the scene's stress unit; with nu it sets C10 = mu / 2 "
         "and D1 = 2 / K. 0 means not given: then give C10 and D1");
  p->set("nu", NeoHookean::kDefaultPoissonRatio, "Poisson's ratio, in (-1, 0.5); used only with E");
  p->set("C10", 0.0,
         "Coefficient C10 = mu / 2 (> 0), in the scene's stress unit. 0 means not given: "
         "then give E (and nu)");
  p->set("D1", 0.0,
         "Coefficient D1 = 2 / K (> 0), in 1 / (the scene's stress unit); given with C10");
  p->set("Volumetric Energy", "quadratic",
         "U(J): 'quadratic' (J - 1)^2 / D1 (Abaqus, code_aster) or 'simo-miehe' "
         "K/4 (J^2 - 1 - 2 ln J) (Simo & Miehe 1991, deal.II); the same at small strain");
  p->set("density", 0.0, "Mass density (>= 0), used by body forces given per mass");
  addThermalParameters(*p, {});
  return p;
}

Teuchos::RCP<const ParameterList> validSimoMiehe() {
  auto p = Teuchos::rcp(new ParameterList("simo-miehe"));
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
  addThermalParameters(*p, {});
  return p;
}

}  // namespace

MaterialRegistry& materialRegistry() {
  static MaterialRegistry registry("material");
  return registry;
}

void registerMaterials() {
  materialRegistry().add(
      {"linear-elastic",
       "Isotropic linear elasticity, small strain (plane strain in 2D), with thermal strain and "
       "parameters tabulated in temperature.",
       validLinearElastic, [](const ParameterList& p) -> std::unique_ptr<Material> {
         const auto valid = validLinearElastic();
         LinearElastic::Parameters le;
         le.youngModulus = temperatureDependent(p, *valid, "E");
         le.poissonRatio = temperatureDependent(p, *valid, "nu");
         le.expansion = thermalExpansion(p, *valid);
         le.density = p.get<double>("density");
         return std::make_unique<LinearElastic>(le);
       }});
  materialRegistry().add(
      {"saint-venant-kirchhoff",
       "Saint Venant-Kirchhoff hyperelasticity, finite strain: S = lambda tr(E) I + 2 mu E with "
       "the Green-Lagrange strain E (large rotations, small strains); thermal stretch F = Fe "
       "F_theta.",
       validSaintVenantKirchhoff, [](const ParameterList& p) -> std::unique_ptr<Material> {
         return std::make_unique<SaintVenantKirchhoff>(
             p.get<double>("E"), p.get<double>("nu"), p.get<double>("density"),
             thermalExpansion(p, *validSaintVenantKirchhoff()));
       }});
  materialRegistry().add(
      {"neo-hookean",
       "Compressible neo-Hookean hyperelasticity, finite strain: W = C10 (I1bar - 3) + U(J), "
       "U = (J - 1)^2 / D1 (Abaqus / code_aster form) or K/4 (J^2 - 1 - 2 ln J). Give either E "
       "and nu or C10 and D1. Thermal stretch F = Fe F_theta.",
       validNeoHookean, [](const ParameterList& p) -> std::unique_ptr<Material> {
         return std::make_unique<NeoHookean>(
             NeoHookean::fromParameters(
                 p.get<double>("E"), p.get<double>("nu"), p.get<double>("C10"), p.get<double>("D1"),
                 p.get<double>("density"),
                 NeoHookean::volumetricFromName(p.get<std::string>("Volumetric Energy")))
                 .withThermalExpansion(thermalExpansion(p, *validNeoHookean())));
       }});
  materialRegistry().add(
      {"j2-small-strain",
       "Von Mises plasticity, small strain (plane strain in 2D): radial return with linear "
       "isotropic and linear kinematic (Prager) hardening, consistent tangent; thermal strain "
       "and parameters tabulated in temperature (isothermal steps).",
       validJ2SmallStrain, [](const ParameterList& p) -> std::unique_ptr<Material> {
         const auto valid = validJ2SmallStrain();
         J2SmallStrain::Parameters j2;
         j2.youngModulus = temperatureDependent(p, *valid, "E");
         j2.poissonRatio = temperatureDependent(p, *valid, "nu");
         j2.yieldStress = temperatureDependent(p, *valid, "Yield Stress");
         j2.isotropicHardening = temperatureDependent(p, *valid, "Isotropic Hardening Modulus");
         j2.kinematicHardening = temperatureDependent(p, *valid, "Kinematic Hardening Modulus");
         j2.expansion = thermalExpansion(p, *valid);
         j2.density = p.get<double>("density");
         return std::make_unique<J2SmallStrain>(j2);
       }});
  materialRegistry().add(
      {"simo-miehe",
       "Von Mises plasticity, finite strain (plane strain in 2D): F = Fe Fp, Hencky elasticity "
       "in logarithmic strains, exponential-map radial return (Simo 1992; de Souza Neto et al. "
       "ch. 14), isotropic hardening linear or tabulated, consistent tangent; thermal stretch "
       "F = Fe F_theta Fp.",
       validSimoMiehe, [](const ParameterList& p) -> std::unique_ptr<Material> {
         SimoMiehe::Parameters sm;
         sm.youngModulus = p.get<double>("E");
         sm.poissonRatio = p.get<double>("nu");
         sm.yieldStress = p.get<double>("Yield Stress");
         sm.isotropicHardening = p.get<double>("Isotropic Hardening Modulus");
         sm.hardeningStrains = p.get<Teuchos::Array<double>>("Hardening Strains").toVector();
         sm.hardeningStresses = p.get<Teuchos::Array<double>>("Hardening Stresses").toVector();
         sm.density = p.get<double>("density");
         sm.expansion = thermalExpansion(p, *validSimoMiehe());
         return std::make_unique<SimoMiehe>(sm);
       }});
}

}  // namespace contactlab
