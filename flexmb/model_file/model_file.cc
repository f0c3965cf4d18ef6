#include "flexmb/model_file/model_file.h"

#include <yaml-cpp/yaml.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <type_traits>

#include "flexmb/common/error.h"
#include "flexmb/crane/crane_template.h"
#include "flexmb/model/model.h"
#include "flexmb/model_file/body_entry.h"
#include "flexmb/model_file/ancf_body_parser.h"
#include "flexmb/model_file/element_registry.h"
#include "flexmb/model_file/parse_context.h"
#include "flexmb/model_file/solver_section.h"

namespace flexmb {
namespace {

// the list at root[key], or an undefined node if absent
YAML::Node List(const YAML::Node& node, const char* key, const ParseContext& ctx) {
  const YAML::Node v = node[key];
  if (v && !v.IsSequence())
    ctx.Fail(v, std::string("expected '") + key + "' as a list of entries ('- ...')");
  return v;
}

void ParseGround(const YAML::Node& node, ParseContext& ctx) {
  ctx.SetEntity("ground");
  ctx.CheckKeys(node, {"markers", "shape"});
  if (node["shape"]) ParseBodyShape(node["shape"], ctx.model().bodies[0]->shape, ctx);
  ParseBodyMarkers(node, 0, ctx);
}

// every entry of the top-level list root[key]
void ParseList(const YAML::Node& root, const char* key, ElementKind kind, ParseContext& ctx) {
  const YAML::Node list = List(root, key, ctx);
  if (!list) return;
  int k = 0;
  for (const YAML::Node& entry : list) ParseElement(kind, entry, k++, ctx);
}

void ParseSolver(const YAML::Node& node, ParseContext& ctx) {
  ctx.SetEntity("solver");
  ReadSolverSection(node, ctx, ctx.model().solver);
}

void ParseOutput(const YAML::Node& node, ParseContext& ctx) {
  ctx.SetEntity("output");
  ctx.CheckKeys(node, {"interval", "animation", "animation_interval", "deformation_scale"});
  OutputSettings& o = ctx.model().output;
  o.interval = ctx.Double(node, "interval", o.interval);
  if (o.interval < 0.0) ctx.Fail(node["interval"], "'interval' must not be negative (0 = every step)");
  o.animation = ctx.Bool(node, "animation", o.animation);
  o.animation_interval = ctx.Double(node, "animation_interval", o.animation_interval);
  if (!(o.animation_interval > 0.0))
    ctx.Fail(node["animation_interval"], "'animation_interval' must be positive");
  o.deformation_scale = ctx.Double(node, "deformation_scale", o.deformation_scale);
  if (!(o.deformation_scale >= 0.0) || !std::isfinite(o.deformation_scale))
    ctx.Fail(node["deformation_scale"], "'deformation_scale' must be a finite number >= 0");
}

// the entry named `name` of the top-level list root[key] (a driver, a force)
YAML::Node NamedEntry(const YAML::Node& root, const char* key, const std::string& name) {
  const YAML::Node list = root[key];
  if (list && list.IsSequence())
    for (const YAML::Node& e : list)
      if (e.IsMap() && e["name"] && e["name"].IsScalar() && e["name"].Scalar() == name) return e;
  return YAML::Node(YAML::NodeType::Undefined);
}

void BuildSections(const YAML::Node& root, ParseContext& ctx, const SolverOverrides& overrides);

// The names a manoeuvre's section uses: the section of the file, the entry
// in "the file has no X named" and "the keys of X", what the map holds.
struct ManoeuvreSection {
  const char* section;
  const char* missing;
  const char* entry;
  const char* holds;
};

// Checks a manoeuvre's map m[section] of entry name -> keys (the entry
// exists in the file's section; refuse(key) is the error for a key a
// manoeuvre may not set, empty if it may) and, with `apply`, sets the keys.
void ReplaceEntryKeys(YAML::Node& root, const YAML::Node& m, const ManoeuvreSection& sec, bool apply,
                      ParseContext& ctx, const std::function<std::string(const std::string&)>& refuse) {
  const YAML::Node map = m[sec.section];
  if (!map) return;
  if (!map.IsMap())
    ctx.Fail(map, std::string("expected '") + sec.section + "' as a map: " + sec.entry + " name -> " + sec.holds);
  for (const auto& kv : map) {
    YAML::Node e = NamedEntry(root, sec.section, kv.first.Scalar());
    if (!e) ctx.Fail(kv.first, std::string("the file has no ") + sec.missing + " named '" + kv.first.Scalar() + "'");
    if (!kv.second.IsMap())
      ctx.Fail(kv.second, std::string("expected the keys of ") + sec.entry + " '" + kv.first.Scalar() + "' to replace");
    for (const auto& key : kv.second) {
      const std::string why = refuse(key.first.Scalar());
      if (!why.empty()) ctx.Fail(key.first, why);
      if (apply) e[key.first.Scalar()] = key.second;
    }
  }
}

// Checks one entry of `manoeuvres` (its keys, and that the drivers and
// force elements it names exist); with `apply`, replaces the file's values
// by its own, in place: solver keys, driver functions, keys of force
// entries, joint release times, bodies' initial states (docs/model-file.md,
// "Manoeuvres").
void Manoeuvre(YAML::Node& root, const std::string& name, const YAML::Node& m, bool apply, ParseContext& ctx) {
  ctx.SetEntity("manoeuvre '" + name + "'");
  if (m.IsNull()) return;  // the file as written
  ctx.CheckKeys(m, {"description", "solver", "drivers", "forces", "joints", "bodies"});
  if (const YAML::Node solver = m["solver"]) {
    if (!solver.IsMap()) ctx.Fail(solver, "expected 'solver' as a map of solver keys");
    if (apply) {
      if (!root["solver"]) root["solver"] = YAML::Node(YAML::NodeType::Map);
      YAML::Node target = root["solver"];
      for (const auto& kv : solver) target[kv.first.Scalar()] = kv.second;
    }
  }
  if (const YAML::Node drivers = m["drivers"]) {
    if (!drivers.IsMap()) ctx.Fail(drivers, "expected 'drivers' as a map: driver name -> its function");
    for (const auto& kv : drivers) {
      YAML::Node d = NamedEntry(root, "drivers", kv.first.Scalar());
      if (!d) ctx.Fail(kv.first, "the file has no driver named '" + kv.first.Scalar() + "'");
      if (apply) d["function"] = kv.second;
    }
  }
  // force values; a body's initial state (the machine: masses, shapes,
  // markers stays); a joint's release time (markers and type make the machine)
  ReplaceEntryKeys(root, m, {"forces", "force element", "force", "keys to replace"}, apply, ctx,
                   [](const std::string& k) -> std::string {
                     return k == "name" || k == "type" ? "a manoeuvre replaces a force's values, not its '" + k + "'"
                                                       : "";
                   });
  ReplaceEntryKeys(root, m, {"bodies", "body", "body", "its initial state"}, apply, ctx, [](const std::string& k) {
    return k == "position" || k == "orientation" || k == "velocity" || k == "angular_velocity"
               ? std::string()
               : "a manoeuvre sets a body's initial state (position, orientation, velocity, angular_velocity), not "
                 "its '" + k + "'";
  });
  ReplaceEntryKeys(root, m, {"joints", "joint", "joint", "{release_time: t}"}, apply, ctx, [](const std::string& k) {
    return k == "release_time" ? std::string() : "a manoeuvre sets a joint's 'release_time' only, not its '" + k + "'";
  });
}

// Checks every entry of `manoeuvres` and applies the selected one (the
// caller's, else the file's `manoeuvre`); returns its name ("" if none).
std::string ApplyManoeuvre(YAML::Node& root, const std::string& requested, ParseContext& ctx) {
  ctx.SetEntity("manoeuvres");
  const YAML::Node all = root["manoeuvres"];
  if (all && !all.IsMap()) ctx.Fail(all, "expected 'manoeuvres' as a map of named manoeuvres");
  std::string name = requested;
  if (name.empty() && root["manoeuvre"]) name = ctx.String(root, "manoeuvre");
  std::string names;
  if (all)
    for (const auto& kv : all) {
      names += (names.empty() ? "" : ", ") + kv.first.Scalar();
      if (kv.first.Scalar() != name) Manoeuvre(root, kv.first.Scalar(), kv.second, false, ctx);
    }
  if (name.empty()) return "";
  if (!all || !all[name]) {
    ctx.SetEntity("manoeuvres");
    const std::string msg = "no manoeuvre named '" + name + "' in the file (" +
                            (names.empty() ? std::string("it defines none") : "defined: " + names) + ")";
    if (requested.empty()) ctx.Fail(root["manoeuvre"], msg);
    throw InputError("--manoeuvre " + name + ": " + msg, {ctx.file(), 0, ""});
  }
  Manoeuvre(root, name, all[name], true, ctx);
  return name;
}

void BuildModel(YAML::Node& root, ParseContext& ctx, const SolverOverrides& overrides) {
  if (!root || root.IsNull()) ctx.Fail(root, "the model file is empty");
  // a crane file: the crane template's entries first (docs/crane-file.md)
  crane::ExpandCraneFile(root, overrides.manoeuvre, ctx);
  ctx.CheckKeys(root, {"name", "gravity", "ground", "bodies", "joints", "drivers", "forces", "sensors",
                       "solver", "output", "manoeuvres", "manoeuvre"});
  Model& model = ctx.model();
  model.manoeuvre = ApplyManoeuvre(root, overrides.manoeuvre, ctx);
  ctx.SetEntity("");
  if (!model.manoeuvre.empty()) {
    // a replaced value is read where the file's own was: say which manoeuvre
    try {
      BuildSections(root, ctx, overrides);
    } catch (const InputError& e) {
      throw InputError(e.message() + " (manoeuvre '" + model.manoeuvre + "')", e.context());
    } catch (const YAML::Exception& e) {
      throw InputError(e.msg + " (manoeuvre '" + model.manoeuvre + "')",
                       {ctx.file(), e.mark.is_null() ? 0 : e.mark.line + 1, ctx.entity()});
    }
    return;
  }
  BuildSections(root, ctx, overrides);
}

// the sections of the model file, in their order, and Model::Finalize
void BuildSections(const YAML::Node& root, ParseContext& ctx, const SolverOverrides& overrides) {
  Model& model = ctx.model();
  model.name = ctx.String(root, "name", model.name);
  model.gravity_W = ctx.Vector3(root, "gravity", model.gravity_W);
  if (root["ground"]) ParseGround(root["ground"], ctx);
  ParseList(root, "bodies", ElementKind::kBody, ctx);
  ParseList(root, "joints", ElementKind::kJoint, ctx);
  ParseList(root, "drivers", ElementKind::kDriver, ctx);
  ParseList(root, "forces", ElementKind::kForce, ctx);
  CheckHoistRopeFeeds(ctx);
  ParseList(root, "sensors", ElementKind::kSensor, ctx);
  if (root["solver"]) ParseSolver(root["solver"], ctx);
  if (root["output"]) ParseOutput(root["output"], ctx);
  if (overrides.t_end || overrides.dt) {
    ctx.SetEntity("solver");
    try {
      ApplySolverOverrides(overrides, model.solver);
    } catch (const InputError& e) {
      throw InputError(e.message(), {ctx.file(), 0, "solver"});
    }
  }
  ctx.SetEntity("");
  try {
    model.Finalize();
  } catch (const InputError& e) {
    const auto it = ctx.lines().find(e.context().entity);
    throw InputError(e.message(), {ctx.file(), it == ctx.lines().end() ? 0 : it->second, e.context().entity});
  }
}

}  // namespace

void ParseElement(ElementKind kind, const YAML::Node& node, int k, ParseContext& ctx) {
  const std::string kind_name = KindName(kind);
  ctx.SetEntity(kind_name + " #" + std::to_string(k + 1));
  if (!node.IsMap()) ctx.CheckKeys(node, {});
  // a body's parser reads (and checks) its own name after its keys
  std::string name;
  if (kind != ElementKind::kBody) {
    name = ctx.String(node, "name");
    ctx.SetEntity(kind_name + " '" + name + "'");
  }
  const char* fallback = kind == ElementKind::kBody ? "rigid" : kind == ElementKind::kDriver ? "coordinate" : nullptr;
  const std::string type = fallback ? ctx.String(node, "type", fallback) : ctx.String(node, "type");
  const ElementType* t = ModelFileTypes().Find(kind, type);
  if (!t) {
    std::string list;
    for (const std::string& n : ModelFileTypes().Names(kind)) list += (list.empty() ? "" : ", ") + n;
    if (kind != ElementKind::kBody)
      ctx.Fail(node["type"], "unknown " + kind_name + " type '" + type + "' (allowed: " + list + ")");
    if (node["name"].IsScalar()) ctx.SetEntity("body '" + node["name"].Scalar() + "'");
    ctx.Fail(node["type"], "body type '" + type + "' is not supported yet (supported: " + list + ")");
  }
  ctx.Guard(node, [&] { t->parse(node, name, ctx); });
  // a driver is a joint of the model: errors of Model::Finalize name it so
  if (kind != ElementKind::kBody)
    ctx.lines()[(kind == ElementKind::kDriver ? std::string("joint") : kind_name) + " '" + name + "'"] =
        ParseContext::Line(node);
}

std::unique_ptr<Model> LoadModelString(const std::string& yaml, const std::string& name_for_messages,
                                       const SolverOverrides& overrides) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw InputError("YAML syntax error: " + e.msg,
                     {name_for_messages, e.mark.is_null() ? 0 : e.mark.line + 1, ""});
  }
  auto model = std::make_unique<Model>();
  ParseContext ctx(name_for_messages, *model);
  try {
    BuildModel(root, ctx, overrides);
  } catch (const YAML::Exception& e) {
    throw InputError(e.msg, {name_for_messages, e.mark.is_null() ? 0 : e.mark.line + 1, ctx.entity()});
  }
  return model;
}

std::unique_ptr<Model> LoadModelFile(const std::string& path, const SolverOverrides& overrides) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError("cannot open the model file: it is a directory", {path, 0, ""});
  std::ifstream in(path);
  if (!in)
    throw InputError("cannot open the model file: " + std::string(std::strerror(errno)), {path, 0, ""});
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError("cannot read the model file", {path, 0, ""});
  return LoadModelString(text.str(), path, overrides);
}

}  // namespace flexmb
