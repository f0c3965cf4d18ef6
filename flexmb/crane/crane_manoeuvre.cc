#include "flexmb/crane/crane_manoeuvre.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <vector>

#include "flexmb/crane/crane_motion.h"

namespace flexmb::crane {
namespace {

// base with the keys of `over` replaced, maps merged key by key
YAML::Node Merge(const YAML::Node& base, const YAML::Node& over) {
  if (!base.IsMap() || !over.IsMap()) return over;
  YAML::Node out(YAML::NodeType::Map);
  for (const auto& kv : base) out[kv.first.Scalar()] = kv.second;
  for (const auto& kv : over) {
    const std::string& k = kv.first.Scalar();
    const YAML::Node& view = out;
    const YAML::Node old = view[k];
    out[k] = old ? Merge(old, kv.second) : kv.second;
  }
  return out;
}

// a move or a list of moves at m[key]
std::vector<YAML::Node> Moves(const YAML::Node& m, const char* key, YamlContext& ctx) {
  const YAML::Node v = m[key];
  if (!v) return {};
  if (v.IsMap()) return {v};
  if (!v.IsSequence()) ctx.Fail(v, std::string("expected '") + key + "' as a move (a map) or a list of moves");
  return std::vector<YAML::Node>(v.begin(), v.end());
}

// the moves at m[key], each read by `fill` (after its keys `keys` are
// checked and its start, speed and until read) and checked
template <class Fill>
std::vector<TrapezoidMove> ReadMoves(const YAML::Node& m, const char* key, std::initializer_list<const char*> keys,
                                     YamlContext& ctx, Fill&& fill) {
  std::vector<TrapezoidMove> out;
  for (const YAML::Node& n : Moves(m, key, ctx)) {
    ctx.CheckKeys(n, keys);
    TrapezoidMove mv;
    mv.start = ctx.Double(n, "start");
    mv.speed = ctx.Double(n, "speed");
    mv.until = ctx.Double(n, "until", -1.0);
    fill(n, mv);
    const std::string why = CheckMove(mv);
    if (!why.empty()) ctx.Fail(n, why);
    out.push_back(mv);
  }
  return out;
}

// hoist: {start, speed [m/s of rope, + hauls in], ramp, stop_ramp, distance | until}
std::vector<TrapezoidMove> HoistMoves(const YAML::Node& m, YamlContext& ctx) {
  return ReadMoves(m, "hoist", {"start", "speed", "ramp", "stop_ramp", "distance", "until"}, ctx,
                   [&](const YAML::Node& n, TrapezoidMove& mv) {
                     mv.ramp = ctx.Double(n, "ramp", 0.5);
                     mv.stop_ramp = ctx.Double(n, "stop_ramp", mv.ramp);
                     mv.distance = ctx.Double(n, "distance", -1.0);
                   });
}

// slew: {start, speed [rad/s], acceleration, deceleration [rad/s^2], angle_deg | until}
std::vector<TrapezoidMove> SlewMoves(const YAML::Node& m, YamlContext& ctx) {
  return ReadMoves(m, "slew", {"start", "speed", "acceleration", "deceleration", "angle_deg", "until"}, ctx,
                   [&](const YAML::Node& n, TrapezoidMove& mv) {
                     const double acc = ctx.Positive(n, "acceleration");
                     const double dec = ctx.Double(n, "deceleration", acc);
                     if (!(dec > 0)) ctx.Fail(n["deceleration"], "'deceleration' must be positive [rad/s^2]");
                     mv.ramp = std::abs(mv.speed) / acc;
                     mv.stop_ramp = std::abs(mv.speed) / dec;
                     if (n["angle_deg"]) mv.distance = ctx.Positive(n, "angle_deg") * kRadPerDeg;
                   });
}

// the hoist's extremes: hauled in (> 0) and paid out (> 0) at any time
std::pair<double, double> HoistExtremes(const std::vector<TrapezoidMove>& moves) {
  double hauled = 0, paid = 0;
  for (const TrapezoidMove& a : moves)
    for (double t : {a.start, a.start + a.ramp, a.CruiseEnd(), a.End()}) {
      double s = 0;
      for (const TrapezoidMove& b : moves) s += b.At(t);
      hauled = std::max(hauled, s);
      paid = std::max(paid, -s);
    }
  return {hauled, paid};
}

// the luffing cylinder's length over time; each move's target within the stroke
std::string LuffExpression(const YAML::Node& m, const CraneData& d, const BoomPoints& b, double length0,
                           YamlContext& ctx) {
  std::string expr = Num(length0);
  double from = length0, after = -1e300;
  for (const YAML::Node& n : Moves(m, "luff", ctx)) {
    ctx.CheckKeys(n, {"start", "to_deg", "duration"});
    CosineRamp r;
    r.start = ctx.Double(n, "start");
    r.duration = ctx.Positive(n, "duration");
    if (r.start < after) ctx.Fail(n["start"], "a luffing move must start after the one before has ended");
    const double to_deg = ctx.Double(n, "to_deg");
    r.from = from;
    r.to = CylinderLength(d, b, to_deg);
    if (r.to < d.stroke_min || r.to > d.stroke_max)
      ctx.Fail(n["to_deg"], fmt::format("the boom at {} deg needs the luffing cylinder at {:.4f} m, outside its "
                                        "stroke [{}, {}] m",
                                        Num(to_deg), r.to, Num(d.stroke_min), Num(d.stroke_max)));
    expr += " + " + r.Expression();
    from = r.to;
    after = r.start + r.duration;
  }
  return expr;
}

struct Reader {
  const std::string& folder;
  double g;
  std::map<std::string, BoomPoints> booms;  // by body file

