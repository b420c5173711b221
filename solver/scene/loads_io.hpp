#pragma once
/// @file loads_io.hpp
/// @brief Reads the optional [loads] table of a scene (after its bodies):
///   [loads]
///   gravity = [gx, gy]            # m/s^2, on every body's mass
///   [[loads.point]]
///   body = "A"                    # a body name
///   node = 3                      # "start", "end" or a node index of that body
///   force = [fx, fy]              # N, global axes, constant

#include <solver/scene/TableReader.hpp>

namespace beamimpact {

/// @brief Fills sc.loads from the top-level table (an absent [loads] table: no loads).
/// @param top the reader of the whole scene file
/// @param sc the scene being read; its bodies must be read already
void read_loads(TableReader& top, Scene& sc);

}  // namespace beamimpact
