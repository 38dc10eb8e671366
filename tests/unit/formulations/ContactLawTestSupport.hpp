#pragma once
// Helpers shared by the pointwise contact-law tests: the three laws with coefficients of
// moderate size, and one contact point's input.
#include "formulations/AugmentedLagrangian.hpp"
#include "formulations/ContactLaw.hpp"
#include "formulations/Lagrange.hpp"
#include "formulations/Penalty.hpp"

#include <memory>
#include <string>

namespace contactlab::test {

inline const double kMu = 0.3;
inline const double kWeight = 0.7;

// Coefficients of moderate size so that central differences are accurate to ~1e-9.
inline std::unique_ptr<ContactLaw> makeLaw(const std::string& name) {
  if (name == "penalty") return std::make_unique<Penalty>(100.0, 50.0);
  if (name == "lagrange") return std::make_unique<Lagrange>(10.0, 5.0);
  return std::make_unique<AugmentedLagrangian>(10.0, 5.0);
}

inline const char* const kLawNames[] = {"penalty", "lagrange", "augmented-lagrangian"};

// A point of tributary weight kWeight with nt tangential components (friction kMu when nt > 0)
// at `gap`, with the normal multiplier p; no slip, no tangential multipliers or history.
inline LawInput pointInput(int nt, double gap, double p = 0.0) {
  LawInput in;
  in.weight = kWeight;
  in.nt = nt;
  in.mu = nt > 0 ? kMu : 0.0;
  in.gap = gap;
  in.p = p;
  return in;
}

}  // namespace contactlab::test
