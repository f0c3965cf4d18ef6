#include "flexmb/forces/force_element.h"

#include "flexmb/common/error.h"

namespace flexmb {

void ForceElement::EvaluateMarkers(const MarkerState* const*, double, ForceEval&) const {
  throw InputError(std::string("force element of type ") + type() + " acts on two markers at most, not " +
                       std::to_string(NumMarkers()),
                   {"", 0, "force '" + name() + "'"});
}

}  // namespace flexmb
