#include <references/exact/recognise_scene.hpp>

#include <cmath>

#include <fmt/format.h>

#include <solver/scene/support_axes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::exact {
namespace {

// Geometry is given with ~15 significant digits (e.g. 60-degree coordinates); 1e-9 relative
// accepts roundoff in the file and rejects any real misalignment.
constexpr double kTol = 1e-9;

double dot(Vec2 a, Vec2 b) { return a[0] * b[0] + a[1] * b[1]; }
double cross(Vec2 a, Vec2 b) { return a[0] * b[1] - a[1] * b[0]; }
Vec2 sub(Vec2 a, Vec2 b) { return {a[0] - b[0], a[1] - b[1]}; }
double norm(Vec2 a) { return std::hypot(a[0], a[1]); }
Vec2 unit(Vec2 a) {
  const double n = norm(a);
  return {a[0] / n, a[1] / n};
}

Rod as_rod(const Body& b) { return Rod{b.length(), b.E, b.rho, b.area}; }

// True when the supports of body b at `node` hold the displacement along the unit normal n (and
// nothing else than translations): a pin, or a roller across the body (fix = ["normal"], or a
// global one when the body lies along x or y). A global roller on an inclined body holds another
// direction: not a simple support.
bool holds_normal(const Body& b, int node, Vec2 n) {
  const NodeHold h = node_hold(b, node);
  if (h.theta) return false;
  return h.held == 2 || (h.held == 1 && std::abs(cross(h.direction, n)) < kTol);
}

// True when the supports of body b at `node` hold the displacement along the unit axis d, in
// global or body axes (the rotation may be held too: it does not enter the axial problem).
bool holds_along(const Body& b, int node, Vec2 d) {
  const NodeHold h = node_hold(b, node);
  return h.held == 2 || (h.held == 1 && std::abs(cross(h.direction, d)) < kTol);
}

/// @brief Throws InputError(scene.file, key, "the exact method cannot solve this scene: " + msg).
[[noreturn]] void refuse(const Scene& scene, const std::string& key, const std::string& msg) {
  throw InputError(scene.file, key, "the exact method cannot solve this scene: " + msg);
}

/// @brief Refuses a scene that is not two bodies with one frictionless contact and no damping.
void check_one_frictionless_undamped_contact(const Scene& scene) {
  if (scene.bodies.size() != 2)
    refuse(scene, "bodies", fmt::format("it needs exactly two bodies, found {}", scene.bodies.size()));
  if (scene.contacts.size() != 1)
    refuse(scene, "contacts", fmt::format("it needs exactly one contact, found {}", scene.contacts.size()));
  const Contact& c = scene.contacts[0];
  if (c.friction != 0.0)
    refuse(scene, "contacts[0].friction",
           fmt::format("friction is not zero (mu = {}); the exact solutions are frictionless "
                       "(compare with --set contacts[0].friction=0)",
                       c.friction));
  if (scene.model.rayleigh_mass != 0.0 || scene.model.rayleigh_stiffness != 0.0)
    refuse(scene, "model.rayleigh_mass", "damping is not zero; the exact solutions are undamped");
}

/// @brief Refuses the Hertz law in a scene that is not a rigid striker on a flexible target.
void refuse_hertz_unless_ball_on_beam(const Scene& scene) {
  for (std::size_t i = 0; i < scene.contacts.size(); ++i) {
    const Contact& c = scene.contacts[i];
    if (c.law != ContactLaw::kHertz) continue;
    if (!scene.bodies[c.striker].rigid || scene.bodies[c.target].rigid)
      refuse(scene, fmt::format("contacts[{}].law", i),
             "its Hertz-law solution is of a rigid striker on a simply supported flexible beam (ball on "
             "beam); expected law = \"hard\", or a rigid striker (rigid = true) on a flexible target");
  }
}

/// @brief Refuses a Timoshenko body unless the scene is a rod striking a beam end-on (the only
/// problem solved with Timoshenko modes: the target's; the striker, struck end-on, carries axial
/// waves only, the same in either theory); the other problems learn of it here.
/// @param rod_on_beam the scene was recognised as a rod on a simply supported beam
void refuse_timoshenko_unless_rod_on_beam(const Scene& scene, bool rod_on_beam) {
  for (std::size_t i = 0; i < scene.bodies.size() && !rod_on_beam; ++i)
    if (scene.bodies[i].theory == BeamTheory::kTimoshenko)
      refuse(scene, fmt::format("bodies[{}].theory", i),
             "its Timoshenko-beam solution is of an elastic rod striking a simply supported beam end-on "
             "(rod on beam); the coaxial-rod, rigid-rod, rod-on-wall and ball-on-beam solutions are of "
             "Euler-Bernoulli bodies: expected theory = \"euler-bernoulli\" (or no theory)");
}

/// @brief The striker's frame, common to both problems, and what the recognisers check against.
struct Frame {
  const Body& A;            ///< striker
  const Body& B;            ///< target
  std::string ka, kb;       ///< their scene keys, "bodies[i]"
  Vec2 pc;                  ///< m, striker's contact end
  Vec2 eb;                  ///< target axis, unit, start to end
  double scale;             ///< m, La + Lb
  double va_norm, vb_norm;  ///< m/s, speeds of striker and target
};

/// @brief A target with supports is a rod clamped at its far end when its only support is at the
/// node away from the striker, holding the displacement along the axis (other components do not
/// enter the axial problem), and it starts at rest.
void recognise_fixed_far_end(const Scene& scene, const Frame& f, ExactProblem& p, double s_start,
                             double s_end) {
  const Body& B = f.B;
  const int far = s_end > s_start ? B.elements : 0;
  if (B.supports.size() != 1 || B.supports[0].node != far || !holds_along(B, far, p.dir))
    refuse(scene, f.kb + ".supports",
           "the coaxial target's supports are not one support at its far end holding the axial "
           "displacement (the coaxial rod solution has a free or a clamped far end only)");
  if (f.vb_norm != 0.0)
    refuse(scene, f.kb + ".velocity", "the target is fixed at its far end but not at rest");
  p.target_far_end = FarEnd::kFixed;
}

/// @brief Two coaxial rods, end to end, both moving along the common axis; the target's far end
/// free, or fixed (recognise_fixed_far_end).
void recognise_coaxial_rods(const Scene& scene, const Frame& f, ExactProblem& p) {
  const Body& B = f.B;
  if (std::abs(cross(f.eb, p.dir)) > kTol || std::abs(cross(sub(B.start, f.pc), p.dir)) > kTol * f.scale)
    refuse(scene, f.kb + ".start",
           "the target is not coaxial with the striker (free target: the coaxial "
           "rod solution needs both bodies on one line)");
  const double s1 = dot(sub(B.start, f.pc), p.dir), s2 = dot(sub(B.end, f.pc), p.dir);
  if (std::min(s1, s2) < -kTol * f.scale)
    refuse(scene, f.kb + ".start", "the target is not ahead of the striker's contact end");
  if (std::abs(cross(B.velocity, p.dir)) > kTol * (f.va_norm + f.vb_norm + 1e-300))
    refuse(scene, f.kb + ".velocity", "the target's velocity is not along the common axis");
  if (!B.supports.empty()) recognise_fixed_far_end(scene, f, p, s1, s2);
  p.kind = ExactKind::kCoaxialRods;
  p.gap = std::max(0.0, std::min(s1, s2));
  p.target_speed = dot(B.velocity, p.dir);
  p.v0 = dot(f.A.velocity, p.dir) - p.target_speed;
  p.target_rod = as_rod(B);
  p.contact_kind = ContactKind::kEndToEnd;
}

/// @brief A rod end-on onto a simply supported beam, struck strictly between its supports.
void recognise_rod_on_beam(const Scene& scene, const Frame& f, ExactProblem& p) {
  const Body& B = f.B;
  if (std::abs(dot(f.eb, p.dir)) > kTol)
    refuse(scene, f.ka + ".end",
           "the striker is not perpendicular to the target (supported target: the "
           "rod-on-beam solution needs a normal, end-on impact)");
  const Vec2 n = {-f.eb[1], f.eb[0]};
  bool simple = B.supports.size() == 2;
  bool start_held = false, end_held = false;
  for (const Support& s : B.supports) {
    if (s.node == 0)
      start_held = holds_normal(B, s.node, n);
    else if (s.node == B.elements)
      end_held = holds_normal(B, s.node, n);
    else
      simple = false;
  }
  if (!(simple && start_held && end_held))
    refuse(scene, f.kb + ".supports",
           "the target is not simply supported (it needs one support at each "
           "end holding the transverse displacement, rotation free, no other supports)");
  if (f.vb_norm != 0.0) refuse(scene, f.kb + ".velocity", "the supported target is not at rest");
  if (!(B.inertia > 0.0))
    refuse(scene, f.kb + ".inertia", "the target has no bending stiffness (inertia = 0)");
  if (scene.effects.bending && !*scene.effects.bending)
    refuse(scene, "effects.bending", "bending is forced off, but the rod-on-beam solution is all bending");
  const double Lb = B.length();
  const Vec2 rel = sub(f.pc, B.start);
  const double x_c = dot(rel, f.eb), h = dot(rel, n);
  if (x_c <= kTol * Lb || x_c >= Lb * (1.0 - kTol))
    refuse(scene, f.kb + ".start", "the struck point is not strictly between the target's supports");
  // The contact end must face the beam: moving along dir brings it towards the axis.
  if (h * dot(p.dir, n) > 0.0)
    refuse(scene, f.ka + ".end", "the striker's contact end does not face the target");
  p.kind = ExactKind::kRodOnBeam;
  p.gap = std::abs(h);
  p.v0 = dot(f.A.velocity, p.dir);
  p.beam = SimpleBeam{Lb, B.E, B.rho, B.area, B.inertia};
  if (B.theory == BeamTheory::kTimoshenko)
    p.shear = BeamShear{B.shear_coefficient, B.E / (2.0 * (1.0 + B.poisson))};
  p.x_c = x_c;
  const double le = Lb / B.elements, k = x_c / le;
  p.contact_kind =
      std::abs(k - std::round(k)) < 1e-9 ? ContactKind::kNodeToNode : ContactKind::kNodeToSurface;
}

}  // namespace

