/// \file main.cc
/// The flexmb command line: "run" and "check" over the library's RunModel and
/// CheckModel (apps/flexmb/commands/run.h), the "fe" group ("fe modes", "fe info",
/// "fe export") over apps/flexmb/commands/fe_commands.h, "fe static" over
/// apps/flexmb/commands/fe_static.h, and "reduce" and "body info"
/// over apps/flexmb/commands/reduce_commands.h.

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include "apps/flexmb/commands/linearize_command.h"
#include "apps/flexmb/commands/modes_command.h"
#include "apps/flexmb/commands/statics_command.h"
#include "flexmb/common/process_tuning.h"
#include "flexmb/common/error.h"
#include "apps/flexmb/commands/fe_commands.h"
#include "apps/flexmb/commands/driver_sensitivity.h"
#include "apps/flexmb/commands/frame_deck.h"
#include "apps/flexmb/commands/handling.h"
#include "apps/flexmb/commands/fe_static.h"
#include "apps/flexmb/commands/reduce_commands.h"
#include "apps/flexmb/commands/run.h"
#include "apps/flexmb/commands/lane_change.h"
#include "flexmb/crane/crane_template.h"
#include "apps/flexmb/commands/straight_run.h"
#include "apps/flexmb/commands/post_command.h"
#include "apps/flexmb/commands/study_command.h"
#ifdef FLEXMB_HAVE_PETSC
#include "flexmb/reduction/petsc/petsc_reduction.h"
#endif

