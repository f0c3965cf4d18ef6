#include "flexmb/model/model.h"

#include <algorithm>

#include "flexmb/bodies/ground.h"
#include "flexmb/common/error.h"

namespace flexmb {
namespace {

void CheckUnique(std::map<std::string, int>& index, const std::string& kind, const std::string& name,
                 int value) {
  if (name.empty()) throw InputError(kind + " without a name");
  if (!index.emplace(name, value).second)
    throw InputError("duplicate name: another " + kind + " is already called '" + name + "'",
                     {"", 0, kind + " '" + name + "'"});
}

int Find(const std::map<std::string, int>& index, const std::string& name) {
  auto it = index.find(name);
  return it == index.end() ? -1 : it->second;
}

}  // namespace

Model::Model() { AddBody(std::make_unique<Ground>()); }

int Model::AddBody(std::unique_ptr<Body> body) {
  const int idx = static_cast<int>(bodies.size());
  CheckUnique(body_index_, "body", body->name(), idx);
  bodies.push_back(std::move(body));
  return idx;
}

int Model::AddMarker(int body, const std::string& name, const Vec3& p_BM, const Mat3& R_BM, int node) {
  const int idx = static_cast<int>(markers.size());
  const std::string full = bodies.at(body)->name() + "." + name;
  CheckUnique(marker_index_, "marker", full, idx);
  if (!p_BM.allFinite() || !R_BM.allFinite())
    throw InputError("marker pose has non-finite entries", {"", 0, "marker '" + full + "'"});
  markers.push_back(Marker{full, body, node, bodies[body]->InternalPosition(p_BM), R_BM});
  return idx;
}

int Model::AddJoint(std::unique_ptr<Joint> joint, int marker_i, int marker_j) {
  const int idx = static_cast<int>(joints.size());
  CheckUnique(joint_index_, "joint", joint->name(), idx);
  joint->marker_i = marker_i;
  joint->marker_j = marker_j;
  joints.push_back(std::move(joint));
  return idx;
}

int Model::AddForce(std::unique_ptr<ForceElement> force, int marker_i, int marker_j) {
  const int idx = static_cast<int>(forces.size());
  CheckUnique(force_index_, "force", force->name(), idx);
  force->marker_i = marker_i;
  force->marker_j = marker_j;
  forces.push_back(std::move(force));
  return idx;
}

int Model::AddForce(std::unique_ptr<ForceElement> force, const std::vector<int>& m) {
  if (m.empty()) throw InputError("force element without markers", {"", 0, "force '" + force->name() + "'"});
  force->more_markers.assign(m.size() > 2 ? m.begin() + 2 : m.end(), m.end());
  return AddForce(std::move(force), m[0], m.size() > 1 ? m[1] : -1);
}

int Model::AddSensor(std::unique_ptr<Sensor> sensor) {
  const int idx = static_cast<int>(sensors.size());
  CheckUnique(sensor_index_, "sensor", sensor->name(), idx);
  sensors.push_back(std::move(sensor));
  return idx;
}

void Model::Finalize() {
  const int n_markers = static_cast<int>(markers.size());
  nq = nv = nc = 0;
  for (auto& b : bodies) {
    b->q_offset = nq;
    b->v_offset = nv;
    nq += b->nq();
    nv += b->nv();
  }
  std::vector<std::vector<int>> marker_nodes(bodies.size());
  for (const Marker& m : markers) {
    if (m.body < 0 || m.body >= static_cast<int>(bodies.size()))
      throw InputError("marker on a body that does not exist", {"", 0, "marker '" + m.name + "'"});
    if (m.node >= 0) marker_nodes[static_cast<size_t>(m.body)].push_back(m.node);
  }
  for (size_t b = 0; b < bodies.size(); ++b) {
    std::vector<int>& nodes = marker_nodes[b];
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    bodies[b]->UseMarkerNodes(nodes);
  }
  for (auto& j : joints) {
    const ErrorContext ctx{"", 0, "joint '" + j->name() + "'"};
    if (j->marker_i < 0 || j->marker_i >= n_markers || j->marker_j < 0 || j->marker_j >= n_markers)
      throw InputError("joint needs two existing markers", ctx);
    if (markers[j->marker_i].body == markers[j->marker_j].body)
      throw InputError("both markers are on body '" + bodies[markers[j->marker_i].body]->name() +
                           "': a joint must connect two different bodies",
                       ctx);
    j->lambda_offset = nc;
    nc += j->NumEquations();
  }
  for (auto& f : forces) {
    const ErrorContext ctx{"", 0, "force '" + f->name() + "'"};
    if (f->marker_i < 0 || f->marker_i >= n_markers || f->marker_j >= n_markers)
      throw InputError("force element on a marker that does not exist", ctx);
    if (f->NumMarkers() > kMaxForceMarkers)
      throw InputError("force element on " + std::to_string(f->NumMarkers()) + " markers (at most " +
                           std::to_string(kMaxForceMarkers) + ")",
                       ctx);
    for (int mk : f->more_markers)
      if (mk < 0 || mk >= n_markers || f->marker_j < 0)
        throw InputError("force element on a marker that does not exist", ctx);
  }
  finalized_ = true;
}

int Model::FindBody(const std::string& n) const { return Find(body_index_, n); }
int Model::FindMarker(const std::string& n) const { return Find(marker_index_, n); }
int Model::FindJoint(const std::string& n) const { return Find(joint_index_, n); }
int Model::FindForce(const std::string& n) const { return Find(force_index_, n); }

State Model::InitialState() const {
  State s;
  s.q.setZero(nq);
  s.v.setZero(nv);
  s.lambda.setZero(nc);
  for (const auto& b : bodies) b->InitialCoordinates(s.q.data() + b->q_offset, s.v.data() + b->v_offset);
  return s;
}

}  // namespace flexmb
