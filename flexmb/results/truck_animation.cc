#include "flexmb/results/truck_animation.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/common/error.h"
#include "flexmb/joints/joint.h"
#include "flexmb/model/model.h"
#include "flexmb/model/state.h"

namespace flexmb::vehicle {
namespace {

constexpr unsigned char kTruckAnimLine = 3, kTruckAnimQuad = 9;
constexpr double kTruckAnimLineWidth = 0.12;  // painted line width [m]
constexpr double kTruckAnimLineZ = 0.002;     // lines just above the road [m]

constexpr double kTruckAnimHubSize = 0.12, kTruckAnimHubWidth = 0.3;  // axle hub box [m]
constexpr double kTruckAnimPatchLength = 0.2, kTruckAnimPatchThickness = 0.02;  // contact patch box [m]
constexpr double kTruckAnimColumnRadius = 0.025;  // steering column [m]
constexpr double kTruckAnimWheelRadius = 0.25, kTruckAnimWheelThickness = 0.04;  // steering wheel [m]
// distance joints drawn as lines between their markers (and each axle's
// additional arm, <axle>_extra_arm)
constexpr const char* kTruckAnimLinks[] = {"drag_link", "tie_rod", "relay_rod"};

// shape axes of the steering column: z along the column, leaning rearwards
// by column_inclination from the vertical
Mat3 TruckAnimColumnAxes(const TruckData& d) {
  const Vec3 ac(-std::sin(d.column_inclination), 0, std::cos(d.column_inclination));
  Mat3 R;
  R.col(0) = Vec3(0, 1, 0);
  R.col(1) = ac.cross(R.col(0));
  R.col(2) = ac;
  return R;
}

// cylinder axis (shape z) along the vehicle's y axis
Mat3 TruckAnimAxisY() {
  Mat3 R;
  R << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  return R;
}

// a painted line from (x0, y) to (x1, y): one quad on the road
void TruckAnimRoadLine(ShapeMesh& m, double x0, double x1, double y) {
  const int b = static_cast<int>(m.points_B.size());
  const double h = 0.5 * kTruckAnimLineWidth;
  m.points_B.emplace_back(x0, y - h, kTruckAnimLineZ);
  m.points_B.emplace_back(x1, y - h, kTruckAnimLineZ);
  m.points_B.emplace_back(x1, y + h, kTruckAnimLineZ);
  m.points_B.emplace_back(x0, y + h, kTruckAnimLineZ);
  m.cell_types.push_back(kTruckAnimQuad);
  m.cell_sizes.push_back(4);
  for (int k = 0; k < 4; ++k) m.connectivity.push_back(b + k);
}

// the corridor's lines (sections 1 and 3; section 2 has none) and the
// course centre line as a polyline, on the ground (body 0)
ShapeMesh TruckAnimCorridor(const LaneChangeCourse& course) {
  const LaneChangeCourseData& c = course.data();
  ShapeMesh m;
  m.body = 0;
  const double x_start = std::min(0.0, c.start_x) - 10.0, x_end = c.start_x + course.TestDistance() + 10.0;
  const double x2 = c.start_x + c.section1_length, x3 = x2 + c.section2_length;
  TruckAnimRoadLine(m, x_start, x2, 0.5 * c.section1_width);
  TruckAnimRoadLine(m, x_start, x2, -0.5 * c.section1_width);
  TruckAnimRoadLine(m, x3, x_end, c.offset + 0.5 * c.section3_width);
  TruckAnimRoadLine(m, x3, x_end, c.offset - 0.5 * c.section3_width);
  const int n = static_cast<int>(std::ceil((x_end - x_start) / 0.5));
  const int b = static_cast<int>(m.points_B.size());
  for (int k = 0; k <= n; ++k) {
    const double x = x_start + (x_end - x_start) * k / n;
    m.points_B.emplace_back(x, course.CentreLine(x), kTruckAnimLineZ);
  }
  for (int k = 0; k < n; ++k) {
    m.cell_types.push_back(kTruckAnimLine);
    m.cell_sizes.push_back(2);
    m.connectivity.push_back(b + k);
    m.connectivity.push_back(b + k + 1);
  }
  return m;
}

// the shape of body `name` when it is a part of an axle (axle, wheel, arm,
// hub, contact patch) or a bogie's beam; false for any other body
bool TruckAnimAxleShape(const TruckData& d, const std::string& name, Shape& s) {
  for (const AxleData& a : d.axles) {
    const TireData& t = a.tire;
    if (name == a.name + "_axle") {
      s.type = Shape::Type::kCylinder;
      s.size = Vec3(a.steered ? 0.07 : 0.1, a.track, 0);
      s.R_BS = TruckAnimAxisY();
      return true;
    }
    if (name == a.name + "_arm") {
      s.type = Shape::Type::kBox;
      s.size = Vec3(a.suspension.arm_length, 0.08, 0.08);
      return true;
    }
    if (name == a.name + "_axle_hub") {
      // from the axle centre up to the additional arm's end
      const double h = a.suspension.extra_arm_height;
      s.type = Shape::Type::kBox;
      s.size = Vec3(kTruckAnimHubSize, kTruckAnimHubWidth, h + kTruckAnimHubSize);
      s.p_BS += Vec3(0, 0, 0.5 * h);
      return true;
    }
    for (int k = 0; k < 2; ++k) {
      if (name == WheelName(a, k)) {
        s.type = Shape::Type::kCylinder;
        s.size = Vec3(t.unloaded_radius, 0.28 * t.count, 0);
        s.R_BS = TruckAnimAxisY();
        return true;
      }
      if (name == WheelName(a, k) + "_patch") {
        // flat on the road under the wheel centre (body frame = vehicle frame, road at z = 0)
        s.type = Shape::Type::kBox;
        s.size = Vec3(kTruckAnimPatchLength, 0.28 * t.count, kTruckAnimPatchThickness);
        s.p_BS.z() = 0.5 * kTruckAnimPatchThickness;
        return true;
      }
    }
  }
  for (size_t b = 0; b < d.bogies.size(); ++b) {
    if (name != "bogie_" + d.bogies[b].name + "_left" && name != "bogie_" + d.bogies[b].name + "_right") continue;
    // a leaf from one axle to the other
    double x_max = -1e300, x_min = 1e300;
    for (const AxleData& a : d.axles)
      if (a.bogie == static_cast<int>(b)) x_max = std::max(x_max, a.x), x_min = std::min(x_min, a.x);
    s.type = Shape::Type::kBox;
    s.size = Vec3(x_max - x_min, 0.09, 0.1);
    s.p_BS.x() = 0.5 * (x_max + x_min);
    return true;
  }
  return false;
}

}  // namespace

void SetTruckShapes(const TruckData& d, Model& model) {
  for (auto& body : model.bodies) {
    const auto* rb = dynamic_cast<const RigidBody*>(body.get());
    if (!rb) continue;
    const std::string& name = body->name();
    Shape s;
    s.p_BS = rb->com_B();
    if (name == "cab") {
      s.type = Shape::Type::kBox;
      s.size = Vec3(1.6, 2.3, 1.8);
    } else if (name == "powertrain") {
      s.type = Shape::Type::kBox;
      s.size = Vec3(1.8, 0.8, 0.9);
    } else if (name == "cargo") {
      s.type = Shape::Type::kBox;
      s.size = Vec3(5.0, 2.3, 1.0);
    } else if (TruckAnimAxleShape(d, name, s)) {
      // an axle's part (axle, wheels, arm, hub, contact patches) or a bogie's beam
    } else if (name.starts_with("knuckle_")) {
      s.type = Shape::Type::kBox;
      s.size = Vec3(0.15, 0.15, 0.25);
    } else if (name == "pitman_arm" || name == "relay_arm") {
      s.type = Shape::Type::kBox;
      s.size = Vec3(0.05, 0.05, d.pitman_arm_length);
    } else if (name == "steering_column") {
      s.type = Shape::Type::kCylinder;
      s.size = Vec3(kTruckAnimColumnRadius, d.column_length, 0);
      s.R_BS = TruckAnimColumnAxes(d);
    } else {
      continue;
    }
    body->shape = s;
  }
}

TruckAnimation::TruckAnimation(const std::string& dir, const TruckData& d, const TruckHandles& h,
                               const LaneChangeCourse& course, const TruckAnimationData& a, Model& model)
    : fps_(a.fps) {
  const ErrorContext ctx{dir, 0, "lane-change animation"};
  if (!(a.fps > 0) || !std::isfinite(a.fps)) throw InputError("animation_fps must be positive", ctx);
  if (!(a.deformation_scale >= 0) || !std::isfinite(a.deformation_scale))
    throw InputError("animation_deformation_scale must be >= 0", ctx);
  SetTruckShapes(d, model);
  model.output.deformation_scale = a.deformation_scale;
  writer_ = std::make_unique<VtkAnimationWriter>(dir, model);
  if (!h.elastic && d.frame_mesh) writer_->AddShapeMesh(MakeMeshShape(h.frame_body, *d.frame_mesh));
  // the steering wheel: a disc at the column's upper end
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) {
    const auto* rb = dynamic_cast<const RigidBody*>(model.bodies[b].get());
    if (!rb || rb->name() != "steering_column") continue;
    Shape wheel;
    wheel.type = Shape::Type::kCylinder;
    wheel.size = Vec3(kTruckAnimWheelRadius, kTruckAnimWheelThickness, 0);
    wheel.R_BS = TruckAnimColumnAxes(d);
    wheel.p_BS = rb->com_B() + 0.5 * d.column_length * wheel.R_BS.col(2);
    writer_->AddShapeMesh(MakeShapeMesh(wheel, b, "steering wheel"));
  }
  std::vector<std::string> links(std::begin(kTruckAnimLinks), std::end(kTruckAnimLinks));
  for (const AxleData& a : d.axles) {
    links.push_back(a.name + "_extra_arm");
    links.push_back("drag_link_" + a.name);  // a second steered axle's
    links.push_back("tie_rod_" + a.name);
  }
  for (const std::string& name : links) {
    const int j = model.FindJoint(name);
    if (j >= 0) writer_->AddLink(model.joints[j]->marker_i, model.joints[j]->marker_j);
  }
  writer_->AddShapeMesh(TruckAnimCorridor(course));
}

bool TruckAnimation::Update(const State& state) {
  if (state.t < static_cast<double>(next_) / fps_ - 1e-9) return false;
  writer_->WriteFrame(state);
  next_ = static_cast<long>(std::floor(state.t * fps_ + 1e-6)) + 1;
  return true;
}

}  // namespace flexmb::vehicle
