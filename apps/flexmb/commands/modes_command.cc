#include "apps/flexmb/commands/modes_command.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "apps/flexmb/commands/analysis_support.h"
#include "apps/flexmb/commands/lane_change.h"
#include "flexmb/common/json_text.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/results/vtk_animation.h"
#include "flexmb/solver/assembler.h"
#include "flexmb/solver/simulator.h"
#include "flexmb/solver/statics.h"
#include "flexmb/solver/system_modes.h"

namespace flexmb::cli {
namespace {

std::string ModesArray(const VecX& v) {
  std::string s = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) s += (i ? ", " : "") + io::JsonNumber(v(i));
  return s + "]";
}

// one animation of mode `mode` over one period in dir
void ModesAnimation(const Model& m, const State& s0, const SystemMode& mode, const ModesCommandOptions& opt,
                    const std::filesystem::path& dir) {
  VtkAnimationWriter anim(dir.string(), m);
  const double f = mode.damped_frequency_hz > 0.0 ? mode.damped_frequency_hz : 0.0;
  const double period = f > 0.0 ? 1.0 / f : 1.0;
  State st = s0;
  VecX dx(m.nv);
  for (int j = 0; j <= opt.frames; ++j) {
    const double th = 2.0 * std::numbers::pi * j / opt.frames;
    // oscillatory: Re(x e^{i th}); without a period a sine sweep of the shape
    if (f > 0.0)
      dx = opt.amplitude * (std::cos(th) * mode.shape - std::sin(th) * mode.shape_imag);
    else
      dx = opt.amplitude * std::sin(th) * mode.shape;
    RetractAll(m, s0.q, dx, st.q);
    st.t = period * j / opt.frames;
    anim.WriteFrame(st);
  }
}

}  // namespace

int ModesCommand(const ModesCommandOptions& opt) { return ModesAnalysis(opt).code; }

