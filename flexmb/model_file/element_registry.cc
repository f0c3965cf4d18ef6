#include "flexmb/model_file/element_registry.h"

#include <stdexcept>

namespace flexmb {

const char* KindName(ElementKind kind) {
  switch (kind) {
    case ElementKind::kBody: return "body";
    case ElementKind::kJoint: return "joint";
    case ElementKind::kDriver: return "driver";
    case ElementKind::kForce: return "force";
    case ElementKind::kSensor: return "sensor";
  }
  return "element";
}

void ElementRegistry::Add(ElementKind kind, std::string name, ElementParser parse) {
  if (Find(kind, name))
    throw std::logic_error(std::string("duplicate ") + KindName(kind) + " type '" + name + "'");
  types_.push_back({kind, std::move(name), parse});
}

const ElementType* ElementRegistry::Find(ElementKind kind, const std::string& name) const {
  for (const ElementType& t : types_)
    if (t.kind == kind && t.name == name) return &t;
  return nullptr;
}

std::vector<std::string> ElementRegistry::Names(ElementKind kind) const {
  std::vector<std::string> names;
  for (const ElementType& t : types_)
    if (t.kind == kind) names.push_back(t.name);
  return names;
}

const ElementRegistry& ModelFileTypes() {
  static const ElementRegistry registry = [] {
    ElementRegistry r;
    RegisterBodyTypes(r);
    RegisterJointTypes(r);
    RegisterForceTypes(r);
    RegisterSensorTypes(r);
    RegisterVehicleTypes(r);
    return r;
  }();
  return registry;
}

}  // namespace flexmb