/// @brief A free rigid rod falling without spin along the normal of an immovable rigid surface,
/// striking it with one end (references.md section 3).
ExactProblem recognise_rigid_rod(const Scene& scene) {
  if (scene.bodies.size() != 2 || scene.contacts.size() != 1)
    refuse(scene, "bodies", "a rigid rod onto a rigid surface needs exactly two bodies and one contact");
  if (scene.model.rayleigh_mass != 0.0 || scene.model.rayleigh_stiffness != 0.0)
    refuse(scene, "model.rayleigh_mass", "damping is not zero; the closed form is undamped");
  const Contact& c = scene.contacts[0];
  const Body& A = scene.bodies[c.striker];
  const Body& B = scene.bodies[c.target];
  const std::string ka = fmt::format("bodies[{}]", c.striker), kb = fmt::format("bodies[{}]", c.target);
  if (!A.rigid || !B.rigid)
    refuse(scene, (A.rigid ? kb : ka) + ".rigid", "the closed form needs both bodies rigid (rigid = true)");
  if (!A.supports.empty()) refuse(scene, ka + ".supports", "the rod must be free");
  if (B.supports.empty()) refuse(scene, kb + ".supports", "the surface must be immovable");
  if (c.node != 0 && c.node != A.elements)
    refuse(scene, "contacts[0].node", "the rod's contact node is not an end of the rod");
  ExactProblem p;
  p.kind = ExactKind::kRigidRod;
  p.striker = c.striker;
  p.target = c.target;
  p.mu = c.friction;
  p.striker_rod = as_rod(A);
  const Vec2 t = unit(sub(B.end, B.start));
  const Vec2 pc = A.node_position(c.node);
  const Vec2 centre{0.5 * (A.start[0] + A.end[0]), 0.5 * (A.start[1] + A.end[1])};
  const double side = cross(t, sub(centre, B.start)) >= 0.0 ? 1.0 : -1.0;
  p.normal = {-side * t[1], side * t[0]};
  p.gap = dot(sub(pc, B.start), p.normal);
  const double along = dot(sub(pc, B.start), t);
  if (!(p.gap > 0.0) || along < 0.0 || along > B.length())
    refuse(scene, "contacts[0].node", "the rod's contact end is not above the surface's span");
  const Vec2 r = sub(pc, centre);  // centre to contact end
  const double half = 0.5 * A.length();
  const double sin_t = -dot(r, p.normal) / half;
  if (!(sin_t > kTol))
    refuse(scene, ka + ".start", "the rod's contact end is not its lower end (or the rod lies flat)");
  p.theta = std::asin(std::min(1.0, sin_t));
  p.v0 = -dot(A.velocity, p.normal);
  if (!(p.v0 > 0.0) || std::abs(cross(A.velocity, p.normal)) > kTol * norm(A.velocity))
    refuse(scene, ka + ".velocity",
           "the rod must fall along the surface normal (the closed form has no "
           "tangential approach speed)");
  p.contact_kind = ContactKind::kNodeToSurface;
  return p;
}

