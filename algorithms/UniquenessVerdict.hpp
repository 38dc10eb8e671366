#pragma once
// One verdict from the two checks of checkUniqueness (doc/algorithms.md, "The verdict"):
// - the determinants of the Jacobians around the state (the adjacent status patterns): signs
//   that differ, or a singular one, mean that another solution may lie close to this one;
// - the critical factor s on mu (the adjacent patterns and the contact set slipping): s <= 1,
//   mu >= mu_crit, means that a slipping or separated state of the same contact set may
//   coexist with this one, even where the signs agree and this state is isolated
//   (doc/verification.md, "V6 on a continuum").
// "locally unique" only when neither says otherwise; "possibly non-unique" when either does,
// with the reason of the first that does (signs, then the critical mu).
#include "algorithms/PatternCriticalFriction.hpp"

#include <string>

namespace contactlab {

struct UniquenessVerdict {
  bool possiblyNonUnique = false;
  std::string verdict;  // "locally unique" or "possibly non-unique" (summary.json's words)
  std::string reason;   // what decided, in a clause ("mu >= mu_crit: ...")
};

UniquenessVerdict uniquenessVerdict(const UniquenessCheck& check);

}  // namespace contactlab
