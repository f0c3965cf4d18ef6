// The model file's `manoeuvres`: a named entry replaces solver keys, driver
// functions and keys of force elements before the model is built; the
// selection by `manoeuvre` or by the caller; errors at their lines.

#include <gtest/gtest.h>

#include <string>

#include "flexmb/common/error.h"
#include "flexmb/forces/spring_damper.h"
#include "flexmb/joints/motion_driver.h"
#include "flexmb/model_file/model_file.h"

namespace flexmb {
namespace {

constexpr const char* kManoeuvreModel =
    "ground:\n"                                                         // 1
    "  markers: [{name: o}]\n"                                          // 2
    "bodies:\n"                                                         // 3
    "  - {name: arm, mass: 1, inertia: [1, 1, 1], markers: [{name: o}]}\n"  // 4
    "joints:\n"                                                         // 5
    "  - {name: hinge, type: revolute, i: ground.o, j: arm.o}\n"        // 6
    "drivers:\n"                                                        // 7
    "  - {name: swing, joint: hinge, function: 0.5}\n"                  // 8
    "forces:\n"                                                         // 9
    "  - {name: s, type: spring_damper, i: ground.o, j: arm.o, stiffness: 10, free_length: 1}\n"  // 10
    "solver: {t_end: 2, dt: 0.01}\n"                                    // 11
    "manoeuvres:\n"                                                     // 12
    "  as_written: ~\n"                                                 // 13
    "  fast:\n"                                                         // 14
    "    description: swing with a ramp, stiffer spring, longer run\n"  // 15
    "    solver: {t_end: 5}\n"                                          // 16
    "    drivers: {swing: {expression: \"0.1*t\"}}\n"                   // 17
    "    forces: {s: {stiffness: 30}}\n";                               // 18

double SwingAt(const Model& m, double t) {
  return dynamic_cast<const MotionDriver&>(*m.joints.at(m.FindJoint("swing"))).function().Value(t);
}

TEST(Manoeuvre, ReplacesSolverDriverAndForceValues) {
  auto plain = LoadModelString(kManoeuvreModel, "m.yaml");
  EXPECT_EQ(plain->manoeuvre, "");
  EXPECT_EQ(plain->solver.t_end, 2.0);
  EXPECT_EQ(SwingAt(*plain, 3.0), 0.5);

  SolverOverrides o;
  o.manoeuvre = "fast";
  auto fast = LoadModelString(kManoeuvreModel, "m.yaml", o);
  EXPECT_EQ(fast->manoeuvre, "fast");
  EXPECT_EQ(fast->solver.t_end, 5.0);
  EXPECT_EQ(fast->solver.dt, 0.01);  // the file's other solver keys stay
  EXPECT_NEAR(SwingAt(*fast, 3.0), 0.3, 1e-12);
  EXPECT_EQ(dynamic_cast<const SpringDamper&>(*fast->forces[0]).law().stiffness, 30.0);

  // chosen in the file; the command line's --t-end still wins
  o.manoeuvre = "";
  o.t_end = 7.0;
  auto chosen = LoadModelString(std::string(kManoeuvreModel) + "manoeuvre: fast\n", "m.yaml", o);
  EXPECT_EQ(chosen->manoeuvre, "fast");
  EXPECT_EQ(chosen->solver.t_end, 7.0);
  o.t_end.reset();
  o.manoeuvre = "as_written";
  EXPECT_EQ(SwingAt(*LoadModelString(kManoeuvreModel, "m.yaml", o), 3.0), 0.5);
}

std::string ManoeuvreError(const std::string& yaml, const std::string& manoeuvre = "") {
  SolverOverrides o;
  o.manoeuvre = manoeuvre;
  try {
    LoadModelString(yaml, "m.yaml", o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Manoeuvre, ErrorsNameTheManoeuvreAndLine) {
  const std::string base = kManoeuvreModel;
  EXPECT_EQ(ManoeuvreError(base, "slow"),
            "m.yaml: --manoeuvre slow: no manoeuvre named 'slow' in the file (defined: as_written, fast)");
  EXPECT_NE(ManoeuvreError(base + "manoeuvre: slow\n").find("m.yaml:19: "), std::string::npos);
  EXPECT_NE(ManoeuvreError(base + "  bad: {drivers: {nothing: 1}}\n", "bad")
                .find("m.yaml:19: manoeuvre 'bad': the file has no driver named 'nothing'"),
            std::string::npos);
  EXPECT_NE(ManoeuvreError(base + "  bad: {forces: {nothing: {stiffness: 1}}}\n", "bad")
                .find("no force element named 'nothing'"),
            std::string::npos);
  EXPECT_NE(ManoeuvreError(base + "  bad: {forces: {s: {type: bushing}}}\n", "bad").find("not its 'type'"),
            std::string::npos);
  EXPECT_NE(ManoeuvreError(base + "  bad: {parts: {}}\n", "bad").find("parts"), std::string::npos);
  // every manoeuvre's names are checked, whichever runs
  EXPECT_NE(ManoeuvreError(base + "  bad: {drivers: {nothing: 1}}\n", "fast").find("no driver named 'nothing'"),
            std::string::npos);
  EXPECT_NE(ManoeuvreError(base + "  bad: {drivers: {nothing: 1}}\n").find("no driver named 'nothing'"),
            std::string::npos);
  // a replaced value is checked like the file's own, at the manoeuvre's
  // line, with the manoeuvre named
  const std::string value_error = ManoeuvreError(base + "  bad: {forces: {s: {stiffness: stiff}}}\n", "bad");
  EXPECT_NE(value_error.find("m.yaml:19: "), std::string::npos) << value_error;
  EXPECT_NE(value_error.find("(manoeuvre 'bad')"), std::string::npos) << value_error;
}

}  // namespace
}  // namespace flexmb