/// @brief A free elastic rod moving along its axis towards an immovable rigid body (a wall or the
/// ground) that lies on its axis ahead of it (end to end) or across it; gravity, if any, along
/// the axis (RodOnWall.hpp).
ExactProblem recognise_rod_on_wall(const Scene& scene) {
  check_one_frictionless_undamped_contact(scene);
  const Contact& c = scene.contacts[0];
  const Body& A = scene.bodies[c.striker];
  const Body& B = scene.bodies[c.target];
  const std::string ka = fmt::format("bodies[{}]", c.striker), kb = fmt::format("bodies[{}]", c.target);
  if (B.supports.empty()) refuse(scene, kb + ".supports", "the rigid target must be immovable (a wall)");
  if (!A.supports.empty()) refuse(scene, ka + ".supports", "the striker has supports; it must be free");
  if (c.node != 0 && c.node != A.elements)
    refuse(scene, "contacts[0].node", "the striker's contact node is not an end of the striker");
  for (std::size_t i = 0; i < scene.loads.point.size(); ++i)
    refuse(scene, fmt::format("loads.point[{}]", i), "point forces are not part of the rod-on-wall solution");
  ExactProblem p;
  p.kind = ExactKind::kRodOnWall;
  p.striker = c.striker;
  p.target = c.target;
  p.striker_rod = as_rod(A);
  const Vec2 pc = A.node_position(c.node), po = A.node_position(c.node == 0 ? A.elements : 0);
  p.dir = unit(sub(pc, po));
  const Vec2 eb = unit(sub(B.end, B.start));
  const double scale = A.length() + B.length();
  const double va = norm(A.velocity), g = norm(scene.loads.gravity);
  if (std::abs(cross(A.velocity, p.dir)) > kTol * (va + 1e-300))
    refuse(scene, ka + ".velocity", "the striker's velocity is not along its own axis");
  if (std::abs(cross(scene.loads.gravity, p.dir)) > kTol * (g + 1e-300))
    refuse(scene, "loads.gravity", "gravity is not along the striker's axis");
  if (std::abs(cross(eb, p.dir)) <= kTol) {  // the wall on the axis, end to end
    if (std::abs(cross(sub(B.start, pc), p.dir)) > kTol * scale)
      refuse(scene, kb + ".start", "the rigid target is parallel to the striker but not on its axis");
    p.gap = std::min(dot(sub(B.start, pc), p.dir), dot(sub(B.end, pc), p.dir));
    p.contact_kind = ContactKind::kEndToEnd;
  } else {  // across the axis: it must be perpendicular, the axis crossing its span strictly inside
    if (std::abs(dot(eb, p.dir)) > kTol)
      refuse(scene, kb + ".end", "the rigid target is neither on the striker's axis nor across it (oblique)");
    const double u = dot(sub(pc, B.start), eb);  // the axis's crossing, from the target's start
    if (u <= kTol * B.length() || u >= B.length() * (1.0 - kTol))
      refuse(scene, kb + ".start", "the striker's axis does not cross the rigid target's span");
    p.gap = dot(sub(B.start, pc), p.dir);
    p.contact_kind = ContactKind::kNodeToSurface;
  }
  if (!(p.gap > 0.0))
    refuse(scene, kb + ".start", "the rigid target is not ahead of the striker's contact end");
  p.v0 = dot(A.velocity, p.dir);
  p.g = dot(scene.loads.gravity, p.dir);
  return p;
}

