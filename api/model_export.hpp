#pragma once
/// @file model_export.hpp
/// @brief `beamimpact model`: writes the semi-discrete model of a scene (the one the paper
/// integrator and IDA step) as plain files, so that a solver written anywhere steps the same
/// equations and a comparison isolates its contact algorithm and time stepping:
///
///   M a + C v + K u = F + sum_k (R_k G_k^T + tau_k T_k^T),   u(0) = u0, v(0) = v0,
///   gap_k = g0_k + G_k u >= 0,  R_k >= 0 (compressive),  |tau_k| <= mu_k R_k,
///
/// with G_k, T_k the normal and tangential rows of contact k at t = 0 (linear surface
/// interpolation, the paper's Eq. 14-20). Files: M.mtx, K.mtx, C.mtx (Matrix Market), dofs.csv,
/// initial_state.csv, load.csv, momentum.csv, and model.json (written last: its presence marks a
/// complete export) describing each of them with units.

#include <filesystem>

#include <nlohmann/json.hpp>

#include <solver/model/Model.hpp>
#include <solver/scene/Scene.hpp>

namespace beamimpact {

/// @brief Format version of model.json (raised when a file or key changes meaning).
inline constexpr int kModelFormatVersion = 2;

/// @brief The constant external load vector F (N on translations, N m on rotations) of the
/// scene on the model's equations. Loads of the scene (gravity, point forces) join here; a scene
/// without loads gives zero.
/// @param scene the scene (effective: forced-off effects removed)
/// @param model its assembled model
Eigen::VectorXd external_load(const Scene& scene, const Model& model);

/// @brief Writes the model of `scene` into dir (made if absent), holding dir's OutputLock (a
/// second writer is refused, InputError). A model.json left by an earlier export is removed
/// before anything else (also when this export is refused) and written last,
/// atomically. Throws InputError (exit 2) for a scene
/// the export cannot describe: a contact search (node = "all") or corotational kinematics
/// (the matrices would change every step).
/// @param scene the loaded scene (with its --set overrides applied)
/// @param dir output folder
/// @return the model.json document written
nlohmann::json export_model(const Scene& scene, const std::filesystem::path& dir);

}  // namespace beamimpact
