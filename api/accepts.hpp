#pragma once
/// @file accepts.hpp
/// @brief The one check of a run against what its method accepts (Method::Accepts) and of the
/// scene's method option tables against the registry; api::run calls it before every run.

#include <string>

#include <api/registry.hpp>

namespace beamimpact {

/// @brief Throws InputError(scene file, key, why) when the method does not take this run: a
/// step asked for (time.dt / time.fraction override) from a method that picks its own, a mesh it
/// cannot take, friction, large rotation, rigid bodies, contact search, several contacts,
/// Timoshenko beams, the Hertz law, bending, a node-to-surface contact or loads it does not model, or an
/// option table ([name]) that is no method's. The CLI exits 2 and the suite reports the run as not
/// applicable.
/// @param m the method; @param scene the scene with its overrides applied
/// @param mesh the mesh asked for ("" none; an element multiplier or the method's preset)
void check_accepts(const Method& m, const Scene& scene, const std::string& mesh);

/// @brief The element multiplier `mesh` (1..64); throws InputError naming `file` and "mesh".
int mesh_factor(const std::string& mesh, const std::string& file, const std::string& method);

}  // namespace beamimpact