  CraneSetup Read(const YAML::Node& crane, YamlContext& ctx) {
    CraneSetup s;
    s.data = ReadCraneData(crane, ctx);
    std::string path;
    if (s.data.boom_type == "flexible") {
      std::filesystem::path p(s.data.boom_file.Scalar());
      if (p.is_relative()) p = std::filesystem::path(folder) / p;
      path = p.string();
    }
    const auto key = path + "|" + std::to_string(s.data.foot_node) + "," + std::to_string(s.data.head_node) + "," +
                     std::to_string(s.data.eye_node);
    if (path.empty() || !booms.count(key)) booms[key] = ReadBoomPoints(s.data, path, ctx);
    s.boom = booms[key];
    s.geometry = PlaceCrane(s.data, s.boom, g, ctx);
    s.luffing = Num(s.geometry.cylinder_length);
    s.hoist = "0";
    s.slew = "0";
    return s;
  }
};

// applies the crane keys of manoeuvre m to s and removes them from m
void Translate(YAML::Node m, CraneSetup& s, YamlContext& ctx) {
  const std::vector<TrapezoidMove> hoist = HoistMoves(m, ctx);
  const auto [hauled, paid] = HoistExtremes(hoist);
  const CraneData& d = s.data;
  if (hauled / d.falls >= s.geometry.hook_drop)
    ctx.Fail(m["hoist"], fmt::format("the hoist hauls in {:.3f} m of rope: the hook block ({:.3f} m below the boom "
                                     "head on {} falls) would run into the sheave",
                                     hauled, s.geometry.hook_drop, d.falls));
  if (d.rope_on_drum >= 0 && paid > d.rope_on_drum)
    ctx.Fail(m["hoist"], fmt::format("the hoist pays out {:.3f} m of rope, more than the {} m on the drum (the drum "
                                     "would be empty)",
                                     paid, Num(d.rope_on_drum)));
  s.hoist = SumExpression(hoist, -1.0 / d.drum_radius);
  s.slew = SumExpression(SlewMoves(m, ctx), 1.0);
  s.luffing = LuffExpression(m, d, s.boom, s.geometry.cylinder_length, ctx);
  if (m["release_time"]) {
    const double t = ctx.Double(m, "release_time");
    if (!(d.release_mass > 0))
      ctx.Fail(m["release_time"], "'release_time' opens the grab: give the payload a 'release_mass'");
    if (!m["joints"]) m["joints"] = YAML::Node(YAML::NodeType::Map);
    YAML::Node joints = m["joints"];
    if (!joints.IsMap()) ctx.Fail(joints, "expected 'joints' as a map: joint name -> {release_time: t}");
    joints["grab"] = YAML::Node(YAML::NodeType::Map);
    joints["grab"]["release_time"] = t;
  }
  for (const char* k : {"hoist", "slew", "luff", "release_time", "crane"}) m.remove(k);
}

}  // namespace

CraneSetup SelectCraneManoeuvre(YAML::Node& root, const std::string& requested, const std::string& folder, double g,
                                YamlContext& ctx) {
  Reader reader{folder, g, {}};
  std::string name = requested;
  if (name.empty() && root["manoeuvre"] && root["manoeuvre"].IsScalar()) name = root["manoeuvre"].Scalar();
  YAML::Node all = root["manoeuvres"];
  CraneSetup selected;
  bool found = false;
  if (all && all.IsMap()) {
    for (auto kv : all) {
      YAML::Node m = kv.second;
      if (!m.IsMap()) continue;  // a null entry (the file as written) or an error for the manoeuvre reader
      const std::string mname = kv.first.Scalar();
      ctx.SetEntity("manoeuvre '" + mname + "'");
      if (m["crane"] && !m["crane"].IsMap())
        ctx.Fail(m["crane"], "expected 'crane' as a map of the crane's keys to replace");
      if (m["drivers"] && m["drivers"].IsMap())
        for (const char* d : {"luffing", "hoist_drive", "slew_drive"})
          if (m["drivers"][d])
            ctx.Fail(m["drivers"][d],
                     std::string("the crane's driver '") + d + "' is set by the manoeuvre's hoist, slew and luff moves");
      CraneSetup s = reader.Read(m["crane"] ? Merge(root["crane"], m["crane"]) : root["crane"], ctx);
      ctx.SetEntity("manoeuvre '" + mname + "'");
      Translate(m, s, ctx);
      if (mname == name) {
        selected = std::move(s);
        found = true;
      }
    }
  }
  if (!found) selected = reader.Read(root["crane"], ctx);
  return selected;
}

}  // namespace flexmb::crane
