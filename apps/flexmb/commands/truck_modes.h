#pragma once
/// \file truck_modes.h
/// `flexmb modes` of a lane-change file (examples/truck_lane_change/
/// truck.yaml): the truck standing on its tires (speed 0, steering wheel,
/// drive and brake torque 0), moved to static equilibrium, linearized, and
/// its modes named by their dominant motion (bounce, pitch, roll, axle hop
/// and tramp, a part on its mounts, the elastic frame's torsion and
/// bending). See docs/cli.md, "modes of a truck".

#include <memory>
#include <string>
#include <vector>

#include "apps/flexmb/commands/analysis_support.h"
#include "flexmb/reduction/reduced_body.h"
#include "flexmb/solver/linearization.h"
#include "flexmb/solver/system_modes.h"
#include "flexmb/vehicle/truck.h"

namespace flexmb::cli {

/// The standing truck of a lane-change file, as built by StandingTruckState.
struct StandingTruck {
  vehicle::TruckData data;        ///< the file's truck (elastic_frame set for the elastic frame)
  vehicle::TruckHandles handles;  ///< its entities in the model
  std::string frame;              ///< "rigid" or "elastic"
};

/// Builds the truck of the lane-change file `path` standing (speed 0, no
/// steering, drive or brake torque; road friction of the file) into `am`
/// (finalized, state consistent) with the frame `frame` ("rigid" or
/// "elastic"; empty: the file's `frame`; the elastic frame reduced as for a
/// run). `at` "statics": moved to static equilibrium (Newton with the
/// pseudo-transient matrix K_t + C / tau + M / tau^2, tau = 1 s, since
/// nothing holds the truck's horizontal position, yaw and wheel spin at rest
/// but the tires' slip damping and SolveStatics stops at the singular K_t),
/// a = 0; "initial": the built state (the lever-rule preloads), a its
/// accelerations. Throws InputError naming the file for a bad file, frame or
/// `at`, NumericalError when there is no equilibrium.
void StandingTruckState(const std::string& path, const std::string& frame, const std::string& at,
                        AnalysisModel& am, VecX& a, std::vector<std::string>& warnings, StandingTruck& truck);

/// The dominant motion of one mode of the standing truck.
struct TruckModeName {
  /// "bounce", "pitch", "roll", "lateral", "longitudinal", "yaw" (the sprung
  /// parts: frame, cab, powertrain, cargo, steering parts, moving as one
  /// rigid body), "front axle hop", "front axle tramp" (and "wind-up",
  /// "lateral", "fore-aft", "yaw"; likewise "rear axle ..."; an axle with
  /// its wheels, knuckles, arm and tire patches as one rigid body), "<body>
  /// on its mounts" (the rest of a body's motion relative to these groups),
  /// or "frame torsion" / "frame vertical bending" / "frame lateral bending"
  /// / "frame other" (elastic frame: when the frame's strain energy is at
  /// least half the mode's potential energy; the kind of the free-free frame
  /// mode carrying most of it).
  std::string name;
  double share = 0.0;  ///< the named motion's share of the mode's kinetic (frame: potential) energy [-]
  /// Elastic frame: the frame's strain energy over the mode's potential
  /// energy [-] (0 for a rigid frame).
  double frame_strain_share = 0.0;
  /// Elastic frame: the free-free frame mode (0-based index into the reduced
  /// body's modal coordinates) carrying most of the frame's strain energy
  /// (-1 for a rigid frame).
  int frame_mode = -1;
};

/// Names the modes `modes` of the linearized standing truck `sys` (built in
/// `m` by BuildTruck; handles `h`) by their kinetic energy: each group
/// (sprung parts, front axle, rear axle) is fitted by a rigid motion about
/// its centre of mass (mass-weighted least squares), the six components'
/// energies and each body's remaining energy compete, the largest names the
/// mode. Rigid (zero) modes get the name of their motion too.
/// `s` is the state linearized about; `frame_body` the elastic frame's
/// reduced body (nullptr: rigid frame).
std::vector<TruckModeName> NameTruckModes(const Model& m, const vehicle::TruckHandles& h, const State& s,
                                          const LinearizedSystem& sys, const std::vector<SystemMode>& modes,
                                          const reduction::ReducedBody* frame_body);

/// One free-free flexible mode of the elastic frame.
struct FrameFreeMode {
  double frequency_hz = 0.0;  ///< sqrt(k_jj / m_jj) / (2 pi) of the reduced body's modal coordinate j [Hz]
  std::string kind;           ///< FrameModeKinds
};

/// The free-free flexible modes of a reduced frame with an orthonormal
/// (diagonal) modal basis, in the order of its modal coordinates.
std::vector<FrameFreeMode> FrameFreeModes(const reduction::ReducedBody& body);

/// Kind of each flexible mode (modal coordinate) of a reduced ladder frame
/// with free-free orthonormal modes (x along the rails, y across, the frame
/// symmetric about y = 0): with the node pairs mirrored about y = 0, the
/// largest of the sums over pairs of (u_z,left + u_z,right)^2 "vertical
/// bending", (u_z,left - u_z,right)^2 "torsion", (u_y,left + u_y,right)^2
/// "lateral bending" and of everything else "other".
std::vector<std::string> FrameModeKinds(const reduction::ReducedBody& body);

}  // namespace flexmb::cli
