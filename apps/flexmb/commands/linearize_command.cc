#include "apps/flexmb/commands/linearize_command.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "apps/flexmb/commands/analysis_support.h"
#include "apps/flexmb/commands/linearize_drivers.h"
#include "flexmb/common/json_text.h"
#include "flexmb/forces/joint_motor.h"
#include "flexmb/solver/assembler.h"
#include "flexmb/solver/linearization.h"
#include "flexmb/solver/statics.h"

namespace flexmb::cli {
namespace {

// the generalized forces (nv x m) of the inputs and their names
MatX LinearizeInputs(const Model& m, const Workspace& ws, const std::vector<std::string>& names,
                     std::vector<std::string>& labels) {
  std::vector<VecX> cols;
  // adds J_i^T w_i (+ J_j^T w_j) for a wrench (f_i, m_i, f_j, m_j)
  const auto add = [&](const ForceElement& f, const Vec12& w, const std::string& label) {
    VecX q = VecX::Zero(m.nv);
    const MarkerState& mi = ws.markers[f.marker_i];
    q.segment(mi.v_offset, mi.nv) += mi.J.transpose() * w.head<6>();
    if (f.marker_j >= 0) {
      const MarkerState& mj = ws.markers[f.marker_j];
      q.segment(mj.v_offset, mj.nv) += mj.J.transpose() * w.tail<6>();
    }
    cols.push_back(q);
    labels.push_back(label);
  };
  for (const std::string& name : names) {
    const ForceElement* f = nullptr;
    for (const auto& e : m.forces)
      if (e->name() == name) f = e.get();
    if (!f) throw InputError("--inputs: no force element named '" + name + "' (nor a motion driver)");
    const std::string type = f->type();
    if (type == "point_force" || type == "point_torque") {
      const int off = type == "point_force" ? 0 : 3;
      const char* axes[3] = {"x", "y", "z"};
      for (int k = 0; k < 3; ++k) {
        Vec12 w = Vec12::Zero();
        w(off + k) = 1.0;
        add(*f, w, name + "." + (off ? "m" : "f") + axes[k]);
      }
    } else if (type == "spring_damper") {
      const Vec3 d = ws.markers[f->marker_j].p_WM - ws.markers[f->marker_i].p_WM;
      if (!(d.norm() > 0.0)) throw NumericalError("--inputs: the markers of '" + name + "' coincide");
      const Vec3 u = d.normalized();
      Vec12 w = Vec12::Zero();
      w.head<3>() = u;
      w.segment<3>(6) = -u;
      add(*f, w, name + ".tension");
    } else if (const auto* motor = dynamic_cast<const JointMotor*>(f)) {
      // one unit of the motor's torque [N m] or force [N] on its axis, as
      // JointMotor::Evaluate applies it
      const MarkerState& mi = ws.markers[f->marker_i];
      const Vec3 a = motor->joint()->CoordinateAxis(motor->coordinate(), mi);
      const bool angle = motor->joint()->CoordinateIsAngle(motor->coordinate());
      Vec12 w = Vec12::Zero();
      if (angle) {
        w.segment<3>(3) = -a;
        w.segment<3>(9) = a;
      } else {
        w.head<3>() = -a;
        w.segment<3>(3) = a.cross(ws.markers[f->marker_j].p_WM - mi.p_WM);
        w.segment<3>(6) = a;
      }
      add(*f, w, name + (angle ? ".torque" : ".force"));
    } else {
      throw InputError("--inputs: force element '" + name + "' of type " + type +
                       " cannot be an input (point_force, point_torque, spring_damper or joint_motor)");
    }
  }
  MatX Q(m.nv, static_cast<int>(cols.size()));
  for (size_t k = 0; k < cols.size(); ++k) Q.col(k) = cols[k];
  return Q;
}

// the components of the chosen sensors at s (accelerations a in ws.vdot)
VecX LinearizeSensors(const Model& m, const State& s, Workspace& ws, const VecX& a, const std::vector<int>& sensors,
                      int count) {
  EvaluateMarkers(m, s, ws);
  EvaluateConstraints(m, s, ws);
  EvaluateForces(m, s, ws, false);
  ws.vdot = a;
  VecX y(count);
  int k = 0;
  for (int i : sensors) {
    const int c = static_cast<int>(m.sensors[i]->Components().size());
    m.sensors[i]->Evaluate(m, s, ws, y.data() + k);
    k += c;
  }
  return y;
}

void LinearizeWriteMatrix(const std::filesystem::path& p, const MatX& A) {
  std::string t = "%%MatrixMarket matrix array real general\n" + std::to_string(A.rows()) + " " +
                  std::to_string(A.cols()) + "\n";
  char buf[40];
  for (Eigen::Index j = 0; j < A.cols(); ++j)
    for (Eigen::Index i = 0; i < A.rows(); ++i) {
      std::snprintf(buf, sizeof buf, "%.17g\n", A(i, j));
      t += buf;
    }
  WriteAnalysisFile(p.string(), t);
}

std::string LinearizeNames(const std::vector<std::string>& v) {
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + io::JsonString(v[i]);
  return s + "]";
}

}  // namespace

int LinearizeCommand(const LinearizeCommandOptions& opt) { return LinearizeAnalysis(opt).code; }

LinearizeResult LinearizeAnalysis(const LinearizeCommandOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  LinearizeResult out;
  std::vector<std::string>& warnings = out.warnings;
  std::string status = "ok", message;
  int code = 0, n_states = 0, n_inputs = 0, n_outputs = 0;
  AnalysisModel am;
  if (!CreateAnalysisDir(opt.out_dir, opt.err)) {
    out.code = 2, out.error_kind = "InputError", out.message = opt.out_dir + ": cannot create the output directory";
    return out;
  }
  const std::filesystem::path dir(opt.out_dir);
  try {
    if (opt.inputs.empty()) throw InputError("--inputs: name at least one force element or driver");
    VecX a0;
    const Model& m =
        AnalysisLinearizationModel(opt.model_path, opt.model_text, opt.at, opt.time, opt.source, am, a0, warnings);
    if (opt.err)
      for (const std::string& w : warnings) std::fprintf(opt.err, "warning: %s\n", w.c_str());
    LinearizedSystem L = Linearize(m, am.state, a0, am.ws);
    std::vector<int> indep;
    ReduceWithBasis(L, PartitionedNullSpace(L.B, std::max(1e-12, m.solver.redundancy_tol), indep));
    const int n = static_cast<int>(L.N.cols());
    // inputs: force elements (generalized forces Qu) and drivers (their
    // accelerations, with their values and rates appended to the state)
    std::vector<std::string> force_names, driver_names, input_names;
    std::vector<std::pair<bool, int>> order;  // (driver, index among its kind) per named input
    for (const std::string& name : opt.inputs) {
      const bool drv = IsLinearizeDriver(m, name);
      order.emplace_back(drv, static_cast<int>(drv ? driver_names.size() : force_names.size()));
      (drv ? driver_names : force_names).push_back(name);
    }
    EvaluateMarkers(m, am.state, am.ws);
    std::vector<std::string> force_labels;
    std::vector<int> force_first;  // first input column of each force element
    MatX Qf(m.nv, 0);
    {
      std::vector<MatX> parts;
      for (const std::string& name : force_names) {
        force_first.push_back(static_cast<int>(force_labels.size()));
        parts.push_back(LinearizeInputs(m, am.ws, {name}, force_labels));
      }
      force_first.push_back(static_cast<int>(force_labels.size()));
      Qf.resize(m.nv, force_first.back());
      for (size_t i = 0; i < parts.size(); ++i) Qf.middleCols(force_first[i], parts[i].cols()) = parts[i];
    }
    const LinearizeDriverSet drivers = LinearizeDriverInputs(m, am.ws, L, indep, driver_names);
    const int nd = static_cast<int>(driver_names.size());
    // Qu (nv x nu) in the named order; driver columns are zero here (their
    // accelerations enter through -M P), drv_col[d] their input column
    std::vector<int> drv_col(static_cast<size_t>(nd));
    MatX Qu(m.nv, static_cast<int>(force_labels.size()) + nd);
    {
      int c = 0;
      for (const auto& o : order) {
        if (o.first) {
          Qu.col(c).setZero();
          drv_col[static_cast<size_t>(o.second)] = c++;
          input_names.push_back(driver_names[static_cast<size_t>(o.second)] + ".acceleration");
        } else {
          const int a = force_first[static_cast<size_t>(o.second)], b = force_first[static_cast<size_t>(o.second) + 1];
          Qu.middleCols(c, b - a) = Qf.middleCols(a, b - a);
          for (int i = a; i < b; ++i) input_names.push_back(force_labels[static_cast<size_t>(i)]);
          c += b - a;
        }
      }
    }
    // outputs
    std::vector<int> sensors;
    std::vector<std::string> output_names;
    if (opt.outputs.empty())
      for (size_t i = 0; i < m.sensors.size(); ++i) sensors.push_back(static_cast<int>(i));
    for (const std::string& name : opt.outputs) {
      int found = -1;
      for (size_t i = 0; i < m.sensors.size(); ++i)
        if (m.sensors[i]->name() == name) found = static_cast<int>(i);
      if (found < 0) throw InputError("--outputs: no sensor named '" + name + "'");
      sensors.push_back(found);
    }
    for (int i : sensors)
      for (const std::string& c : m.sensors[i]->Components()) output_names.push_back(m.sensors[i]->name() + "." + c);
    const int p = static_cast<int>(output_names.size()), nu = static_cast<int>(Qu.cols());
    if (p == 0) throw InputError("--outputs: the model has no sensors to output");
    // A, B: Mr z'' + Cr z' + Kr z = N^T (Qu u - K P df - C P df' - M P u_d),
    // the state (z, z', df, df') (linearize_drivers.h)
    const Eigen::LLT<MatX> llt(L.Mr);
    const MatX MiK = llt.solve(L.Kr), MiC = llt.solve(L.Cr), MiQ = llt.solve(L.N.transpose() * Qu);
    const int ns = 2 * n + 2 * nd;
    MatX A = MatX::Zero(ns, ns), B = MatX::Zero(ns, nu);
    A.block(0, n, n, n).setIdentity();
    A.block(n, 0, n, n) = -MiK;
    A.block(n, n, n, n) = -MiC;
    B.middleRows(n, n) = MiQ;
    if (nd > 0) {
      const MatX& P = drivers.P;
      A.block(n, 2 * n, n, nd) = -llt.solve(L.N.transpose() * L.K * P);
      A.block(n, 2 * n + nd, n, nd) = -llt.solve(L.N.transpose() * L.C * P);
      A.block(2 * n, 2 * n + nd, nd, nd).setIdentity();
      const MatX MiMP = llt.solve(L.N.transpose() * L.M * P);
      for (int d = 0; d < nd; ++d) {
        B.block(n, drv_col[static_cast<size_t>(d)], n, 1) = -MiMP.col(d);
        B(2 * n + nd + d, drv_col[static_cast<size_t>(d)]) = 1.0;
      }
    }
    // C, D by central differences of the sensors along the states and inputs
    MatX C(p, ns), D(p, nu);
    State st = am.state;
    const State s0 = am.state;
    const double eps = 1e-6;
    VecX dx(m.nv);
    const MatX& P = drivers.P;
    for (int k = 0; k < ns + nu; ++k) {
      VecX y[2];
      for (int side = 0; side < 2; ++side) {
        const double h = side ? -eps : eps;
        VecX x = VecX::Zero(ns), u = VecX::Zero(nu);
        if (k < ns) x(k) = h; else u(k - ns) = h;
        dx = L.N * x.head(n) + P * x.segment(2 * n, nd);
        RetractAll(m, s0.q, dx, st.q);
        st.v = s0.v + L.N * x.segment(n, n) + P * x.tail(nd);
        const VecX a = a0 + L.N * (A.middleRows(n, n) * x + B.middleRows(n, n) * u) +
                       P * (A.bottomRows(nd) * x + B.bottomRows(nd) * u);
        y[side] = LinearizeSensors(m, st, am.ws, a, sensors, p);
      }
      const VecX col = (y[0] - y[1]) / (2.0 * eps);
      if (k < ns) C.col(k) = col; else D.col(k - ns) = col;
    }
    if (!A.allFinite() || !B.allFinite() || !C.allFinite() || !D.allFinite())
      throw NumericalError("linearize: the state-space matrices are not finite");
    std::vector<std::string> state_names;
    for (int k = 0; k < n; ++k) state_names.push_back("dx " + VelocityCoordinateName(m, indep[k]));
    for (int k = 0; k < n; ++k) state_names.push_back("v " + VelocityCoordinateName(m, indep[k]));
    for (const std::string& d : driver_names) state_names.push_back("driver " + d + ".position");
    for (const std::string& d : driver_names) state_names.push_back("driver " + d + ".velocity");
    const VecX y0 = LinearizeSensors(m, s0, am.ws, a0, sensors, p);
    std::string js = "{\n  \"model\": " + io::JsonString(opt.model_path) + ",\n  \"at\": " + io::JsonString(opt.at) +
                     ",\n  \"time\": " + io::JsonNumber(s0.t) + ",\n  \"states\": " + LinearizeNames(state_names) +
                     ",\n  \"inputs\": " + LinearizeNames(input_names) + ",\n  \"outputs\": " +
                     LinearizeNames(output_names) + ",\n  \"output_values\": " + io::JsonArray(y0) +
                     ",\n  \"files\": {\"A\": \"A.mtx\", \"B\": \"B.mtx\", \"C\": \"C.mtx\", \"D\": \"D.mtx\"}\n}\n";
    if (!opt.out_dir.empty()) {
      LinearizeWriteMatrix(dir / "A.mtx", A);
      LinearizeWriteMatrix(dir / "B.mtx", B);
      LinearizeWriteMatrix(dir / "C.mtx", C);
      LinearizeWriteMatrix(dir / "D.mtx", D);
      WriteAnalysisFile((dir / "statespace.json").string(), js);
    }
    out.A = A, out.B = B, out.C = C, out.D = D;
    out.states = state_names, out.inputs = input_names, out.outputs = output_names;
    out.output_values = y0, out.time = s0.t;
    n_states = ns, n_inputs = nu, n_outputs = p;
    if (opt.info)
      std::fprintf(opt.info, "state-space model of '%s': %d states, %d inputs, %d outputs; results in %s\n",
                   m.name.c_str(), n_states, n_inputs, n_outputs, opt.out_dir.c_str());
  } catch (const InputError& e) {
    status = "failed", message = AnalysisErrorText(e, opt.model_path), code = 2, out.error_kind = "InputError";
  } catch (const NumericalError& e) {
    status = "failed", message = AnalysisErrorText(e, opt.model_path), code = 1, out.error_kind = "NumericalError";
  } catch (const std::exception& e) {
    status = "failed", message = e.what(), code = 1, out.error_kind = "Error";
  }
  if (code != 0 && opt.err) std::fprintf(opt.err, "error: %s\n", message.c_str());
  JsonObjectText sum;
  sum.Text("status", status);
  sum.Text("message", message);
  sum.Text("analysis", "linearize");
  sum.Text("model", opt.model_path);
  sum.Text("at", opt.at);
  sum.Number("time", am.state.t);
  sum.Raw("states", std::to_string(n_states));
  sum.Raw("inputs", std::to_string(n_inputs));
  sum.Raw("outputs", std::to_string(n_outputs));
  sum.Raw("redundant_constraints", std::to_string(am.report.redundant.size()));
  out.code = FinishAnalysisSummary(sum, opt.out_dir, start, warnings, opt.err, code, &out.summary_json);
  out.message = message;
  if (out.code != 0 && out.error_kind.empty()) out.error_kind = "InputError", out.message = "cannot write summary.json";
  return out;
}

}  // namespace flexmb::cli
