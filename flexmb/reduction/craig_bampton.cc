#include "flexmb/reduction/craig_bampton.h"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/reduction/craig_bampton_basis.h"
#include "flexmb/reduction/inertia_invariants.h"
#include "flexmb/reduction/deformation_stiffness.h"
#include "flexmb/reduction/geometric_stiffness.h"
#include "flexmb/reduction/stress_modes.h"
#include "flexmb/reduction/rigid_modes.h"

#ifndef FLEXMB_VERSION
#define FLEXMB_VERSION "unknown"
#endif

namespace flexmb::reduction {

namespace {

using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string Num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string NodeIds(const fe::Mesh& mesh, const std::vector<int>& nodes) {
  std::string s;
  for (int n : nodes) {
    if (!s.empty()) s += ",";
    s += n >= 0 && n < static_cast<int>(mesh.nodes.size()) ? std::to_string(mesh.nodes[n].id) : "?";
  }
  return s;
}

std::string UtcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

void CheckOptions(const fe::Mesh& mesh, const ReductionOptions& o) {
  const ErrorContext where{mesh.source, 0, "reduction options"};
  if (o.normal_modes < 0) throw InputError("the number of normal modes must not be negative", where);
  if (!std::isfinite(o.cutoff_hz) || o.cutoff_hz < 0.0) {
    throw InputError("the frequency cut-off must be a finite number >= 0 [Hz]", where);
  }
  if (o.keep == 0 || o.keep < -1) throw InputError("keep must be -1 (all modes) or at least 1", where);
  if (!std::isfinite(o.rayleigh_alpha) || !std::isfinite(o.rayleigh_beta) || o.rayleigh_alpha < 0.0 ||
      o.rayleigh_beta < 0.0) {
    throw InputError("Rayleigh damping coefficients must be finite and >= 0", where);
  }
  if (!std::isfinite(o.eigen_tolerance) || o.eigen_tolerance < 0.0 || o.eigen_tolerance >= 1.0) {
    throw InputError("the eigen solver tolerance must be in [0, 1) (0: the solver's default)", where);
  }
  for (double z : o.damping_ratios) {
    if (!std::isfinite(z) || z < 0.0) throw InputError("damping ratios must be finite and >= 0", where);
  }
}

// Cyclic Jacobi on a symmetric, nearly diagonal matrix a (overwritten by its
// diagonal form); the rotations are accumulated into the columns of v. An
// entry is rotated away if larger than 1e-15 sqrt(|a_pp a_qq|), which keeps
// the relative accuracy of small diagonal entries.
void JacobiDiagonalize(Eigen::MatrixXd& a, Eigen::MatrixXd& v) {
  const Eigen::Index n = a.rows();
  for (int sweep = 0; sweep < 30; ++sweep) {
    bool rotated = false;
    for (Eigen::Index p = 0; p < n; ++p) {
      for (Eigen::Index q = p + 1; q < n; ++q) {
        const double apq = a(p, q);
        if (!(std::abs(apq) > 1e-15 * std::sqrt(std::abs(a(p, p) * a(q, q))))) continue;
        rotated = true;
        const double theta = (a(q, q) - a(p, p)) / (2.0 * apq);
        const double tt = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(tt * tt + 1.0), sn = tt * c;
        // a <- J^T a J with J the rotation in the (p, q) plane
        for (Eigen::Index k = 0; k < n; ++k) {
          const double akp = a(k, p), akq = a(k, q);
          a(k, p) = c * akp - sn * akq;
          a(k, q) = sn * akp + c * akq;
        }
        for (Eigen::Index k = 0; k < n; ++k) {
          const double apk = a(p, k), aqk = a(q, k);
          a(p, k) = c * apk - sn * aqk;
          a(q, k) = sn * apk + c * aqk;
        }
        a(p, q) = a(q, p) = 0.0;
        for (Eigen::Index k = 0; k < n; ++k) {
          const double vkp = v(k, p), vkq = v(k, q);
          v(k, p) = c * vkp - sn * vkq;
          v(k, q) = sn * vkp + c * vkq;
        }
      }
    }
    if (!rotated) return;
  }
}

// K y = lambda M y for symmetric K, M (M positive definite): ascending
// eigenvalues, M-orthonormal eigenvectors. With M = L L^T and K = R^T R, the
// symmetric matrix B = L^T K^{-1} L = (R^{-T} L)^T (R^{-T} L) has the
// eigenvalues 1 / lambda and orthonormal eigenvectors v, y = L^{-T} v. So the
// basis is M-orthonormal to round-off and the low modes (large 1 / lambda)
// keep their relative accuracy whatever the spread of the spectrum; the
// standard reduction L^{-1} K L^{-T} errs by eps lambda_max on every
// eigenvalue, which the static response of the body (dominated by the low
// modes) feels at eps lambda_max / lambda_min. If K is not positive definite
// (a zero mode left), the standard reduction.
struct ReducedModes {
  Eigen::VectorXd lambda;
  Eigen::MatrixXd y;
};
ReducedModes SolveReducedModes(const Eigen::MatrixXd& k_in, const Eigen::MatrixXd& m_in) {
  const Eigen::MatrixXd k = 0.5 * (k_in + k_in.transpose()), m = 0.5 * (m_in + m_in.transpose());
  const Eigen::Index n = k.rows();
  ReducedModes out;
  if (n == 0) {
    out.lambda.resize(0);
    out.y.resize(0, 0);
    return out;
  }
  Eigen::LLT<Eigen::MatrixXd> ml(m);
  if (ml.info() != Eigen::Success) {
    throw NumericalError("Craig-Bampton reduction: the reduced mass matrix is not positive definite");
  }
  const Eigen::MatrixXd l = ml.matrixL();
  Eigen::LLT<Eigen::MatrixXd> kl(k);
  if (kl.info() == Eigen::Success) {
    Eigen::MatrixXd c = l;
    kl.matrixL().solveInPlace(c);   // R^{-T} L (K = R^T R, matrixL = R^T)
    Eigen::MatrixXd b(n, n);
    b.setZero();
    b.selfadjointView<Eigen::Lower>().rankUpdate(c.transpose());
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> be(b);   // reads the lower triangle
    const Eigen::VectorXd& mu = be.eigenvalues();
    if (be.info() == Eigen::Success && mu.minCoeff() > 0.0) {
      // mu ascending: lambda = 1 / mu descending; reverse
      out.lambda.resize(n);
      Eigen::MatrixXd v(n, n);
      for (Eigen::Index j = 0; j < n; ++j) {
        out.lambda[j] = 1.0 / mu[n - 1 - j];
        v.col(j) = be.eigenvectors().col(n - 1 - j);
      }
      ml.matrixU().solveInPlace(v);   // L^{-T} v
      // the high modes (small 1 / lambda) come out mixed to eps lambda_max /
      // lambda_min: a Jacobi cleanup of the nearly diagonal y^T K y = (R y)^T
      // (R y), whose rotations keep the basis M-orthonormal and are tiny
      Eigen::MatrixXd t = Eigen::MatrixXd(kl.matrixU() * v);
      t = (t.transpose() * t).eval();
      Eigen::MatrixXd rot = Eigen::MatrixXd::Identity(n, n);
      JacobiDiagonalize(t, rot);
      const Eigen::MatrixXd y = v * rot;
      std::vector<Eigen::Index> order(static_cast<size_t>(n));
      for (Eigen::Index j = 0; j < n; ++j) order[static_cast<size_t>(j)] = j;
      std::stable_sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return t(a, a) < t(b, b); });
      out.lambda.resize(n);
      out.y.resize(n, n);
      for (Eigen::Index j = 0; j < n; ++j) {
        out.lambda[j] = t(order[static_cast<size_t>(j)], order[static_cast<size_t>(j)]);
        out.y.col(j) = y.col(order[static_cast<size_t>(j)]);
      }
      return out;
    }
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(k, m);
  if (eig.info() != Eigen::Success) {
    throw NumericalError("Craig-Bampton reduction: the reduced eigenproblem failed");
  }
  out.lambda = eig.eigenvalues();
  out.y = eig.eigenvectors();
  return out;
}

// Final orthonormalization of the kept modes y (columns) against the
// reduced matrices: the M-orthonormal eigenvectors of the complement of the
// rigid motions come out with an error of about eps times its condition
// (2e-10 for a free ladder frame against 3e-14 pinned). Two steps of
// y <- y (3 I - G) / 2, G = y^T M y (first-order symmetric, Lowdin,
// orthonormalization; each squares the error) make y^T M y = I to the
// round-off of the products; a Jacobi rotation of the now nearly diagonal
// y^T K y (rotations keep M-orthonormality) then restores K-diagonality.
// Returns the eigenvalues, ascending, and reorders y to match.
Eigen::VectorXd ReorthonormalizeModes(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness,
                                      Eigen::MatrixXd& y) {
  const Eigen::Index n = y.cols();
  for (int pass = 0; pass < 2 && n > 0; ++pass) {
    Eigen::MatrixXd g = y.transpose() * (mass * y);
    g = 0.5 * (g + g.transpose()).eval();
    y = (y * (1.5 * Eigen::MatrixXd::Identity(n, n) - 0.5 * g)).eval();
  }
  Eigen::MatrixXd k = y.transpose() * (stiffness * y);
  k = 0.5 * (k + k.transpose()).eval();
  Eigen::MatrixXd rot = Eigen::MatrixXd::Identity(n, n);
  JacobiDiagonalize(k, rot);
  const Eigen::MatrixXd rotated = y * rot;
  std::vector<Eigen::Index> order(static_cast<size_t>(n));
  for (Eigen::Index j = 0; j < n; ++j) order[static_cast<size_t>(j)] = j;
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index i, Eigen::Index j) { return k(i, i) < k(j, j); });
  Eigen::VectorXd lambda(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const Eigen::Index o = order[static_cast<size_t>(j)];
    lambda[j] = k(o, o);
    y.col(j) = rotated.col(o);
  }
  return lambda;
}

}  // namespace

