#pragma once
/// \file truck_frame.h
/// The truck's chassis frame as an FE part: the generated ladder frame
/// (ladder_frame.h), or the user's own FE frame as a body file made by
/// `flexmb reduce`, with every attachment of FrameAttachments carried by a
/// named interface node (the seed's workflow: the frame's FE model, with its
/// interface nodes, comes from an FE package and is pulled into the
/// multibody model).

#include <memory>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "flexmb/fe/mesh.h"
#include "flexmb/reduction/reduced_body.h"
#include "flexmb/vehicle/truck.h"

namespace flexmb {
class YamlContext;
}

namespace flexmb::vehicle {

/// Reads the truck's `frame` map into `d`: the ladder frame's geometry and
/// material (the frame is generated, SetFrameMesh), or with `body` the body
/// file (relative to `dir`), its `mounts` {attachment name: node id} and
/// `mount_tolerance`; the rail geometry keys then only place the mounts
/// (examples/truck_lane_change/README.md, "Your own FE frame"). Call after the rest of the truck is read: the mounts
/// are checked against FrameAttachments. Errors name the file and line.
void ReadTruckFrame(const YAML::Node& truck, YamlContext& ctx, const std::string& dir, TruckData& d);

/// Mass, centre of mass and inertia about it of a reduced body, from its
/// inertia invariants (mvv, mvo0, moo0) [kg, m, kg m^2].
MassProperties3 BodyMassProperties(const reduction::ReducedBody& body);

/// Makes `body` the truck's frame (d.frame_body): the rigid frame takes its
/// mass properties, the display its mesh. Its basic frame must be the
/// vehicle frame and its units SI.
void SetFrameBody(TruckData& d, std::shared_ptr<const reduction::ReducedBody> body);

/// The generated frame as the FE model that is reduced: the ladder frame's
/// mesh with the arm pivots' brackets and a spider at every interface node,
/// and per attachment its node.
struct GeneratedFrameModel {
  fe::Mesh mesh;
  std::vector<int> interface_nodes;  ///< node indices, one per attachment (repeats removed)
  std::vector<std::pair<std::string, int>> mounts;  ///< attachment name -> node index
};

/// Builds the generated frame's FE model of `d` (d.frame_mesh) at gravity
/// `g` (the attachments' static heights): the interface node of each
/// attachment is the mesh node nearest to it. Throws InputError without a
/// generated mesh.
GeneratedFrameModel BuildGeneratedFrameModel(const TruckData& d, double g);

/// The node (index into frame.mesh) that carries the attachment `name`
/// meant at `point` [m]: with the user's frame (d.frame_body) the node named
/// in d.frame_mounts, else the node nearest to the point. Throws InputError
/// naming the attachment when it has no node, the node is not an interface
/// node of `frame`, or (the user's frame) lies farther than
/// d.mount_tolerance from the point.
int FrameMountNode(const TruckData& d, const reduction::ReducedBody& frame, const std::string& name,
                   const Vec3& point);

}  // namespace flexmb::vehicle