ModesResult ModesAnalysis(const ModesCommandOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  ModesResult out;
  JsonObjectText sum;
  std::vector<std::string>& warnings = out.warnings;
  std::string status = "ok", message;
  int code = 0, dof = 0, rigid = 0, reported = 0;
  AnalysisModel am;
  const Model* used = nullptr;  // the model analysed (am's or the source's)
  if (!CreateAnalysisDir(opt.out_dir, opt.err)) {
    out.code = 2, out.error_kind = "InputError", out.message = opt.out_dir + ": cannot create the output directory";
    return out;
  }
  const std::filesystem::path dir(opt.out_dir);
  try {
    if (opt.count < 1) throw InputError("--count must be at least 1");
    if (opt.frames < 2) throw InputError("--frames must be at least 2");
    if (!(opt.amplitude > 0.0) || !std::isfinite(opt.amplitude)) throw InputError("--amplitude must be positive");
    VecX a;
    // a lane-change file: the truck standing on its tires
    const bool truck = !opt.source && opt.model_text.empty() && vehicle::IsLaneChangeFile(opt.model_path);
    StandingTruck standing;
    if (truck)
      StandingTruckState(opt.model_path, opt.frame, opt.at, am, a, warnings, standing);
    else if (!opt.frame.empty())
      throw InputError("--frame is for lane-change (truck) files only");
    const Model& m = truck ? *am.model
                           : AnalysisLinearizationModel(opt.model_path, opt.model_text, opt.at, opt.time, opt.source,
                                                        am, a, warnings);
    used = &m;
    if (opt.err)
      for (const std::string& w : warnings) std::fprintf(opt.err, "warning: %s\n", w.c_str());
    const LinearizedSystem sys = Linearize(m, am.state, a, am.ws);
    dof = static_cast<int>(sys.N.cols());
    const std::vector<SystemMode> all = SolveSystemModes(sys);
    std::vector<const SystemMode*> modes;
    for (const SystemMode& md : all) {
      if (md.kind == ModeKind::kRigid) ++rigid;
      if (md.kind == ModeKind::kRigid || reported < opt.count) {
        modes.push_back(&md);
        if (md.kind != ModeKind::kRigid) ++reported;
      }
    }
    for (const SystemMode* md : modes) out.modes.push_back(*md);
    if (truck) {
      out.names = NameTruckModes(m, standing.handles, am.state, sys, out.modes, standing.data.elastic_frame.get());
      if (standing.data.elastic_frame) out.frame_free_modes = FrameFreeModes(*standing.data.elastic_frame);
    }
    // table and JSON
    std::string csv = "mode,kind,frequency_hz,damped_frequency_hz,damping_ratio,eigenvalue_real,eigenvalue_imag";
    csv += truck ? ",name,energy_share\n" : "\n";
    std::string js = "{\n  \"model\": " + io::JsonString(opt.model_path) + ",\n  \"at\": " + io::JsonString(opt.at) +
                     ",\n  \"time\": " + io::JsonNumber(am.state.t) + ",\n  \"dof\": " + std::to_string(dof) +
                     ",\n  \"rigid_modes\": " + std::to_string(rigid) + ",\n  \"coordinates\": [";
    for (int c = 0; c < m.nv; ++c) js += (c ? ", " : "") + io::JsonString(VelocityCoordinateName(m, c));
    js += "],\n  \"modes\": [\n";
    char line[512];
    if (opt.info)
      std::fprintf(opt.info, "model '%s': %d degrees of freedom, %d rigid-body modes\n%5s  %-11s %16s %16s %12s\n",
                   m.name.c_str(), dof, rigid, "mode", "kind", "frequency [Hz]", "damped [Hz]", "damping");
    for (size_t k = 0; k < modes.size(); ++k) {
      const SystemMode& md = *modes[k];
      std::snprintf(line, sizeof line, "%zu,%s,%.15g,%.15g,%.15g,%.15g,%.15g", k + 1, ModeKindName(md.kind),
                    md.frequency_hz, md.damped_frequency_hz, md.damping_ratio, md.eigenvalue.real(),
                    md.eigenvalue.imag());
      csv += line;
      const std::string name = truck ? out.names[k].name : "";
      if (truck) {
        std::snprintf(line, sizeof line, ",%s,%.6g", name.c_str(), out.names[k].share);
        csv += line;
      }
      csv += "\n";
      if (opt.info)
        std::fprintf(opt.info, "%5zu  %-11s %16.9g %16.9g %12.6g%s%s\n", k + 1, ModeKindName(md.kind), md.frequency_hz,
                     md.damped_frequency_hz, md.damping_ratio, truck ? "  " : "", name.c_str());
      js += std::string(k ? ",\n" : "") + "    {\"mode\": " + std::to_string(k + 1) +
            ", \"kind\": " + io::JsonString(ModeKindName(md.kind)) +
            (truck ? ", \"name\": " + io::JsonString(out.names[k].name) +
                         ", \"energy_share\": " + io::JsonNumber(out.names[k].share) +
                         ", \"frame_strain_share\": " + io::JsonNumber(out.names[k].frame_strain_share) +
                         ", \"frame_mode\": " + std::to_string(out.names[k].frame_mode)
                   : std::string()) +
            ", \"frequency_hz\": " + io::JsonNumber(md.frequency_hz) +
            ", \"damped_frequency_hz\": " + io::JsonNumber(md.damped_frequency_hz) +
            ", \"damping_ratio\": " + io::JsonNumber(md.damping_ratio) +
            ", \"eigenvalue\": [" + io::JsonNumber(md.eigenvalue.real()) + ", " +
            io::JsonNumber(md.eigenvalue.imag()) + "], \"shape\": " + ModesArray(md.shape) +
            ", \"shape_imag\": " + ModesArray(md.shape_imag) + "}";
    }
    js += "\n  ]";
    if (!out.frame_free_modes.empty()) {
      js += ",\n  \"frame_free_modes\": [";
      for (size_t j = 0; j < out.frame_free_modes.size(); ++j)
        js += std::string(j ? ", " : "") + "{\"frequency_hz\": " + io::JsonNumber(out.frame_free_modes[j].frequency_hz) +
              ", \"kind\": " + io::JsonString(out.frame_free_modes[j].kind) + "}";
      js += "]";
    }
    js += "\n}\n";
    out.model_name = m.name, out.time = am.state.t, out.dof = dof, out.rigid = rigid;
    for (int c = 0; c < m.nv; ++c) out.coordinates.push_back(VelocityCoordinateName(m, c));
    if (!opt.out_dir.empty()) {
      WriteAnalysisFile((dir / "modes.csv").string(), csv);
      WriteAnalysisFile((dir / "modes.json").string(), js);
      if (opt.animation)
        for (size_t k = 0; k < modes.size(); ++k)
          if (modes[k]->kind != ModeKind::kRigid)
            ModesAnimation(m, am.state, *modes[k], opt, dir / ("mode_" + std::to_string(k + 1)));
    }
    if (opt.info && !out.frame_free_modes.empty()) {
      std::fprintf(opt.info, "the elastic frame's free-free modes [Hz]:");
      for (const FrameFreeMode& f : out.frame_free_modes)
        if (f.frequency_hz < 2.0 * out.frame_free_modes.front().frequency_hz)
          std::fprintf(opt.info, " %.3f (%s)", f.frequency_hz, f.kind.c_str());
      std::fprintf(opt.info, "\n");
    }
    if (opt.info) std::fprintf(opt.info, "results in %s\n", opt.out_dir.c_str());
  } catch (const InputError& e) {
    status = "failed", message = AnalysisErrorText(e, opt.model_path), code = 2, out.error_kind = "InputError";
  } catch (const NumericalError& e) {
    status = "failed", message = AnalysisErrorText(e, opt.model_path), code = 1, out.error_kind = "NumericalError";
  } catch (const std::exception& e) {
    status = "failed", message = e.what(), code = 1, out.error_kind = "Error";
  }
  if (code != 0 && opt.err) std::fprintf(opt.err, "error: %s\n", message.c_str());
  sum.Text("status", status);
  sum.Text("message", message);
  sum.Text("analysis", "modes");
  sum.Text("model", opt.model_path);
  sum.Text("model_name", used ? used->name : "");
  sum.Text("at", opt.at);
  sum.Number("time", am.state.t);
  sum.Raw("dof", std::to_string(dof));
  sum.Raw("rigid_modes", std::to_string(rigid));
  sum.Raw("modes", std::to_string(reported));
  sum.Raw("constraint_equations", std::to_string(am.report.equations));
  sum.Raw("redundant_constraints", std::to_string(am.report.redundant.size()));
  sum.Texts("redundant", am.report.messages);
  out.code = FinishAnalysisSummary(sum, opt.out_dir, start, warnings, opt.err, code, &out.summary_json);
  out.message = message;
  if (out.code != 0 && out.error_kind.empty()) out.error_kind = "InputError", out.message = "cannot write summary.json";
  return out;
}

}  // namespace flexmb::cli
