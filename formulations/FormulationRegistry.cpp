#include "formulations/FormulationRegistry.hpp"

#include "base/NumberText.hpp"
#include "formulations/AugmentedLagrangian.hpp"
#include "formulations/Lagrange.hpp"
#include "formulations/NormalFieldAugmentedLagrangian.hpp"
#include "formulations/Penalty.hpp"

#include <map>
#include <utility>

namespace contactlab {
namespace {

using Teuchos::ParameterList;

// Two positive coefficients; 0 (the default of the required ones) fails validation in the
// law's constructor with a sentence naming them.
Teuchos::RCP<const ParameterList> coefficients(const std::string& normal, double normalDefault,
                                               const std::string& normalDoc,
                                               const std::string& tangential,
                                               double tangentialDefault,
                                               const std::string& tangentialDoc) {
  auto p = Teuchos::rcp(new ParameterList);
  p->set(normal, normalDefault, normalDoc);
  p->set(tangential, tangentialDefault, tangentialDoc);
  return p;
}

// The augmented Lagrangian's coefficients, shared by its normal-field variant.
Teuchos::RCP<ParameterList> augmentation() {
  return Teuchos::rcp(new ParameterList(*coefficients(
      "Normal Augmentation", 0.0,
      "r_n > 0 (pressure per length); 0 = automatic: E/h, E the softer body's Young's modulus "
      "at rest, h the median edge of the slave facets (printed in the log). It changes the "
      "Newton path, not the converged state",
      "Tangential Augmentation", 0.0,
      "r_t > 0 (inverse length; unused without friction); 0 = automatic: 1 / (0.01 mu h), h as "
      "for r_n (printed in the log): the stick stiffness mu p r_t equals r_n at a contact "
      "pressure p of 1 % of E. Its natural scale is E / (mu p h). It changes the Newton path, "
      "not the converged state (where the solution is unique)")));
}

// r_n and r_t as given; r_t, unused without friction, is 1 when left at its default 0.
std::pair<double, double> augmentationOf(const ParameterList& p) {
  const double rn = p.get<double>("Normal Augmentation");
  double rt = p.get<double>("Tangential Augmentation");
  if (rt == 0.0 && rn > 0) rt = 1.0;
  return {rn, rt};
}

std::invalid_argument named(const std::invalid_argument& e, const std::string& keys) {
  return std::invalid_argument(std::string(e.what()) + " (" + keys + ")");
}

// The contact pressure, as a fraction of E, at which the automatic r_t makes the stick
// stiffness mu p r_t of the augmented friction law equal to r_n = E / h.
constexpr double kAutomaticContactStrain = 0.01;

// A normal coefficient E / h (the augmented Lagrangian's r_n, Lagrange's c_n).
AutomaticCoefficient contactStiffness(const std::string& key, const std::string& symbol) {
  return {key, false, [](const ContactScale& s, double) { return s.stiffness(); },
          [key, symbol](const ContactScale& s, double, double value) {
            return key + " " + symbol + " = E / h = " + numberText(value) +
                   " (automatic: E = " + numberText(s.youngModulus) +
                   ", the softer body's; h = " + numberText(s.facetSize) +
                   ", the slave facets' median edge)";
          }};
}

// r_t when a frictional scene leaves Tangential Augmentation at 0: 1 / (0.01 mu h), i.e.
// r_n / (mu p) at p = 1 % of E. The multiplier Lambda is a number and r_t Lambda's change per
// unit slip: its natural scale is (E / h) / (mu p), so 1 / h (the old advice) is E / (mu p)
// times too small wherever the contact strain p / E is small: code_aster SSNV128 (p / E =
// 4e-4, mu = 1) failed with r_t = 1 / h under every algorithm and converges from 1e4 to 1e8
// (1 / (0.01 h) = 8e4). Measured on the 9 frictional scenes shipped with contactlab (p / E
// from 5e-5 to 0.05): all converge with it, in 0.75x to 2.4x the Newton iterations of their
// hand-picked r_t; 1 / (0.001 mu h) fails 2 of them (doc/verification.md "SSNV128").
AutomaticCoefficient tangentialAugmentation() {
  return {"Tangential Augmentation", true,
          [](const ContactScale& s, double mu) {
            return 1.0 / (kAutomaticContactStrain * mu * s.facetSize);
          },
          [](const ContactScale& s, double mu, double value) {
            return "Tangential Augmentation r_t = 1 / (" + numberText(kAutomaticContactStrain) +
                   " mu h) = " + numberText(value) + " (automatic: mu = " + numberText(mu) +
                   ", h = " + numberText(s.facetSize) + ")";
          }};
}

std::map<std::string, std::vector<AutomaticCoefficient>>& automaticCoefficientTable() {
  static std::map<std::string, std::vector<AutomaticCoefficient>> table;
  return table;
}

}  // namespace

FormulationRegistry& formulationRegistry() {
  static FormulationRegistry registry("formulation");
  return registry;
}

const std::vector<AutomaticCoefficient>& automaticCoefficients(const std::string& formulation) {
  static const std::vector<AutomaticCoefficient> none;
  const auto it = automaticCoefficientTable().find(formulation);
  return it == automaticCoefficientTable().end() ? none : it->second;
}

void registerFormulations() {
  auto& r = formulationRegistry();
  auto& automatic = automaticCoefficientTable();
  r.add({"penalty",
         "Penalty: p = eps_n <-g>, regularized Coulomb friction; no multipliers, inexact "
         "(interpenetration p/eps_n)",
         [] {
           return coefficients("Normal Penalty", 0.0,
                               "eps_n > 0 (pressure per length; required). Start near 10-100 E/h",
                               "Tangential Penalty", 0.0,
                               "eps_t > 0 (traction per length of elastic slip; required "
                               "with friction, unused without)");
         },
         [](const ParameterList& p) -> std::unique_ptr<ContactLaw> {
           try {
             const double epsN = p.get<double>("Normal Penalty");
             double epsT = p.get<double>("Tangential Penalty");
             if (epsT == 0.0 && epsN > 0) epsT = epsN;  // unused without friction
             return std::make_unique<Penalty>(epsN, epsT);
           } catch (const std::invalid_argument& e) {
             throw named(e, "Normal Penalty, Tangential Penalty");
           }
         }});
  r.add({"lagrange",
         "Exact Lagrange multipliers (pressure and normalized friction direction per slave "
         "point) with a primal-dual active set for contact and stick/slip",
         [] {
           return coefficients(
               "Normal Complementarity Constant", 0.0,
               "c_n > 0: weighs the gap against the pressure when choosing the active set "
               "(p - c_n g >= 0); does not change the solution. 0 = automatic: E/h as the "
               "augmented Lagrangian's r_n (printed in the log)",
               "Tangential Complementarity Constant", 1.0,
               "c_t > 0 (inverse length): same role for stick/slip (||Lambda + c_t v|| < 1)");
         },
         [](const ParameterList& p) -> std::unique_ptr<ContactLaw> {
           try {
             return std::make_unique<Lagrange>(
                 p.get<double>("Normal Complementarity Constant"),
                 p.get<double>("Tangential Complementarity Constant"));
           } catch (const std::invalid_argument& e) {
             throw named(e, "Normal Complementarity Constant, Tangential Complementarity Constant");
           }
         }});
  r.add({"augmented-lagrangian",
         "The seed's augmented Lagrangian: multipliers p and Lambda, augmented p^ = p - r_n g "
         "and Lambda^ = Lambda + r_t v, generalized Newton on the statuses",
         [] { return Teuchos::RCP<const ParameterList>(augmentation()); },
         [](const ParameterList& p) -> std::unique_ptr<ContactLaw> {
           try {
             const auto [rn, rt] = augmentationOf(p);
             return std::make_unique<AugmentedLagrangian>(rn, rt);
           } catch (const std::invalid_argument& e) {
             throw named(e, "Normal Augmentation, Tangential Augmentation");
           }
         }});
  r.add({"normal-field-augmented-lagrangian",
         "The seed's non-standard augmented Lagrangian: the augmented Lagrangian with a slave "
         "normal n_s as unknown at each point (the gap measured along it), tied to the master's "
         "normal by w kappa_n (n_s - n(u)) = 0; node-to-segment and rigid obstacles",
         [] {
           auto p = augmentation();
           p->set("Normal Field Penalty", 0.0,
                  "kappa_n >= 0 (pressure): weighs the kinematic condition n_s = n(u); 0 = "
                  "automatic, r_n times the point's size. It changes the Newton path, not the "
                  "converged state");
           return Teuchos::RCP<const ParameterList>(p);
         },
         [](const ParameterList& p) -> std::unique_ptr<ContactLaw> {
           try {
             const auto [rn, rt] = augmentationOf(p);
             return std::make_unique<NormalFieldAugmentedLagrangian>(
                 rn, rt, p.get<double>("Normal Field Penalty"));
           } catch (const std::invalid_argument& e) {
             throw named(e, "Normal Augmentation, Tangential Augmentation, Normal Field Penalty");
           }
         }});
  // Left at 0, these come from the zone's contact scale (the laws' converged states do not
  // depend on them: they set the Newton path).
  automatic["lagrange"] = {contactStiffness("Normal Complementarity Constant", "c_n")};
  for (const char* name : {"augmented-lagrangian", "normal-field-augmented-lagrangian"})
    automatic[name] = {contactStiffness("Normal Augmentation", "r_n"), tangentialAugmentation()};
}

}  // namespace contactlab
