#pragma once
/// @file recognise_scene.hpp
/// @brief Decides whether a scene has an exact (or semi-analytic) counterpart and extracts
/// its 1D data; any other scene is refused with the condition that failed ("the exact method
/// cannot solve this scene: ..."). What the method never takes (a contact search, several
/// contacts, large rotation) is the registry's to refuse (Method::Accepts, checked by api::run);
/// what it takes for one problem only (the Hertz law: ball on beam; a Timoshenko beam: rod on
/// beam) the recogniser refuses for the others.

#include <string>

#include <references/exact/Rod.hpp>
#include <references/exact/SimpleBeam.hpp>
#include <references/exact/TimoshenkoBeam.hpp>
#include <solver/scene/Scene.hpp>
#include <solver/schema/output_schema.hpp>

namespace beamimpact::exact {

/// @brief The two problems the exact method solves.
enum class ExactKind {
  kCoaxialRods,  ///< two coaxial rods end to end, the target's far end free or fixed (references.md section
                 ///< 1)
  kRodOnBeam,    ///< a free rod end-on onto a simply supported beam (references.md section 2)
  kRigidRod,     ///< a rigid rod onto an immovable rigid surface, with friction (references.md section 3)
  kRodOnWall,    ///< a free elastic rod end-on onto an immovable rigid body, gravity along it (RodOnWall.hpp)
  kBallOnBeam,  ///< a free rigid striker onto a simply supported beam through a Hertz spring (BallOnBeam.hpp)
};

/// @brief The 1D problem a scene describes, in the frame of its contact.
struct ExactProblem {
  ExactKind kind = ExactKind::kCoaxialRods;
  int striker = 0, target = 0;            ///< body indices in the scene
  Vec2 dir{};                             ///< unit vector: striker contact end towards the target
  double v0 = 0.0;                        ///< m/s, approach speed along dir (relative to the target)
  double target_speed = 0.0;              ///< m/s, target's initial speed along dir (rods only; 0 for beams)
  double gap = 0.0;                       ///< m, initial gap along dir
  Rod striker_rod;                        ///< the striker as a rod
  Rod target_rod;                         ///< the target as a rod (kCoaxialRods)
  FarEnd target_far_end = FarEnd::kFree;  ///< kCoaxialRods: the target's far end free or fixed
  SimpleBeam beam;                        ///< the target as a beam (kRodOnBeam, kBallOnBeam)
  BeamShear shear;                        ///< kRodOnBeam: a Timoshenko target's kappa and G (else zero)
  double x_c = 0.0;              ///< m, struck point from the target's start node (kRodOnBeam, kBallOnBeam)
  double mass = 0.0;             ///< kg, kBallOnBeam: the rigid striker's mass rho A L
  double hertz_stiffness = 0.0;  ///< N/m^1.5, kBallOnBeam: k of the contact's Hertz spring
  ContactKind contact_kind = ContactKind::kEndToEnd;  ///< string forms in schema/output_schema.hpp
  Vec2 normal{};       ///< kRigidRod: unit normal of the surface, toward the rod
  double theta = 0.0;  ///< kRigidRod: rad, angle between the rod and the surface
  double mu = 0.0;     ///< kRigidRod: Coulomb coefficient
  double g = 0.0;      ///< kRodOnWall: m/s^2, gravity along dir (towards the wall)
};

/// @brief Recognises the scene or throws InputError(scene.file, key, condition that failed).
ExactProblem recognise_scene(const Scene& scene);

}  // namespace beamimpact::exact
