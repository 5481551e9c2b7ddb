// cambrian: ODE's soft constraints in Bullet's rigid-body solver.
#include "physics/soft_constraints.hpp"

#include <initializer_list>

namespace cambrian {

SoftRows softRowsAt(double cfm, double erp, double time_step, double substep) {
  if (!(cfm > 0))
    return {0, erp};
  const double stiffness = erp / (time_step * cfm), damping = (1 - erp) / cfm;
  const double both = substep * stiffness + damping;
  return {1 / both, substep * stiffness / both};
}

void SoftConstraintSolver::soften(double cfm, double substep) {
  mixing_ = cfm > 0 ? cfm / substep : 0;
}

namespace {

// each row's impulse P then settles where its velocity error is mixing x P, as Bullet's contact
// rows do with m_globalCfm: the row's inverse effective mass a gains mixing, and the row's
// target impulse and its mixing term are taken over the new sum
void mixRows(btConstraintArray& rows, double mixing) {
  for (int i = 0; i < rows.size(); ++i) {
    btSolverConstraint& row = rows[i];
    if (row.m_jacDiagABInv == 0)
      continue;
    const btScalar a = 1 / row.m_jacDiagABInv;
    const btScalar inverse = 1 / (a + mixing);
    row.m_rhs *= inverse * a;
    row.m_rhsPenetration *= inverse * a;
    row.m_cfm = mixing * inverse;
    row.m_jacDiagABInv = inverse;
  }
}

}  // namespace

btScalar SoftConstraintSolver::solveGroupCacheFriendlySetup(
    btCollisionObject** bodies, int body_count, btPersistentManifold** manifolds,
    int manifold_count, btTypedConstraint** constraints, int constraint_count,
    const btContactSolverInfo& info, btIDebugDraw* draw) {
  const btScalar residual = btSequentialImpulseConstraintSolver::solveGroupCacheFriendlySetup(
      bodies, body_count, manifolds, manifold_count, constraints, constraint_count, info, draw);
  if (mixing_ > 0) {
    mixRows(m_tmpSolverNonContactConstraintPool, mixing_);
    mixRows(m_tmpSolverContactFrictionConstraintPool, mixing_);
  }
  return residual;
}

void SoftDirectSolver::soften(double cfm, double substep) {
  mixing_ = cfm > 0 ? cfm / substep : 0;
}

btScalar SoftDirectSolver::solveGroupCacheFriendlySetup(
    btCollisionObject** bodies, int body_count, btPersistentManifold** manifolds,
    int manifold_count, btTypedConstraint** constraints, int constraint_count,
    const btContactSolverInfo& info, btIDebugDraw* draw) {
  // the matrix takes m_globalCfm on its diagonal and each row's velocity error (its target
  // impulse over its inverse effective mass, which mixing leaves as it is); the mixed rows are
  // what a fallback step iterates over
  const btScalar residual = btMLCPSolver::solveGroupCacheFriendlySetup(
      bodies, body_count, manifolds, manifold_count, constraints, constraint_count, info, draw);
  if (mixing_ > 0) {
    mixRows(m_tmpSolverNonContactConstraintPool, mixing_);
    mixRows(m_tmpSolverContactFrictionConstraintPool, mixing_);
  }
  return residual;
}

}  // namespace cambrian
