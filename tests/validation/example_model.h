#pragma once
/// \file example_model.h
/// Helpers of the validation tests: load a model file from examples/, read
/// its sensors by name while it runs, unwrap angles in time.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "flexmb/model_file/model_file.h"
#include "flexmb/model/model.h"
#include "flexmb/solver/simulator.h"

namespace flexmb::validation {

/// Loads examples/<name>/model.yaml from the source tree (finalized model).
inline std::unique_ptr<Model> LoadExample(const std::string& name) {
  return LoadModelFile(std::string(FLEXMB_SOURCE_DIR) + "/examples/" + name + "/model.yaml");
}

/// One component of a sensor of the model, read by the names used in the
/// model file and in results.csv ("<sensor>.<component>").
class SensorValue {
 public:
  /// Throws std::runtime_error (failing the test) if the sensor or the
  /// component does not exist.
  SensorValue(const Model& model, const std::string& sensor, const std::string& component)
      : model_(model) {
    for (size_t k = 0; k < model.sensors.size(); ++k) {
      if (model.sensors[k]->name() != sensor) continue;
      sensor_ = model.sensors[k].get();
      const std::vector<std::string> c = sensor_->Components();
      for (size_t i = 0; i < c.size(); ++i)
        if (c[i] == component) component_ = static_cast<int>(i);
      out_.resize(c.size());
    }
    if (!sensor_ || component_ < 0)
      throw std::runtime_error("model has no sensor component " + sensor + "." + component);
  }
  /// The value at a state whose workspace is up to date (Simulator observer).
  double operator()(const State& s, const Workspace& ws) const {
    sensor_->Evaluate(model_, s, ws, out_.data());
    return out_[component_];
  }

 private:
  const Model& model_;
  const Sensor* sensor_ = nullptr;
  int component_ = -1;
  mutable std::vector<double> out_;
};

/// Continuous angle from samples wrapped to (-pi, pi]; the samples must be
/// dense enough that the true change between two is below pi.
class Unwrapper {
 public:
  double operator()(double wrapped) {
    if (!started_) {
      started_ = true;
    } else {
      double d = wrapped - last_;
      if (d > std::numbers::pi) turns_ -= 2 * std::numbers::pi;
      if (d < -std::numbers::pi) turns_ += 2 * std::numbers::pi;
    }
    last_ = wrapped;
    return wrapped + turns_;
  }

 private:
  bool started_ = false;
  double last_ = 0.0, turns_ = 0.0;
};

/// Total mechanical energy of the model's bodies (kinetic + gravity) [J],
/// computed from the bodies directly (independent of the energy sensors).
inline double BodyEnergy(const Model& m, const State& s) {
  double e = 0.0;
  for (const auto& b : m.bodies) {
    if (b->nv() == 0) continue;
    e += b->KineticEnergy(s.q.data() + b->q_offset, s.v.data() + b->v_offset) +
         b->GravityPotential(s.q.data() + b->q_offset, m.gravity_W);
  }
  return e;
}

/// x as text with all its digits (%.17g), for numbers written into model
/// text by a test.
inline std::string ExactNumber(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

}  // namespace flexmb::validation