namespace {

volatile std::sig_atomic_t g_interrupted = 0;

// the first Ctrl-C (or SIGTERM) stops the run at the next output time,
// which reports the signal (g_interrupted holds its number); a second one kills
extern "C" void OnInterrupt(int sig) {
  g_interrupted = sig;
  std::signal(sig, SIG_DFL);
}

int Run(const std::string& model, const std::string& out, std::optional<double> t_end,
        std::optional<double> dt, const std::string& manoeuvre, bool animation, bool quiet) {
  flexmb::RunOptions opt;
  opt.model_path = model;
  opt.manoeuvre = manoeuvre;
  opt.out_dir = out;
  opt.t_end = t_end;
  opt.dt = dt;
  opt.animation = animation;
  opt.progress = !quiet && isatty(STDERR_FILENO);
  opt.info = quiet ? nullptr : stdout;
  opt.err = stderr;
  opt.interrupt = &g_interrupted;
  std::signal(SIGINT, OnInterrupt);
  std::signal(SIGTERM, OnInterrupt);
  const flexmb::RunSummary s = flexmb::RunModel(opt);
  if (s.status != flexmb::RunStatus::kOk) {
    std::fprintf(stderr, "error: %s\n", s.message.c_str());
  } else if (!quiet) {
    std::printf("reached t = %g s in %ld steps (%ld rejected), %.3g s wall time; results in %s\n",
                s.t_end, s.steps, s.rejected_steps, s.wall_time_s, out.c_str());
  }
  return flexmb::ExitCode(s.status);
}

// runs a command: exit 2 for an input error, 1 for a numerical or other
// error, the message on stderr only (stdout stays valid JSON or empty)
template <class F>
int Guarded(F&& command) {
  try {
    return command();
  } catch (const flexmb::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}

// "reduce --backend petsc": every process of the MPI job runs the command
// on its share of the model; rank 0 writes the body and reports (errors,
// which every process meets alike, too)
int ReduceWithPetsc(flexmb::io::ReduceOptions& opt, int* argc, char*** argv) {
#ifdef FLEXMB_HAVE_PETSC
  namespace rp = flexmb::reduction::petsc;
  (void)argc;
  (void)argv;
  std::optional<rp::MpiSession> session;
  const int started = Guarded([&] {
    session.emplace();
    return 0;
  });
  if (started != 0) return started;
  opt.reducer = rp::ReduceCraigBamptonPetsc;
  opt.root = session->rank() == 0;
  opt.backend = "MUMPS and SLEPc (PETSc) on " + std::to_string(session->size()) + " MPI ranks";
  if (opt.root) return Guarded([&] { return flexmb::io::Reduce(opt, std::cout); });
  try {
    return flexmb::io::Reduce(opt, std::cout);
  } catch (const flexmb::InputError&) {
    return 2;
  } catch (const std::exception&) {
    return 1;
  }
#else
  // flexmb itself does not link PETSc and MPI (they would add 70 ms to the
  // start of every run): the same command line goes to flexmb-petsc, this
  // program built with them, beside this executable (exec keeps the process,
  // so mpirun's rank environment stays valid)
  (void)opt;
  (void)argc;
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path helper = self.parent_path() / "flexmb-petsc";
  if (!ec && std::filesystem::exists(helper, ec)) {
    execv(helper.c_str(), *argv);
    std::fprintf(stderr, "error: --backend petsc: cannot start %s\n", helper.c_str());
    return 1;
  }
  std::fprintf(stderr, "error: --backend petsc: this flexmb was built without PETSc (no %s; install petsc-dev, "
                       "slepc-dev and openmpi with scripts/install-deps.sh and configure again; CMake option "
                       "FLEXMB_PETSC)\n", helper.c_str());
  return 2;
#endif
}

}  // namespace

int main(int argc, char** argv) {
  flexmb::TuneProcess(argv);  // OpenBLAS kernels and malloc settings (docs/design.md)
  CLI::App app{"flexmb: flexible multibody dynamics"};
  app.set_version_flag("--version", "flexmb " FLEXMB_VERSION);
  app.require_subcommand(1);

  std::string model, out;
  std::optional<double> t_end, dt;
  bool animation = false, quiet = false;
  CLI::App* run = app.add_subcommand("run", "simulate a model file and write results");
  run->add_option("model", model, "model file (YAML)")->required();
  run->add_option("--out,-o", out, "output directory")->required();
  run->add_option("--t-end", t_end, "end time [s] (overrides solver.t_end)");
  run->add_option("--dt", dt, "step size [s] (overrides solver.dt)");
  std::string manoeuvre;
  run->add_option("--manoeuvre", manoeuvre, "model files only: the entry of the file's 'manoeuvres' to run");
  run->add_flag("--animation", animation, "write anim.pvd and frames/ (as output.animation)");
  run->add_flag("--quiet,-q", quiet, "no progress bar, no summary lines");
  std::optional<double> speed;
  std::optional<std::string> frame;
  run->add_option("--speed", speed, "lane-change files only: entry speed [km/h] (default: the file's)");
  run->add_option("--frame", frame, "lane-change files only: frame model, rigid or elastic (default: the file's)");
  std::optional<double> animation_fps;
  run->add_option("--animation-fps", animation_fps,
                  "lane-change files only: write the animation at this many frames per second of simulated time "
                  "(default: the file's animation_fps, 25)");

  flexmb::cli::StaticsCommandOptions statics_opt;
  CLI::App* statics = app.add_subcommand("statics", "static equilibrium of a model file (load stepping)");
  statics->add_option("model", statics_opt.model_path, "model file (YAML)")->required();
  statics->add_option("--out,-o", statics_opt.out_dir, "output directory")->required();
  statics->add_option("--time", statics_opt.time, "time at which drivers and loads are evaluated [s] (default 0)");
  statics->add_option("--manoeuvre", statics_opt.manoeuvre, "the entry of the file's 'manoeuvres' to solve");
  statics->add_flag("--animation", statics_opt.animation, "write anim.pvd, one frame per load step");
  bool statics_quiet = false;
  statics->add_flag("--quiet,-q", statics_quiet, "no summary line");

  flexmb::cli::ModesCommandOptions sys_modes_opt;
  CLI::App* sys_modes = app.add_subcommand("modes", "linearized modes of a model file about a state");
  sys_modes->add_option("model", sys_modes_opt.model_path, "model file (YAML)")->required();
  sys_modes->add_option("--out,-o", sys_modes_opt.out_dir, "output directory")->required();
  sys_modes->add_option("--at", sys_modes_opt.at,
                        "state: statics (static equilibrium, default), initial (the consistent initial state) "
                        "or time (simulated to --time)")
      ->check(CLI::IsMember({"statics", "initial", "time"}));
  sys_modes->add_option("--time", sys_modes_opt.time,
                        "with --at time: simulate to this time [s]; otherwise: time of the loads (default 0)");
  sys_modes->add_option("--count,-n", sys_modes_opt.count, "vibration modes reported, lowest first (default 10)");
  sys_modes->add_option("--frame", sys_modes_opt.frame,
                        "lane-change (truck) files only: frame model, rigid or elastic (default: the file's); the "
                        "truck stands on its tires")
      ->check(CLI::IsMember({"rigid", "elastic"}));
  bool sys_modes_no_anim = false;
  sys_modes->add_flag("--no-animation", sys_modes_no_anim, "no mode_<k>/anim.pvd animations");
  sys_modes->add_option("--frames", sys_modes_opt.frames, "animation frames per period (default 24)");
  sys_modes->add_option("--amplitude", sys_modes_opt.amplitude,
                        "animation amplitude: largest shape entry [m or rad] (default 0.1)");
  bool sys_modes_quiet = false;
  sys_modes->add_flag("--quiet,-q", sys_modes_quiet, "no frequency table");

  flexmb::cli::LinearizeCommandOptions lin_opt;
  CLI::App* lin = app.add_subcommand("linearize", "state-space model (A, B, C, D) of a model file about a state");
  lin->add_option("model", lin_opt.model_path, "model file (YAML)")->required();
  lin->add_option("--out,-o", lin_opt.out_dir, "output directory")->required();
  lin->add_option("--inputs", lin_opt.inputs, "force elements as inputs (point_force, point_torque, spring_damper, joint_motor)")
      ->delimiter(',')
      ->required();
  lin->add_option("--outputs", lin_opt.outputs, "sensors as outputs (default: all)")->delimiter(',');
  lin->add_option("--at", lin_opt.at, "state: statics (default), initial or time (simulated to --time)")
      ->check(CLI::IsMember({"statics", "initial", "time"}));
  lin->add_option("--time", lin_opt.time,
                  "with --at time: simulate to this time [s]; otherwise: time of the loads and drivers (default 0)");
  bool lin_quiet = false;
  lin->add_flag("--quiet,-q", lin_quiet, "no summary line");

  CLI::App* truck = app.add_subcommand("truck", "truck lane-change test tools");
  truck->require_subcommand(1);
  std::string truck_file;
  double v_low = 20, v_high = 90, v_tol = 1;
  CLI::App* max_speed = truck->add_subcommand("max-speed", "highest entry speed passing the lane change (bisection)");
  max_speed->add_option("file", truck_file, "lane-change file (YAML)")->required();
  max_speed->add_option("--low", v_low, "lowest speed tried [km/h] (default 20)");
  max_speed->add_option("--high", v_high, "highest speed tried [km/h] (default 90)");
  max_speed->add_option("--tol", v_tol, "bisection tolerance [km/h] (default 1)");
  max_speed->add_option("--frame", frame, "frame model, rigid or elastic (default: the file's)");

  flexmb::vehicle::DriverSensitivityOptions sens_opt;
  std::vector<std::string> sens_vary;
  bool sens_quiet = false;
  CLI::App* sens = truck->add_subcommand(
      "driver-sensitivity", "highest passing lane-change speed for a range of driver settings (the truck or the driver?)");
  sens->add_option("file", truck_file, "lane-change file (YAML)")->required();
  sens->add_option("--vary", sens_vary, "KEY=V1,V2,...: a numeric key of the driver section and its values (repeatable)")
      ->required();
  sens->add_option("--low", sens_opt.low, "lowest speed tried [km/h] (default 20)");
  sens->add_option("--high", sens_opt.high, "highest speed tried [km/h] (default 90)");
  sens->add_option("--tol", sens_opt.tol, "bisection tolerance [km/h] (default 1)");
  sens->add_option("--frame", frame, "frame model, rigid or elastic (default: the file's)");
  sens->add_option("--out,-o", sens_opt.out_dir, "output directory: sensitivity.csv, summary.json");
  sens->add_flag("--quiet,-q", sens_quiet, "no table and trials");

  flexmb::vehicle::StraightRunOptions straight_opt;
  CLI::App* straight = truck->add_subcommand("straight-run", "straight run over a rough road at a constant speed");
  straight->add_option("file", straight_opt.file, "lane-change file (YAML): the truck, driver, solver")->required();
  straight->add_option("--out,-o", straight_opt.out_dir, "output directory")->required();
  straight->add_option("--speed", straight_opt.speed_kmh, "speed [km/h] (default: the file's entry speed)");
  straight->add_option("--frame", straight_opt.frame, "frame model, rigid or elastic (default: the file's)");
  straight->add_option("--dt", straight_opt.dt, "step size [s] (default: the file's)");
  straight->add_option("--road", straight_opt.road, "iso8608 (default), csv or flat");
  straight->add_option("--road-class", straight_opt.road_class, "ISO 8608 road class A to H (default B)");
  straight->add_option("--road-length", straight_opt.road_length, "road length [m] (default 300)");
  straight->add_option("--seed", straight_opt.seed, "random seed of the generated road (default 1)");
  straight->add_option("--road-csv", straight_opt.road_csv, "CSV of x, z_left, z_right [m] (with --road csv)");
  straight->add_option("--distance", straight_opt.distance, "distance driven on the road [m] (default: the road)");
  straight->add_option("--run-up", straight_opt.run_up_time, "time on the flat before the road [s] (default 3)");
  straight->add_option("--fade-in", straight_opt.fade_in, "length over which the road fades in [m] (default 5)");
  bool straight_quiet = false;
  straight->add_flag("--quiet,-q", straight_quiet, "no summary line");

  std::string frame_deck_out;
  CLI::App* frame_deck =
      truck->add_subcommand("frame-deck", "write the generated ladder frame as a Nastran deck, for flexmb reduce");
  frame_deck->add_option("file", truck_file, "lane-change file (YAML)")->required();
  frame_deck->add_option("--out,-o", frame_deck_out, "Nastran bulk data file to write")->required();

  flexmb::vehicle::HandlingOptions handling_opt;
  CLI::App* handling = truck->add_subcommand(
      "handling", "handling tests: step steer and sine steer (ISO 14793), constant steering-wheel angle (ISO 14792), braking, braking in a turn");
  handling->add_option("file", handling_opt.file, "lane-change file (YAML): the truck, road_mu, driver gains, solver")
      ->required();
  handling->add_option("--test", handling_opt.test,
                       "step-steer (default), sine-steer, constant-steer, braking or brake-in-turn");
  handling->add_option("--out,-o", handling_opt.out_dir, "output directory (results.csv, summary.json)");
  handling->add_option("--speed", handling_opt.speed_kmh,
                       "speed [km/h] (step steer; default: the file's entry speed), start speed (constant steer; 10)");
  handling->add_option("--steer", handling_opt.steer_deg,
                       "steering-wheel angle [deg] (default: the single-track angle for --ay or --radius)");
  handling->add_option("--ay", handling_opt.target_ay, "step steer: steady lateral acceleration of the default angle [m/s^2] (2)");
  handling->add_option("--radius", handling_opt.radius, "constant steer: kinematic radius of the default angle [m] (50)");
  handling->add_option("--rise-time", handling_opt.rise_time, "step steer: ramp of the steering input [s] (0.15)");
  handling->add_option("--hold", handling_opt.hold_time, "step steer: time after the step [s] (6)");
  handling->add_option("--frequency", handling_opt.frequency, "sine steer: input frequency [Hz] (0.5)");
  handling->add_option("--periods", handling_opt.periods, "sine steer: periods of the input, the first not fitted (4)");
  handling->add_option("--speed-rate", handling_opt.speed_rate_kmh_s, "constant steer: speed rise [km/h per s] (1)");
  handling->add_option("--max-ay", handling_opt.max_ay, "constant steer: end at this lateral acceleration [m/s^2] (3)");
  handling->add_option("--max-speed", handling_opt.max_speed_kmh, "constant steer: or at this speed [km/h] (90)");
  handling->add_option("--brake-torque", handling_opt.brake_torque,
                       "braking: total brake torque [N m] (default: for --decel on the unloaded radius)");
  handling->add_option("--decel", handling_opt.decel, "braking: deceleration of the default brake torque [m/s^2] (3)");
  handling->add_option("--brake-rise-time", handling_opt.brake_rise_time, "braking: ramp of the brake torque [s] (0.2)");
  handling->add_option("--frame", handling_opt.frame, "frame model, rigid or elastic (default: the file's)");
  handling->add_option("--dt", handling_opt.dt, "step size [s] (default: the file's)");
  bool handling_quiet = false;
  handling->add_flag("--quiet,-q", handling_quiet, "no summary line");

  CLI::App* crane = app.add_subcommand("crane", "crane files (docs/crane-file.md)");
  crane->require_subcommand(1);
  CLI::App* crane_expand =
      crane->add_subcommand("expand", "write the model file that the crane template makes of a crane file");
  std::string crane_file, crane_manoeuvre, crane_out;
  crane_expand->add_option("file", crane_file, "crane file (YAML)")->required();
  crane_expand->add_option("--manoeuvre", crane_manoeuvre, "for this entry of its manoeuvres (default: the file's)");
  crane_expand->add_option("-o,--out", crane_out, "output file (default: standard output)");

  CLI::App* check = app.add_subcommand("check", "validate a model file and report its constraints");
  check->add_option("model", model, "model file or lane-change file (YAML)")->required();
  std::optional<std::string> check_frame;
  std::optional<double> check_speed;
  check->add_option("--frame", check_frame, "lane-change file: frame model, rigid or elastic (default: the file's)");
  check->add_option("--speed", check_speed, "lane-change file: entry speed [km/h] (default: the file's)");
  std::string check_manoeuvre;
  check->add_option("--manoeuvre", check_manoeuvre, "model file: check the model with this entry of its manoeuvres");

  CLI::App* fe = app.add_subcommand("fe", "finite-element models of parts: modes, static, info, export");
  fe->require_subcommand(1);
  flexmb::io::FeModesOptions modes_opt;
  CLI::App* modes = fe->add_subcommand("modes", "natural frequencies of a part's full FE model");
  modes->add_option("model", modes_opt.model_path, "mesh file, FE model file (.yaml) or exchange-set directory")
      ->required();
  modes->add_option("--fix", modes_opt.fix, "nodes to clamp: comma-separated node ids or a node set name");
  modes->add_option("--count,-n", modes_opt.count, "number of modes (default 10)");
  modes->add_flag("--json", modes_opt.json, "print one JSON object instead of the table");
  modes->add_flag("--lumped", modes_opt.lumped, "lumped instead of consistent element mass");
  modes->add_option("--shift", modes_opt.shift, "spectral shift [rad^2/s^2], negative (default: automatic)");

  flexmb::io::FeStaticOptions static_opt;
  CLI::App* fe_static = fe->add_subcommand("static", "linear static solution of a part's full FE model");
  fe_static->add_option("model", static_opt.model_path, "mesh file or FE model file (.yaml)")->required();
  fe_static->add_option("--fix", static_opt.fix, "nodes to clamp: comma-separated node ids or a node set name");
  fe_static->add_option("--support", static_opt.supports,
                        "support of single components ID:COMPONENTS, digits 1-6 in basic axes (repeatable)");
  fe_static->add_option("--gravity", static_opt.gravity, "gravity gx,gy,gz [m/s^2] in the model's axes");
  fe_static->add_option("--force", static_opt.forces, "nodal load ID:fx,fy,fz[,mx,my,mz] [N, N m] (repeatable)");
  fe_static->add_option("--nodes", static_opt.nodes, "nodes to report (ids or a set; default: the loaded nodes)");
  fe_static->add_flag("--json", static_opt.json, "print one JSON object instead of the table");
  fe_static->add_flag("--second-order", static_opt.second_order,
                      "second-order (P-delta) solution (K + K_G) u = f, K_G from the linear solution's stresses");

  flexmb::io::FeInfoOptions info_opt;
  CLI::App* info = fe->add_subcommand("info", "counts, mass, centre of mass and bounding box of an FE model");
  info->add_option("model", info_opt.model_path, "mesh file, FE model file (.yaml) or exchange-set directory")
      ->required();
  info->add_flag("--json", info_opt.json, "print one JSON object instead of text");

  flexmb::io::FeExportOptions export_opt;
  CLI::App* fe_export =
      fe->add_subcommand("export", "write the exchange set (M_CCS.hb, K_CCS.hb, geometry.vtk, dof_map.txt)");
  fe_export->add_option("model", export_opt.model_path, "mesh file, FE model file (.yaml) or exchange-set directory")
      ->required();
  fe_export->add_option("--hb", export_opt.hb_dir, "directory to write the exchange set to")->required();
  fe_export->add_option("--fix", export_opt.fix, "nodes to clamp: comma-separated node ids or a node set name");
  fe_export->add_option("--interface", export_opt.interface,
                        "also write modes.mtx: Craig-Bampton modes for these interface nodes (ids or a node set)");
  fe_export->add_option("--modes", export_opt.modes, "fixed-interface normal modes in modes.mtx (default 10)");

  flexmb::io::ReduceOptions reduce_opt;
  CLI::App* reduce = app.add_subcommand("reduce", "Craig-Bampton reduction of an FE model to a flexible body file");
  reduce->add_option("model", reduce_opt.model_path, "mesh file, FE model file (.yaml) or exchange-set directory")
      ->required();
  reduce->add_option("--interface", reduce_opt.interface,
                     "interface nodes: comma-separated node ids or a node set (required unless --modes-file)");
  reduce->add_option("--modes", reduce_opt.modes, "fixed-interface normal modes (0 = Guyan)");
  reduce->add_option("--cutoff", reduce_opt.cutoff_hz, "all fixed-interface modes below this frequency [Hz]");
  reduce->add_option("--keep", reduce_opt.keep, "keep the lowest N flexible modes (default: all)");
  reduce->add_option("--fix", reduce_opt.fix, "nodes to clamp: comma-separated node ids or a node set name");
  reduce->add_option("--frame", reduce_opt.frame,
                     "floating frame: mean (mean axes; also tisserand, buckens) or node:ID (attached to node ID, "
                     "clamped in the reduction); default mean, or the --fix nodes");
  auto* rayleigh = reduce->add_option("--rayleigh", reduce_opt.rayleigh, "Rayleigh damping ALPHA,BETA");
  reduce->add_option("--damping-ratio", reduce_opt.damping_ratio, "modal damping ratio Z (or Z1,Z2,...)")
      ->excludes(rayleigh);
  reduce->add_option("--modes-file", reduce_opt.modes_file,
                     "use the static and normal modes of this modes file (modes.mtx of an exchange set) instead of "
                     "computing them; the interface is the file's");
  reduce->add_flag("--geometric-stiffening", reduce_opt.geometric_stiffening,
                   "also store the centrifugal geometric stiffness (beams, shells, solids)");
  reduce->add_flag("--deformation-stiffening", reduce_opt.deformation_stiffening,
                   "also store the geometric stiffness of the body's own deformation (P-delta of the "
                   "interface forces; beams, shells, solids)");
  reduce->add_flag("--acceleration-modes", reduce_opt.acceleration_modes,
                   "also add the static responses to the six rigid-body accelerations (own weight, uniform "
                   "acceleration) as basis vectors: distributed mass away from the interface");
  reduce->add_flag("--solid-corner-stress", reduce_opt.solid_corner_stress,
                   "also store solid stress modes at the corner nodes (post: stresses at nodes; a larger body "
                   "file)");
  reduce->add_option("--units", reduce_opt.units,
                     "unit system of the FE model, recorded in the body file: SI (default), mm-t-s, mm-kg-ms, "
                     "mm-kg-s, mm-g-ms, cm-g-s, in-lbf-s; models use SI body files only");
  reduce->add_option("--output,-o", reduce_opt.output, "body file to write (.h5)")->required();
  reduce->add_flag("--json", reduce_opt.json, "print one JSON object instead of text");
  reduce->add_option("--eigen-tolerance", reduce_opt.eigen_tolerance,
                     "relative residual of the fixed-interface modes (default: block Lanczos 1e-6, petsc 1e-12)")
      ->check(CLI::Range(0.0, 0.1));
  std::string reduce_backend = "cholmod";
  reduce->add_option("--backend", reduce_backend,
                     "solver of the factorization and the modes: cholmod (this process, default) or petsc (MUMPS "
                     "and SLEPc over MPI: run under mpirun -np N)")
      ->check(CLI::IsMember({"cholmod", "petsc"}));

  CLI::App* body = app.add_subcommand("body", "flexible body files: info");
  body->require_subcommand(1);
  flexmb::io::BodyInfoOptions body_info_opt;
  CLI::App* body_info = body->add_subcommand("info", "counts, mass, frequencies and provenance of a body file");
  body_info->add_option("file", body_info_opt.body_path, "body file (.h5)")->required();
  body_info->add_flag("--json", body_info_opt.json, "print one JSON object instead of text");

  flexmb::commands::PostOptions post_opt;
  CLI::App* post = app.add_subcommand("post", "stresses, hot spots and fatigue damage of a flexible body of a run");
  post->add_option("dir", post_opt.run_dir, "run folder (holds modal_coordinates.bin)")->required();
  post->add_option("--body", post_opt.body, "flexible body name")->required();
  post->add_option("--out,-o", post_opt.out_dir, "output folder (default DIR/post_BODY)");
  post->add_option("--top", post_opt.top, "hot spots listed (default 10)");
  post->add_option("--measure", post_opt.measure,
                   "counted stress: max_abs_principal (default), signed_von_mises, von_mises, max_principal, min_principal");
  post->add_option("--sn", post_opt.sn, "S-N preset, e.g. en1993-71 (EN 1993-1-9 detail category)");
  post->add_option("--sn-file", post_opt.sn_file, "S-N table: CSV of cycles, range [Pa]");
  post->add_option("--sn-basquin", post_opt.sn_basquin, "S_ref[Pa],N_ref,m1[,N_knee,m2[,N_cut]]")->delimiter(',');
  post->add_option("--mean-stress", post_opt.mean_stress, "none (default), goodman, fkm");
  post->add_option("--ultimate", post_opt.ultimate, "Goodman: ultimate strength [Pa]");
  post->add_option("--sensitivity", post_opt.sensitivity, "FKM: mean-stress sensitivity M");
  post->add_option("--distance-km", post_opt.distance_km, "distance of the run [km]: damage per 1000 km, life in km");
  post->add_option("--element", post_opt.elements, "element id: stress history to CSV (repeatable)");
  post->add_option("--node", post_opt.nodes, "node id: elastic displacement history to CSV (repeatable)");
  post->add_flag("--json", post_opt.json, "print one JSON object instead of text");

  CLI::App* study = app.add_subcommand("study", "parameter study from a study file, on a local or remote Dask cluster");
  study->set_help_flag();  // its options and --help belong to python3 -m flexmb.study_cli
  study->prefix_command();
  study->allow_extras();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  if (study->parsed()) return flexmb::cli::StudyCommand(study->remaining(), argv[0]);
  if (run->parsed() && !manoeuvre.empty() && flexmb::vehicle::IsLaneChangeFile(model)) {
    std::fprintf(stderr, "error: --manoeuvre %s: only for a model file (this is a lane-change file)\n",
                 manoeuvre.c_str());
    return 2;
  }
  if (run->parsed() && flexmb::vehicle::IsLaneChangeFile(model)) {
    return Guarded([&] {
      flexmb::vehicle::LaneChangeOptions o{model, out, speed, frame, dt, false, quiet ? nullptr : stdout};
      if (animation) o.animation = true;
      o.animation_fps = animation_fps;
      const flexmb::vehicle::LaneChangeResult r = flexmb::vehicle::RunLaneChange(o);
      if (!r.completed && !r.rolled_over) std::fprintf(stderr, "error: lane change did not complete: %s\n", r.message.c_str());
      return r.completed || r.rolled_over ? 0 : 1;
    });
  }
  if (run->parsed() && flexmb::cli::ModelAsksForStatics(model, manoeuvre)) {
    flexmb::cli::StaticsCommandOptions o;
    o.model_path = model;
    o.manoeuvre = manoeuvre;
    o.out_dir = out;
    o.animation = animation;
    o.info = quiet ? nullptr : stdout;
    o.err = stderr;
    return flexmb::cli::StaticsCommand(o);
  }
  if (run->parsed()) return Run(model, out, t_end, dt, manoeuvre, animation, quiet);
  if (statics->parsed()) {
    statics_opt.info = statics_quiet ? nullptr : stdout;
    statics_opt.err = stderr;
    return flexmb::cli::StaticsCommand(statics_opt);
  }
  if (lin->parsed()) {
    lin_opt.info = lin_quiet ? nullptr : stdout;
    lin_opt.err = stderr;
    return flexmb::cli::LinearizeCommand(lin_opt);
  }
  if (sys_modes->parsed()) {
    sys_modes_opt.animation = !sys_modes_no_anim;
    sys_modes_opt.info = sys_modes_quiet ? nullptr : stdout;
    sys_modes_opt.err = stderr;
    return flexmb::cli::ModesCommand(sys_modes_opt);
  }
  if (max_speed->parsed()) {
    return Guarded([&] {
      flexmb::vehicle::LaneChangeOptions o{truck_file, "", std::nullopt, frame, std::nullopt, true, nullptr};
      bool low_ok = false;
      const double v = flexmb::vehicle::MaxPassSpeed(o, v_low, v_high, v_tol, stderr, &low_ok);
      std::printf("{\"max_pass_speed_kmh\": %.3f, \"low_passed\": %s, \"tolerance_kmh\": %g}\n", low_ok ? v : 0.0,
                  low_ok ? "true" : "false", v_tol);
      return 0;
    });
  }
  if (sens->parsed()) {
    return Guarded([&] {
      sens_opt.base.file = truck_file;
      sens_opt.base.frame = frame;
      for (const std::string& v : sens_vary) sens_opt.vary.push_back(flexmb::vehicle::ParseDriverVariation(v));
      sens_opt.info = sens_quiet ? nullptr : stdout;
      flexmb::vehicle::RunDriverSensitivity(sens_opt);
      return 0;
    });
  }
  if (handling->parsed()) {
    return Guarded([&] {
      handling_opt.info = handling_quiet ? nullptr : stdout;
      const flexmb::vehicle::HandlingResult r = flexmb::vehicle::RunHandlingTest(handling_opt);
      if (!r.completed) std::fprintf(stderr, "error: handling test did not complete: %s\n", r.message.c_str());
      return r.completed ? 0 : 1;
    });
  }
  if (frame_deck->parsed())
    return Guarded([&] { return flexmb::cli::WriteTruckFrameDeck(truck_file, frame_deck_out, stdout); });
  if (straight->parsed()) {
    return Guarded([&] {
      if (!straight_opt.road_csv.empty() && straight_opt.road == "iso8608") straight_opt.road = "csv";
      straight_opt.info = straight_quiet ? nullptr : stdout;
      const flexmb::vehicle::StraightRunResult r = flexmb::vehicle::RunStraight(straight_opt);
      if (!r.completed) std::fprintf(stderr, "error: straight run did not complete: %s\n", r.message.c_str());
      return r.completed ? 0 : 1;
    });
  }
  if (modes->parsed()) return Guarded([&] { return flexmb::io::FeModes(modes_opt, std::cout); });
  if (fe_static->parsed()) return Guarded([&] { return flexmb::io::FeStatic(static_opt, std::cout); });
  if (crane_expand->parsed())
    return Guarded([&] {
      const std::string text = flexmb::crane::ExpandedCraneFile(crane_file, crane_manoeuvre);
      if (crane_out.empty()) {
        std::fputs(text.c_str(), stdout);
        return 0;
      }
      std::ofstream f(crane_out);
      f << text;
      if (!f) throw flexmb::InputError("cannot write the model file", {crane_out, 0, ""});
      return 0;
    });
  if (info->parsed()) return Guarded([&] { return flexmb::io::FeInfo(info_opt, std::cout); });
  if (fe_export->parsed()) return Guarded([&] { return flexmb::io::FeExport(export_opt, std::cout); });
  if (reduce->parsed() && reduce_backend == "petsc") return ReduceWithPetsc(reduce_opt, &argc, &argv);
  if (reduce->parsed()) return Guarded([&] { return flexmb::io::Reduce(reduce_opt, std::cout); });
  if (post->parsed()) return Guarded([&] { return flexmb::commands::Post(post_opt, std::cout); });
  if (body_info->parsed()) return Guarded([&] { return flexmb::io::BodyInfo(body_info_opt, std::cout); });
  return Guarded([&] {
    if (flexmb::vehicle::IsLaneChangeFile(model)) {
      flexmb::vehicle::LaneChangeOptions o;
      o.file = model;
      o.frame = check_frame;
      o.speed_kmh = check_speed;
      flexmb::vehicle::CheckLaneChange(o, stdout);
      return 0;
    }
    flexmb::CheckModel(model, stdout, check_manoeuvre);
    return 0;
  });
}
