#include "flexmb/sensors/force_sensors.h"

#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"

namespace flexmb {

void ForceElementSensor::Evaluate(const Model& model, const State&, const Workspace& ws, double* out) const {
  const Vec6 w = MarkerWrench(ws.forces[force_], model.forces[force_]->NumMarkers(), 0);
  for (int k = 0; k < 6; ++k) out[k] = w(k);
  out[6] = w.head<3>().norm();
}

}  // namespace flexmb