ReductionOptions PrepareReductionOptions(const fe::Mesh& mesh, const ReductionOptions& options_in) {
  CheckOptions(mesh, options_in);
  ReductionOptions options = options_in;
  // interface nodes listed twice count once
  options.interface_nodes.clear();
  for (int n : options_in.interface_nodes) {
    if (std::find(options.interface_nodes.begin(), options.interface_nodes.end(), n) ==
        options.interface_nodes.end()) {
      options.interface_nodes.push_back(n);
    }
  }
  return options;
}

fe::AssemblyOptions ReductionAssemblyOptions(const ReductionOptions& options) {
  fe::AssemblyOptions assembly;
  assembly.mass_form = options.mass_form;
  assembly.extra_fixed_nodes = options.fixed_nodes;
  // an RBE3 reference node as interface node keeps its own DOF
  assembly.independent_nodes = options.interface_nodes;
  return assembly;
}

ReducedBody ReduceCraigBampton(const fe::FeModel& model, const ReductionOptions& options_in,
                               ReductionTimings* timings) {
  const ReductionOptions options = PrepareReductionOptions(model.mesh, options_in);
  ReductionTimings local_timings;
  ReductionTimings& t = timings != nullptr ? *timings : local_timings;
  t = ReductionTimings{};

  auto t0 = Clock::now();
  const fe::AssembledModel a = fe::BuildMatrices(model, ReductionAssemblyOptions(options));
  t.assemble = Seconds(t0);

  const CraigBamptonBasis basis = BuildCraigBamptonBasis(model.mesh, a, options, &t);
  return ReduceBasis(model, a, basis, options, &t);
}

