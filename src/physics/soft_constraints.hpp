// cambrian: ODE's soft constraints in Bullet's rigid-body solver — every joint, contact and
// friction row a spring and damper, of the stiffness and damping ODE's global CFM and ERP give.
#pragma once

#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletDynamics/MLCPSolvers/btDantzigSolver.h>
#include <BulletDynamics/MLCPSolvers/btMLCPSolver.h>

namespace cambrian {

/// ODE's constraint force mixing and error reduction of one step: a row's impulse P and its
/// velocity error obey J v + (cfm / step) P = erp x error / step.
struct SoftRows {
  double cfm = 0;  ///< m/(N s) on a linear row (rad/(N m s) on a turning one); 0: rigid
  double erp = 0;  ///< share of a row's position error removed per step
};

/// The rows of a substep of `substep` s that are the same spring and damper as ODE's `cfm` and
/// `erp` at a step of `time_step` s (ODE: stiffness erp / (time_step cfm), damping
/// (1 - erp) / cfm; at substep = time_step the same two numbers). cfm 0: rigid rows.
SoftRows softRowsAt(double cfm, double erp, double time_step, double substep);

/// Bullet's sequential-impulse solver whose joint and friction rows get a constraint force
/// mixing of `cfm`, as ODE's do (Bullet mixes a joint row's impulse in without the step and the
/// row's effective mass, so the same number means something else there). Contacts' normal rows
/// take the world's m_globalCfm, which Bullet already treats as ODE does.
class SoftConstraintSolver : public btSequentialImpulseConstraintSolver {
 public:
  /// Rows of `cfm` at a Bullet step of `substep` s from now on (0: Bullet's own).
  void soften(double cfm, double substep);

 protected:
  btScalar solveGroupCacheFriendlySetup(btCollisionObject** bodies, int body_count,
                                        btPersistentManifold** manifolds, int manifold_count,
                                        btTypedConstraint** constraints, int constraint_count,
                                        const btContactSolverInfo& info,
                                        btIDebugDraw* draw) override;

 private:
  double mixing_ = 0;  // velocity per impulse, cfm / substep
};

/// Bullet's MLCP solver with its Dantzig pivoting: all rows of a step solved together and
/// exactly, as ODE's dWorldStep does, each row mixed by the world's m_globalCfm (the same
/// springs and dampers as SoftConstraintSolver's). A step the pivoting cannot solve (Bullet
/// gives up on a degenerate pivot, or an impulse past 1,000 N s) is solved by sequential
/// impulses over rows mixed as SoftConstraintSolver mixes them; fallbacks() counts those steps.
class SoftDirectSolver : public btMLCPSolver {
 public:
  SoftDirectSolver() : btMLCPSolver(&dantzig_) {}
  /// Rows of `cfm` at a Bullet step of `substep` s from now on (0: Bullet's own).
  void soften(double cfm, double substep);
  /// Steps solved by sequential impulses since the world was made.
  int fallbacks() const { return getNumFallbacks(); }

 protected:
  btScalar solveGroupCacheFriendlySetup(btCollisionObject** bodies, int body_count,
                                        btPersistentManifold** manifolds, int manifold_count,
                                        btTypedConstraint** constraints, int constraint_count,
                                        const btContactSolverInfo& info,
                                        btIDebugDraw* draw) override;

 private:
  btDantzigSolver dantzig_;
  double mixing_ = 0;  // velocity per impulse, cfm / substep
};

}  // namespace cambrian
