#pragma once
/// \file frame_deck.h
/// `flexmb truck frame-deck`: the generated ladder frame of a lane-change
/// file written as Nastran bulk data, with its brackets, spiders and
/// interface nodes, so that it takes the user's path: an FE deck reduced by
/// `flexmb reduce` and named in the truck file (`frame: {body, mounts}`).

#include <cstdio>
#include <string>

namespace flexmb::cli {

/// Writes the generated frame of the lane-change file `truck_file` to
/// `deck` (WriteNastranBulk; the interface as ASET1, each mount named in a
/// comment) and prints to `out` the reduce command with the file's frame
/// settings and the truck file's `frame` block (body and mounts). Throws
/// InputError for a bad file or a truck whose frame is already a body file.
int WriteTruckFrameDeck(const std::string& truck_file, const std::string& deck, std::FILE* out);

}  // namespace flexmb::cli