ReducedBody ReduceBasis(const fe::FeModel& model, const fe::AssembledModel& a, const CraigBamptonBasis& basis,
                        const ReductionOptions& options, ReductionTimings* timings, const DistributedSteps* steps) {
  const fe::Mesh& mesh = model.mesh;
  ReductionTimings local_timings;
  ReductionTimings& t = timings != nullptr ? *timings : local_timings;
  const auto t0 = Clock::now();
  const int nb = basis.static_modes(), m = basis.size();

  // rigid motions: the geometric rigid vectors are (u_b, 0) in the basis
  // (exact when K r = 0, as the static modes reproduce every zero-energy motion)
  fe::Vec3 origin = fe::Vec3::Zero();
  for (const fe::Node& node : mesh.nodes) origin += node.x;
  if (!mesh.nodes.empty()) origin /= static_cast<double>(mesh.nodes.size());
  const Eigen::MatrixXd r = RigidBodyVectors(mesh, a.dofs, origin);
  Eigen::MatrixXd candidates = Eigen::MatrixXd::Zero(m, 6);
  for (int k = 0; k < nb; ++k) candidates.row(k) = r.row(basis.boundary[k]);
  const RigidSplit split = SplitRigidMotions(basis.mass, basis.stiffness, candidates, basis.stiffness_scale);

  // orthonormal flexible modes in the M-orthogonal complement of the rigid motions
  const Eigen::MatrixXd& z = split.complement;
  const Eigen::MatrixXd kz = z.transpose() * basis.stiffness * z;
  const Eigen::MatrixXd mz = z.transpose() * basis.mass * z;
  const ReducedModes eig = SolveReducedModes(kz, mz);
  const int available = m - split.count;
  if (options.keep > available) {
    throw InputError("keep = " + std::to_string(options.keep) + " flexible modes asked, but the basis has only " +
                         std::to_string(available) + " (" + std::to_string(nb) + " static + " +
                         std::to_string(basis.normal_modes() - basis.acceleration_modes) + " normal + " +
                         std::to_string(basis.acceleration_modes) + " acceleration - " + std::to_string(split.count) +
                         " rigid)",
                     {mesh.source, 0, "reduction options"});
  }
  const int nk = options.keep < 0 ? available : options.keep;
  if (nk > 0 && eig.lambda[0] < 1e-12 * basis.stiffness_scale) {
    throw NumericalError("the reduced body has a mode of (near) zero frequency that is not a rigid-body motion: "
                         "a mechanism (parts joined only through interface nodes, or a joint-like rigid link?)",
                         {mesh.source, 0, "reduced body"});
  }
  // all flexible modes are orthonormalized together, so that the kept ones
  // do not depend on how many are kept
  Eigen::MatrixXd y_all = z * eig.y;
  const Eigen::VectorXd lambda = ReorthonormalizeModes(basis.mass, basis.stiffness, y_all).head(nk);
  const Eigen::MatrixXd y = y_all.leftCols(nk);

  // modes: 6 rows per node, every node, through T (dependent nodes included)
  const bool root = steps == nullptr || steps->root;
  const Eigen::MatrixXd h_free = steps != nullptr ? steps->expand(y) : basis.Expand(y);
  ReducedBody body;
  const int nn = static_cast<int>(mesh.nodes.size());
  if (root) {
    body.modes = Eigen::MatrixXd::Zero(6 * static_cast<Eigen::Index>(nn), nk);
    // row 6 node + c of the modes = row dofs.full[node][c] of T h_free
    const Eigen::SparseMatrix<double, Eigen::RowMajor, int> tr = a.T;
    for (int j = 0; j < nk; ++j) {
      const double* h = h_free.col(j).data();
      double* out = body.modes.col(j).data();
      for (int node = 0; node < nn; ++node) {
        for (int c = 0; c < 6; ++c) {
          const int f = a.dofs.full[node][c];
          if (f < 0) continue;
          double v = 0.0;
          for (decltype(tr)::InnerIterator it(tr, f); it; ++it) v += it.value() * h[it.col()];
          out[6 * node + c] = v;
        }
      }
    }
  }
  // inertia invariants of the modes with the node-by-node mass (THEORY
  // section 4); H^T M_full H = y^T M_CB y is at hand (M = T^T M_full T)
  const auto t_invariants = Clock::now();
  const Eigen::MatrixXd modal_mass = y.transpose() * basis.mass * y;
  body.invariants = steps != nullptr ? steps->invariants(body.modes, modal_mass)
                                     : ComputeInertiaInvariants(mesh, a, body.modes, &modal_mass);
  t.invariants = Seconds(t_invariants);
  // stress of every element for a unit value of each modal coordinate;
  // imported matrices come without element properties: no stress modes
  const auto t_stress = Clock::now();
  if (!model.imported) {
    body.stress = steps != nullptr ? steps->stress(body.modes)
                                   : ComputeStressModes(mesh, body.modes, options.solid_corner_stress);
  }
  t.stress_modes = Seconds(t_stress);
  const auto t_stiffening = Clock::now();
  if (options.geometric_stiffening) {
    if (model.imported)
      throw InputError("geometric stiffening needs the elements (imported matrices have none)",
                       {mesh.source, 0, "reduction options"});
    body.geometric_stiffness = ComputeGeometricStiffness(
        mesh, body.modes, options.fixed_nodes.empty() ? options.interface_nodes : options.fixed_nodes,
        options.mass_form);
  }
  if (options.deformation_stiffening) {
    if (model.imported)
      throw InputError("deformation stiffening needs the elements (imported matrices have none)",
                       {mesh.source, 0, "reduction options"});
    body.deformation_stiffness = ComputeDeformationStiffness(mesh, body.modes);
  }
  t.stiffening = Seconds(t_stiffening);
  body.frequencies_hz.resize(nk);
  for (int j = 0; j < nk; ++j) {
    body.frequencies_hz[j] = std::copysign(std::sqrt(std::abs(lambda[j])), lambda[j]) / (2.0 * M_PI);
  }
  body.mass = Eigen::MatrixXd::Identity(nk, nk);
  body.stiffness = lambda.asDiagonal();
  if (!options.damping_ratios.empty()) {
    body.damping = Eigen::MatrixXd::Zero(nk, nk);
    for (int j = 0; j < nk; ++j) {
      const double zeta = options.damping_ratios[std::min<size_t>(j, options.damping_ratios.size() - 1)];
      body.damping(j, j) = 2.0 * zeta * std::sqrt(std::max(lambda[j], 0.0));
    }
  } else {
    body.damping = options.rayleigh_alpha * body.mass + options.rayleigh_beta * body.stiffness;
  }
  body.mesh = mesh;
  body.interface_nodes = options.interface_nodes;
  body.static_modes = nb;
  body.normal_modes = basis.normal_modes() - basis.acceleration_modes;
  body.rigid_modes_removed = split.count;

  std::string ratios;
  for (double v : options.damping_ratios) ratios += (ratios.empty() ? "" : ",") + Num(v);
  // the floating frame the modes leave (docs/design.md, "The floating frame")
  std::string frame;
  if (!options.fixed_nodes.empty()) {
    frame = "attached to the clamped nodes ";
    frame += NodeIds(mesh, options.fixed_nodes);
  } else if (split.count == 6) {
    frame = "mean axes (flexible modes mass-orthogonal to the rigid-body modes: Tisserand's and Buckens' "
            "conditions to first order in the deformation)";
  } else {
    frame = "held by the model's own constraints (" + std::to_string(split.count) + " rigid-body modes removed)";
  }
  body.provenance = {
      {"source", mesh.source},
      {"method", "Craig-Bampton (fixed-interface), orthonormalized, rigid-body modes removed"},
      {"interface_nodes", NodeIds(mesh, options.interface_nodes)},
      {"fixed_nodes", NodeIds(mesh, options.fixed_nodes)},
      {"frame", frame},
      {"normal_modes_requested", std::to_string(options.normal_modes)},
      {"cutoff_hz", Num(options.cutoff_hz)},
      {"keep", std::to_string(options.keep)},
      {"mass_form", options.mass_form == fe::MassForm::kConsistent ? "consistent" : "lumped"},
      {"rayleigh_alpha", Num(options.rayleigh_alpha)},
      {"rayleigh_beta", Num(options.rayleigh_beta)},
      {"damping_ratios", ratios},
      {"free_dof", std::to_string(a.dofs.n_free)},
      {"static_modes", std::to_string(nb)},
      {"normal_modes", std::to_string(basis.normal_modes() - basis.acceleration_modes)},
      {"acceleration_modes", std::to_string(basis.acceleration_modes)},
      {"rigid_modes_removed", std::to_string(split.count)},
      {"flexible_modes", std::to_string(nk)},
      {"geometric_stiffening",
       options.geometric_stiffening
           ? std::string("centrifugal (6 load cases), held at the ") +
                 (options.fixed_nodes.empty() ? "interface nodes" : "fixed nodes")
           : std::string("none")},
      {"deformation_stiffening",
       options.deformation_stiffening ? std::string("per mode (n matrices G_j = H^T K_G(H e_j) H)") : std::string("none")},
      {"stress_modes", model.imported ? "none (imported matrices have no element properties)" : "per element"},
      {"flexmb_version", FLEXMB_VERSION},
      {"date", UtcNow()},
  };
  t.orthonormalize += Seconds(t0) - t.invariants - t.stress_modes - t.stiffening;
  return body;
}

}  // namespace flexmb::reduction
