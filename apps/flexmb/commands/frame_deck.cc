#include "apps/flexmb/commands/frame_deck.h"

#include <filesystem>
#include <iterator>

#include "apps/flexmb/commands/lane_change.h"
#include "flexmb/common/error.h"
#include "flexmb/fe_io/nastran/nastran_writer.h"
#include "flexmb/vehicle/truck_frame.h"

namespace flexmb::cli {

int WriteTruckFrameDeck(const std::string& truck_file, const std::string& deck, std::FILE* out) {
  const vehicle::TruckData d = vehicle::LoadLaneChangeTruck(truck_file);
  if (d.frame_body)
    throw InputError("the truck's frame is already a body file (" + d.frame_body_file + "); nothing is generated",
                     {truck_file, 0, "truck frame"});
  const vehicle::FrameReductionData r = vehicle::LaneChangeFrameReduction(truck_file);
  const vehicle::GeneratedFrameModel frame = vehicle::BuildGeneratedFrameModel(d, 9.81);
  io::NastranDeckExtras extras;
  extras.comments = {"ladder frame generated from " + truck_file + " (flexmb truck frame-deck)",
                     "basic frame = vehicle frame: x forward from the front-axle centre, y left, z up from the road",
                     "RBE2: the arm pivots' brackets and the spiders at the interface nodes; ASET1: the interface"};
  // which PSHELL is which part (the section ids are the LadderSection indices + 1)
  const char* parts[] = {"rails", "cross members", "platform sills", "platform cross bearers", "platform side rails",
                         "platform brackets"};
  std::string pshells = "PSHELL";
  for (size_t k = 0; k < frame.mesh.shell_sections.size() && k < std::size(parts); ++k)
    pshells += (k ? ", " : " ") + std::to_string(frame.mesh.shell_sections[k].id) + ": " + parts[k];
  extras.comments.push_back(pshells);
  const vehicle::PlatformData& pl = d.ladder.platform;
  char platform[128] = "";
  if (pl.present) {
    std::snprintf(platform, sizeof platform, "platform: spacer %.17g sill_height %.17g", pl.spacer, pl.sill_height);
    extras.comments.push_back(std::string(platform) + " (they place the cargo mounts on its top)");
  }
  for (const auto& [name, node] : frame.mounts)
    extras.comments.push_back("mount " + name + ": node " + std::to_string(frame.mesh.nodes[static_cast<size_t>(node)].id));
  extras.interface_nodes = frame.interface_nodes;
  io::WriteNastranBulk(frame.mesh, deck, extras);

  const std::string body = std::filesystem::path(deck).replace_extension(".h5").string();
  std::fprintf(out, "wrote %s: %zu nodes, %zu shells, %zu rigid elements, %zu interface nodes (ASET1)\n", deck.c_str(),
               frame.mesh.nodes.size(), frame.mesh.elements.size(), frame.mesh.rigid_links.size(),
               frame.interface_nodes.size());
  std::fprintf(out, "reduce it as the lane-change file does:\n  flexmb reduce %s --interface ASET --modes %d", deck.c_str(),
               r.normal_modes);
  if (r.keep >= 0) std::fprintf(out, " --keep %d", r.keep);
  if (r.acceleration_modes) std::fprintf(out, " --acceleration-modes");
  std::fprintf(out, " --damping-ratio %g --units SI -o %s\n", r.damping_ratio, body.c_str());
  std::fprintf(out, "and give it to the truck (truck: frame:), with the rail geometry keys kept:\n");
  std::fprintf(out, "  frame:\n    body: %s\n    mount_tolerance: 0.35   # m: the arm pivots hang about 0.3 m below the rails\n",
               std::filesystem::path(body).filename().c_str());
  if (pl.present)
    std::fprintf(out, "    platform: {spacer: %g, sill_height: %g}   # the cargo mounts on its top\n", pl.spacer,
                 pl.sill_height);
  std::fprintf(out, "    mounts:\n");
  for (const auto& [name, node] : frame.mounts)
    std::fprintf(out, "      %s: %d\n", name.c_str(), frame.mesh.nodes[static_cast<size_t>(node)].id);
  return 0;
}

}  // namespace flexmb::cli
