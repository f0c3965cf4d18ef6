#include "flexmb/sensors/force_sensors.h"

#include "flexmb/model/workspace.h"

namespace flexmb {

void ForceElementSensor::Evaluate(const Model&, const State&, const Workspace& ws, double* out) const {
  const Vec12& w = ws.forces[force_].wrench;
  for (int k = 0; k < 6; ++k) out[k] = w(k);
  out[6] = w.head<3>().norm();
}

}  // namespace flexmb
