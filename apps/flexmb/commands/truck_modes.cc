#include "apps/flexmb/commands/truck_modes.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <map>
#include <numbers>
#include <tuple>

#include "apps/flexmb/commands/lane_change.h"
#include "flexmb/common/error.h"
#include "flexmb/solver/assembler.h"
#include "flexmb/solver/initial_conditions.h"
#include "flexmb/solver/statics.h"

namespace flexmb::cli {
namespace {

using TruckModesCx = std::complex<double>;

// the lane-change file's frame model and road friction (the file is
// checked by LoadLaneChangeTruck first)
void TruckModesFileSettings(const std::string& path, std::string& frame, double& mu) {
  const YAML::Node t = YAML::LoadFile(path)["lane_change_test"];
  frame = t["frame"] ? t["frame"].as<std::string>() : "rigid";
  mu = t["road_mu"] ? t["road_mu"].as<double>() : 0.8;
}

// 0: sprung parts, 1: the steered axles' group ("front axle"), 2: the
// other axles' ("rear axle"; TruckHandles::body_axle)
int TruckModesGroup(const vehicle::TruckHandles& h, size_t body) {
  const int axle = body < h.body_axle.size() ? h.body_axle[body] : -1;
  return axle < 0 ? 0 : axle < h.steered_axles ? 1 : 2;
}

// velocity coordinates of the rigid motions of the bodies of group g about
// the point c: columns translation x, y, z, rotation about x, y, z (world)
MatX TruckModesRigidBasis(const Model& m, const vehicle::TruckHandles& h, const State& s, int g, const Vec3& c) {
  MatX G = MatX::Zero(m.nv, 6);
  for (size_t b = 1; b < m.bodies.size(); ++b) {
    const Body& body = *m.bodies[b];
    if (body.nv() < 6 || TruckModesGroup(h, b) != g) continue;
    const double* q = s.q.data() + body.q_offset;
    const Vec3 p(q[0], q[1], q[2]);
    const Mat3 R = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized().toRotationMatrix();
    for (int k = 0; k < 3; ++k) {
      const Vec3 e = Vec3::Unit(k);
      G.block<3, 1>(body.v_offset, k) = e;
      G.block<3, 1>(body.v_offset, 3 + k) = e.cross(p - c);
      G.block<3, 1>(body.v_offset + 3, 3 + k) = R.transpose() * e;
    }
  }
  return G;
}

// static equilibrium of the standing truck (TruckStaticsSettings: nothing
// holds its position, heading and wheel spins at rest but the tires' slip
// damping); a residual no displacement removes (a creep) is named in
// `warnings`
void TruckModesStatics(const Model& m, State& s, Workspace& ws, const std::string& path,
                       std::vector<std::string>& warnings) {
  StaticsResult r;
  try {
    r = SolveStatics(m, s, ws, vehicle::TruckStaticsSettings());
  } catch (const NumericalError& e) {
    throw NumericalError(std::string("the standing truck has no static equilibrium: ") + e.what(), {path, 0, "truck"});
  }
  if (!r.creep.empty())
    warnings.push_back("the standing truck creeps: a residual force of " + std::to_string(r.residual) + " at " +
                       r.creep + " that no static displacement removes; linearized about the state reached");
}

const char* const kTruckModesSprung[6] = {"longitudinal", "lateral", "bounce", "roll", "pitch", "yaw"};
const char* const kTruckModesAxle[6] = {"fore-aft", "lateral", "hop", "tramp", "wind-up", "yaw"};

}  // namespace

void StandingTruckState(const std::string& path, const std::string& frame, const std::string& at,
                        AnalysisModel& am, VecX& a, std::vector<std::string>& warnings, StandingTruck& truck) {
  if (at != "statics" && at != "initial")
    throw InputError("--at must be statics or initial for a lane-change (truck) file, got '" + at + "'",
                     {path, 0, "modes"});
  truck.data = vehicle::LoadLaneChangeTruck(path);
  double mu = 0.8;
  TruckModesFileSettings(path, truck.frame, mu);
  if (!frame.empty()) truck.frame = frame;
  if (truck.frame != "rigid" && truck.frame != "elastic")
    throw InputError("frame must be 'rigid' or 'elastic', got '" + truck.frame + "'", {path, 0, "frame"});
  am.model = std::make_unique<Model>();
  Model& m = *am.model;
  m.name = "truck_standing";
  if (truck.frame == "elastic")
    truck.data.elastic_frame =
        vehicle::ReduceTruckFrame(truck.data, vehicle::LaneChangeFrameReduction(path), -m.gravity_W.z());
  auto zero = std::make_shared<double>(0.0);
  truck.handles = vehicle::BuildTruck(truck.data, 0.0, mu, zero, zero, m, nullptr);
  m.Finalize();
  am.state = m.InitialState();
  {
    AnalysisWarnings collect(warnings);
    am.report = MakeConsistent(m, am.state, am.ws);
  }
  if (at == "initial") {
    a = am.ws.vdot;
    return;
  }
  TruckModesStatics(m, am.state, am.ws, path, warnings);
  a = VecX::Zero(m.nv);
}

std::vector<TruckModeName> NameTruckModes(const Model& m, const vehicle::TruckHandles& h, const State& s,
                                          const LinearizedSystem& sys, const std::vector<SystemMode>& modes,
                                          const reduction::ReducedBody* frame_body) {
  // each group's rigid basis about its centre of mass c (from the basis
  // about the origin: the 6 x 6 rigid mass matrix's coupling block is
  // m skew(c) transposed)
  std::array<MatX, 3> G;
  std::array<MatX, 3> GMG;
  for (int g = 0; g < 3; ++g) {
    const MatX G0 = TruckModesRigidBasis(m, h, s, g, Vec3::Zero());
    const MatX A0 = G0.transpose() * sys.M * G0;
    const double mass = A0(0, 0);
    const Vec3 c = mass > 0 ? Vec3(Vec3(-A0(2, 4), -A0(0, 5), -A0(1, 3)) / mass) : Vec3(Vec3::Zero());
    G[g] = TruckModesRigidBasis(m, h, s, g, c);
    GMG[g] = G[g].transpose() * sys.M * G[g];
  }
  std::vector<std::string> kinds;
  if (frame_body) kinds = FrameModeKinds(*frame_body);
  const MatX Ks = 0.5 * (sys.K + sys.K.transpose());
  std::vector<TruckModeName> names;
  for (const SystemMode& md : modes) {
    const Eigen::VectorXcd x = md.shape.cast<TruckModesCx>() + TruckModesCx(0, 1) * md.shape_imag.cast<TruckModesCx>();
    const Eigen::VectorXcd Mx = sys.M.cast<TruckModesCx>() * x;
    const double total = std::max(x.dot(Mx).real(), 1e-300);  // dot: x^H M x
    TruckModeName best;
    Eigen::VectorXcd rest = x;
    for (int g = 0; g < 3; ++g) {
      if (GMG[g](0, 0) <= 0) continue;
      const Eigen::VectorXcd b = G[g].transpose().cast<TruckModesCx>() * Mx;
      const Eigen::VectorXcd alpha = GMG[g].cast<TruckModesCx>().ldlt().solve(b);
      rest -= G[g].cast<TruckModesCx>() * alpha;
      for (int k = 0; k < 6; ++k) {
        const double e = std::norm(alpha(k)) * GMG[g](k, k) / total;
        if (e > best.share)
          best.share = e, best.name = g == 0 ? kTruckModesSprung[k]
                                             : std::string(g == 1 ? "front axle " : "rear axle ") + kTruckModesAxle[k];
      }
    }
    const Eigen::VectorXcd Mr = sys.M.cast<TruckModesCx>() * rest;
    for (size_t b = 1; b < m.bodies.size(); ++b) {
      const Body& body = *m.bodies[b];
      const int n = body.nv();
      if (n == 0) continue;
      const double e = rest.segment(body.v_offset, n).dot(Mr.segment(body.v_offset, n)).real() / total;
      if (e > best.share) best.share = e, best.name = body.name() + " on its mounts";
    }
    // elastic frame: strain energy of its free-free modes against the potential energy
    if (frame_body && h.elastic) {
      const Body& fb = *m.bodies[h.frame_body];
      const int n = fb.nv() - 6;
      double strain = 0.0, top = -1.0;
      for (int j = 0; j < n; ++j) {
        const double e = frame_body->stiffness(j, j) * std::norm(x(fb.v_offset + 6 + j));
        strain += e;
        if (e > top) top = e, best.frame_mode = j;
      }
      const double pot = x.dot(Ks.cast<TruckModesCx>() * x).real();
      best.frame_strain_share = pot > 0 ? strain / pot : 0.0;
      if (best.frame_strain_share >= 0.5 && best.frame_mode >= 0) {
        best.name = "frame " + kinds[static_cast<size_t>(best.frame_mode)];
        best.share = top / pot;
      }
    }
    names.push_back(best);
  }
  return names;
}

std::vector<std::string> FrameModeKinds(const reduction::ReducedBody& body) {
  // mirror pairs (left node y > 0, right node at (x, -y, z)) by rounded coordinates
  std::map<std::tuple<long long, long long, long long>, int> right;
  const auto key = [](const Vec3& p) {
    return std::make_tuple(std::llround(p.x() * 1e4), std::llround(std::abs(p.y()) * 1e4), std::llround(p.z() * 1e4));
  };
  const auto& nodes = body.mesh.nodes;
  for (size_t k = 0; k < nodes.size(); ++k)
    if (nodes[k].x.y() < -1e-6) right[key(nodes[k].x)] = static_cast<int>(k);
  std::vector<std::pair<int, int>> pairs;
  for (size_t k = 0; k < nodes.size(); ++k) {
    if (nodes[k].x.y() <= 1e-6) continue;
    const auto it = right.find(key(nodes[k].x));
    if (it != right.end()) pairs.emplace_back(static_cast<int>(k), it->second);
  }
  std::vector<std::string> kinds;
  for (Eigen::Index j = 0; j < body.modes.cols(); ++j) {
    double bend = 0, twist = 0, lateral = 0, all = 0;
    for (const auto& [l, r] : pairs) {
      const Vec3 ul = body.modes.block(6 * static_cast<Eigen::Index>(l), j, 3, 1);
      const Vec3 ur = body.modes.block(6 * static_cast<Eigen::Index>(r), j, 3, 1);
      bend += std::pow(ul.z() + ur.z(), 2);
      twist += std::pow(ul.z() - ur.z(), 2);
      lateral += std::pow(ul.y() + ur.y(), 2);
      all += 2.0 * (ul.squaredNorm() + ur.squaredNorm());
    }
    const double other = all - bend - twist - lateral;
    const double top = std::max({bend, twist, lateral, other});
    kinds.push_back(top == twist ? "torsion" : top == bend ? "vertical bending" : top == lateral ? "lateral bending" : "other");
  }
  return kinds;
}

}  // namespace flexmb::cli

namespace flexmb::cli {

std::vector<FrameFreeMode> FrameFreeModes(const reduction::ReducedBody& body) {
  const std::vector<std::string> kinds = FrameModeKinds(body);
  std::vector<FrameFreeMode> out;
  for (size_t j = 0; j < kinds.size(); ++j) {
    const auto i = static_cast<Eigen::Index>(j);
    out.push_back({std::sqrt(std::max(0.0, body.stiffness(i, i) / body.mass(i, i))) / (2.0 * std::numbers::pi),
                   kinds[j]});
  }
  return out;
}

}  // namespace flexmb::cli
