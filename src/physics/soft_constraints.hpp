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

/// Gives each joint and friction row of `rows` a constraint force mixing of `mixing` (velocity
/// per impulse) as ODE does; rows of Bullet's solver after its setup.
void mixSoftRows(btConstraintArray& rows, double mixing);

/// A Bullet solver (`Solver`) whose joint and friction rows get a constraint force mixing of
/// `cfm`, as ODE's do (Bullet mixes a joint row's impulse in without the step and the row's
/// effective mass, so the same number means something else there). Contacts' normal rows take
/// the world's m_globalCfm, which Bullet already treats as ODE does.
template <class Solver>
class SoftRowsSolver : public Solver {
 public:
  using Solver::Solver;
  /// Rows of `cfm` at a Bullet step of `substep` s from now on (0: Bullet's own).
  void soften(double cfm, double substep) { mixing_ = cfm > 0 ? cfm / substep : 0; }

 protected:
  btScalar solveGroupCacheFriendlySetup(btCollisionObject** bodies, int body_count,
                                        btPersistentManifold** manifolds, int manifold_count,
                                        btTypedConstraint** constraints, int constraint_count,
                                        const btContactSolverInfo& info,
                                        btIDebugDraw* draw) override {
    const btScalar residual = Solver::solveGroupCacheFriendlySetup(
        bodies, body_count, manifolds, manifold_count, constraints, constraint_count, info, draw);
    if (mixing_ > 0) {
      mixSoftRows(this->m_tmpSolverNonContactConstraintPool, mixing_);
      mixSoftRows(this->m_tmpSolverContactFrictionConstraintPool, mixing_);
    }
    return residual;
  }

 private:
  double mixing_ = 0;  // velocity per impulse, cfm / substep
};

/// Bullet's sequential-impulse solver with ODE's soft rows.
using SoftConstraintSolver = SoftRowsSolver<btSequentialImpulseConstraintSolver>;

/// Bullet's MLCP solver with its Dantzig pivoting: all rows of a step solved together and
/// exactly, as ODE's dWorldStep does, each row mixed by the world's m_globalCfm (the same
/// springs and dampers as SoftConstraintSolver's: the mixing leaves a row's velocity error, which
/// the matrix takes, as it is). A step the pivoting cannot solve (Bullet gives up on a degenerate
/// pivot, or an impulse past 1,000 N s) is solved by sequential impulses over the mixed rows;
/// fallbacks() counts those steps.
class SoftDirectSolver : public SoftRowsSolver<btMLCPSolver> {
 public:
  SoftDirectSolver() : SoftRowsSolver<btMLCPSolver>(&dantzig_) {}
  /// Steps solved by sequential impulses since the world was made.
  int fallbacks() const { return getNumFallbacks(); }

 private:
  btDantzigSolver dantzig_;
};

}  // namespace cambrian
