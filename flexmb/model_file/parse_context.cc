#include "flexmb/model_file/parse_context.h"

#include "flexmb/model/model.h"

namespace flexmb {
namespace {

std::string MarkerRefQuoted(const char* key) { return std::string("'") + key + "'"; }

}  // namespace

int ParseContext::Marker(const YAML::Node& node, const char* key) const {
  const std::string ref = String(node, key);
  const YAML::Node v = node[key];
  const size_t dot = ref.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == ref.size())
    Fail(v, "marker reference '" + ref + "' in " + MarkerRefQuoted(key) + " must read 'body.marker'");
  const std::string body = ref.substr(0, dot);
  if (model_.FindBody(body) < 0)
    Fail(v, "marker '" + ref + "' in " + MarkerRefQuoted(key) + ": there is no body named '" + body + "'");
  const int m = model_.FindMarker(ref);
  if (m < 0)
    Fail(v, "marker '" + ref + "' in " + MarkerRefQuoted(key) + ": body '" + body + "' has no marker named '" +
                ref.substr(dot + 1) + "'");
  return m;
}

int ParseContext::Joint(const YAML::Node& node, const char* key) const {
  const std::string name = String(node, key);
  const int j = model_.FindJoint(name);
  if (j < 0) Fail(node[key], "there is no joint named '" + name + "' (in " + MarkerRefQuoted(key) + ")");
  return j;
}

int ParseContext::Force(const YAML::Node& node, const char* key) const {
  const std::string name = String(node, key);
  const int f = model_.FindForce(name);
  if (f < 0) Fail(node[key], "there is no force element named '" + name + "' (in " + MarkerRefQuoted(key) + ")");
  return f;
}

int ParseContext::Body(const YAML::Node& node, const char* key) const {
  const std::string name = String(node, key);
  const int b = model_.FindBody(name);
  if (b < 0) Fail(node[key], "there is no body named '" + name + "' (in " + MarkerRefQuoted(key) + ")");
  return b;
}

void ParseContext::ParseMarkerList(const YAML::Node& node, int body,
                                   std::initializer_list<const char*> allowed,
                                   const std::function<int(const YAML::Node&)>& node_of,
                                   std::map<std::string, int>& lines) {
  const YAML::Node list = MapChild(node, "markers");
  if (!list) return;
  if (!list.IsSequence()) Fail(list, "expected 'markers' as a list of entries ('- ...')");
  const std::string owner = entity();
  const std::string body_name = model_.bodies[body]->name();
  for (const YAML::Node& m : list) {
    SetEntity(owner);
    CheckKeys(m, allowed);
    const std::string name = String(m, "name");
    if (name.empty()) Fail(m["name"], "a marker name must not be empty");
    if (name.find('.') != std::string::npos)
      Fail(m["name"], "a marker name must not contain '.' (it separates body and marker in "
                      "'body.marker'), got '" + name + "'");
    const std::string entity = "marker '" + body_name + "." + name + "'";
    SetEntity(entity);
    const int k = node_of ? node_of(m) : -1;
    const Vec3 p = Vector3(m, "position", Vec3::Zero());
    const Mat3 R = Orientation(m, "orientation");
    Guard(m, [&] { return model_.AddMarker(body, name, p, R, k); });
    lines[entity] = Line(m);
  }
  SetEntity(owner);
}

}  // namespace flexmb
