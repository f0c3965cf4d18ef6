#include "flexmb/sensors/flexible_sensors.h"

#include <algorithm>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/common/error.h"
#include "flexmb/model/model.h"
#include "flexmb/reduction/stress_modes.h"

namespace flexmb {
namespace {

// the body, known to be flexible when the sensor was made
const FlexibleBody& Flexible(const Model& model, int body) {
  return static_cast<const FlexibleBody&>(*model.bodies[body]);
}

// values of one element's rows of a stress table (at most 2 points x 6)
using ElementValues = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 12, 1>;
using Vec6d = Eigen::Matrix<double, 6, 1>;

void EvaluateRows(const reduction::StressTable& t, int k, const double* w, ElementValues& out) {
  const Eigen::Index rows = static_cast<Eigen::Index>(t.Locations()) * t.Components();
  out.resize(rows);
  out.noalias() = t.modes.middleRows(t.Row(k, 0, 0), rows) * Eigen::Map<const VecX>(w, t.modes.cols());
}

// stress tensor in body axes of point l of element k from its values
Mat3 BodyTensor(const reduction::StressTable& t, int k, int l, const ElementValues& v, bool shell) {
  const int c = l * t.Components();
  Mat3 s;
  if (shell) {
    s << v(c), v(c + 2), 0.0, v(c + 2), v(c + 1), 0.0, 0.0, 0.0, 0.0;
    const Mat3& A = t.axes[k];
    return A * s * A.transpose();
  }
  s << v(c), v(c + 3), v(c + 5), v(c + 3), v(c + 1), v(c + 4), v(c + 5), v(c + 4), v(c + 2);
  return s;
}

const char* const kTensorNames[6] = {"sxx", "syy", "szz", "sxy", "syz", "szx"};

}  // namespace

ModalCoordinatesSensor::ModalCoordinatesSensor(std::string name, int body, const FlexibleBody& flexible)
    : Sensor(std::move(name)), body_(body), n_(flexible.modes()) {}

std::vector<std::string> ModalCoordinatesSensor::Components() const {
  std::vector<std::string> c;
  for (int i = 0; i < n_; ++i) c.push_back("w" + std::to_string(i + 1));
  return c;
}

void ModalCoordinatesSensor::Evaluate(const Model& model, const State& state, const Workspace&,
                                      double* out) const {
  const Body& b = *model.bodies[body_];
  for (int i = 0; i < n_; ++i) out[i] = state.q(b.q_offset + 7 + i);
}

void NodeDisplacementSensor::Evaluate(const Model& model, const State& state, const Workspace&,
                                      double* out) const {
  const FlexibleBody& b = Flexible(model, body_);
  const Vec3 u = b.NodeDisplacement(state.q.data() + b.q_offset, node_);
  for (int k = 0; k < 3; ++k) out[k] = u(k);
}

void NodePositionSensor::Evaluate(const Model& model, const State& state, const Workspace&,
                                  double* out) const {
  const FlexibleBody& b = Flexible(model, body_);
  const Vec3 p = b.NodePosition(state.q.data() + b.q_offset, node_);
  for (int k = 0; k < 3; ++k) out[k] = p(k);
}

void NodeVelocitySensor::Evaluate(const Model& model, const State& state, const Workspace&,
                                  double* out) const {
  const FlexibleBody& b = Flexible(model, body_);
  const Vec3 p = b.NodeVelocity(state.q.data() + b.q_offset, state.v.data() + b.v_offset, node_);
  for (int k = 0; k < 3; ++k) out[k] = p(k);
}

ElementStressSensor::ElementStressSensor(std::string name, int body, const FlexibleBody& flexible, int element)
    : Sensor(std::move(name)), body_(body), table_(nullptr) {
  const reduction::StressModes& sm = flexible.reduced().stress;
  for (const reduction::StressTable* t : {&sm.shell, &sm.beam, &sm.solid}) {
    const auto it = std::lower_bound(t->elements.begin(), t->elements.end(), element);
    if (it != t->elements.end() && *it == element && t->modes.cols() == flexible.modes()) {
      table_ = t;
      k_ = static_cast<int>(it - t->elements.begin());
    }
  }
  if (!table_)
    throw InputError("element index " + std::to_string(element) + " has no stress modes",
                     {"", 0, "flexible body '" + flexible.name() + "'"});
  von_mises_ = table_ != &sm.beam;
  for (const std::string& l : table_->locations) {
    for (const std::string& c : table_->components) names_.push_back(l + "_" + c);
    if (von_mises_) names_.push_back(l + "_von_mises");
  }
}

void ElementStressSensor::Evaluate(const Model& model, const State& state, const Workspace&,
                                   double* out) const {
  const FlexibleBody& b = Flexible(model, body_);
  ElementValues v;
  EvaluateRows(*table_, k_, state.q.data() + b.q_offset + 7, v);
  const int nc = table_->Components();
  int o = 0;
  for (int l = 0; l < table_->Locations(); ++l) {
    const auto point = v.segment(l * nc, nc);
    for (int c = 0; c < nc; ++c) out[o++] = point(c);
    if (!von_mises_) continue;
    out[o++] = nc == 3 ? reduction::VonMises(Vec3(point)) : reduction::VonMises(Vec6d(point));
  }
}

NodeStressSensor::NodeStressSensor(std::string name, int body, const FlexibleBody& flexible, int node)
    : Sensor(std::move(name)), body_(body), table_(nullptr) {
  const reduction::ReducedBody& r = flexible.reduced();
  for (const reduction::StressTable* t : {&r.stress.shell, &r.stress.solid}) {
    if (table_ || t->modes.cols() != flexible.modes()) continue;
    for (size_t k = 0; k < t->elements.size(); ++k) {
      const std::vector<int>& nodes = r.mesh.elements[t->elements[k]].nodes;
      if (std::find(nodes.begin(), nodes.end(), node) != nodes.end()) ks_.push_back(static_cast<int>(k));
    }
    if (!ks_.empty()) table_ = t, shell_ = t == &r.stress.shell;
  }
  if (!table_)
    throw InputError("node index " + std::to_string(node) + " has no shell or solid element with stress modes",
                     {"", 0, "flexible body '" + flexible.name() + "'"});
  for (const std::string& l : table_->locations) {
    for (const char* c : kTensorNames) names_.push_back(l + "_" + c);
    names_.push_back(l + "_von_mises");
  }
}

void NodeStressSensor::Evaluate(const Model& model, const State& state, const Workspace&,
                                double* out) const {
  const FlexibleBody& b = Flexible(model, body_);
  const double* w = state.q.data() + b.q_offset + 7;
  ElementValues v;
  for (int l = 0; l < table_->Locations(); ++l) {
    Mat3 s = Mat3::Zero();
    for (const int k : ks_) {
      EvaluateRows(*table_, k, w, v);
      s += BodyTensor(*table_, k, l, v, shell_);
    }
    s /= static_cast<double>(ks_.size());
    Vec6d t;
    t << s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(2, 0);
    double* o = out + 7 * l;
    for (int c = 0; c < 6; ++c) o[c] = t(c);
    o[6] = reduction::VonMises(t);
  }
}

void StrainEnergySensor::Evaluate(const Model& model, const State& state, const Workspace&,
                                  double* out) const {
  const FlexibleBody& b = Flexible(model, body_);
  out[0] = b.StrainEnergy(state.q.data() + b.q_offset);
}

}  // namespace flexmb