namespace {

/// @brief The problem the scene describes, whatever its bodies' beam theory.
ExactProblem recognise_problem(const Scene& scene) {
  refuse_hertz_unless_ball_on_beam(scene);
  const bool hertz = !scene.contacts.empty() && scene.contacts[0].law == ContactLaw::kHertz;
  if (scene.bodies.size() == 2 && scene.contacts.size() == 1 &&
      !scene.bodies[scene.contacts[0].striker].rigid && scene.bodies[scene.contacts[0].target].rigid)
    return recognise_rod_on_wall(scene);
  if (scene.loads.any())
    refuse(scene, "loads",
           "external loads (gravity, point forces) enter its rod-on-a-rigid-wall solution only; expected no "
           "[loads] table, or a method that applies them (paper, ida)");
  if (!hertz)  // a rigid striker with the Hertz law is a ball on a beam (below)
    for (const Body& b : scene.bodies)
      if (b.rigid) return recognise_rigid_rod(scene);
  check_one_frictionless_undamped_contact(scene);
  const Contact& c = scene.contacts[0];
  ExactProblem p;
  p.striker = c.striker;
  p.target = c.target;
  const Body& A = scene.bodies[c.striker];
  const Body& B = scene.bodies[c.target];
  const std::string ka = fmt::format("bodies[{}]", c.striker), kb = fmt::format("bodies[{}]", c.target);
  if (c.node != 0 && c.node != A.elements)
    refuse(scene, "contacts[0].node", "the striker's contact node is not an end of the striker");
  if (!A.supports.empty()) refuse(scene, ka + ".supports", "the striker has supports; it must be free");
  const Vec2 pc = A.node_position(c.node);
  const Vec2 po = A.node_position(c.node == 0 ? A.elements : 0);
  p.dir = unit(sub(pc, po));
  const double scale = A.length() + B.length();
  const double va_norm = norm(A.velocity), vb_norm = norm(B.velocity);
  if (std::abs(cross(A.velocity, p.dir)) > kTol * (va_norm + vb_norm + 1e-300))
    refuse(scene, ka + ".velocity", "the striker's velocity is not along its own axis");
  p.striker_rod = as_rod(A);
  const Frame f{A, B, ka, kb, pc, unit(sub(B.end, B.start)), scale, va_norm, vb_norm};
  const bool coaxial = B.supports.empty() || std::abs(cross(f.eb, p.dir)) <= kTol;  // free, or on the axis
  if (hertz && coaxial)
    refuse(scene, kb + ".supports",
           "its Hertz-law solution is of a striker across a simply supported beam (ball on beam)");
  if (coaxial)
    recognise_coaxial_rods(scene, f, p);
  else
    recognise_rod_on_beam(scene, f, p);
  if (hertz) {
    p.kind = ExactKind::kBallOnBeam;
    p.mass = A.rho * A.area * A.length();
    p.hertz_stiffness = c.hertz_stiffness;
  }
  return p;
}

}  // namespace

ExactProblem recognise_scene(const Scene& scene) {
  const ExactProblem p = recognise_problem(scene);
  refuse_timoshenko_unless_rod_on_beam(scene, p.kind == ExactKind::kRodOnBeam);
  return p;
}

}  // namespace beamimpact::exact
