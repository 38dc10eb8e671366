#include "algorithms/UniquenessVerdict.hpp"

#include "base/NumberText.hpp"

#include <cmath>

namespace contactlab {

UniquenessVerdict uniquenessVerdict(const UniquenessCheck& c) {
  const std::string examined = std::to_string(c.patterns) + " status pattern(s) examined";
  if (c.singularPatterns > 0)
    return {true, "possibly non-unique",
            "the Jacobian is singular on " + std::to_string(c.singularPatterns) + " of the " +
                examined};
  if (!c.sameSign)
    return {true, "possibly non-unique",
            "the determinants of the Jacobians around the state differ in sign" +
                (c.breakingPattern.empty() ? std::string()
                                           : " (it changes at " + c.breakingPattern + ")")};
  if (c.scale <= 1.0)
    return {true, "possibly non-unique",
            "mu >= mu_crit (critical factor " + numberText(c.scale) +
                " on mu): the Jacobians around the state agree in sign, so no other state lies "
                "close to it, but a slipping or separated state of the same contact set may "
                "coexist with it"};
  return {false, "locally unique",
          "the Jacobians of the " + examined + " agree in sign and " +
              (std::isinf(c.scale)
                   ? std::string("there is no critical mu")
                   : "mu < mu_crit (critical factor " + numberText(c.scale) + " on mu)")};
}

}  // namespace contactlab
