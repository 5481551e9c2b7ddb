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

btScalar SoftConstraintSolver::solveGroupCacheFriendlySetup(
    btCollisionObject** bodies, int body_count, btPersistentManifold** manifolds,
    int manifold_count, btTypedConstraint** constraints, int constraint_count,
    const btContactSolverInfo& info, btIDebugDraw* draw) {
  const btScalar residual = btSequentialImpulseConstraintSolver::solveGroupCacheFriendlySetup(
      bodies, body_count, manifolds, manifold_count, constraints, constraint_count, info, draw);
  if (mixing_ > 0) {
    // each row's impulse P then settles where its velocity error is mixing_ x P, as Bullet's
    // contact rows do with m_globalCfm: the row's inverse effective mass a gains mixing_, and
    // the row's target impulse and its mixing term are taken over the new sum
    for (btConstraintArray* rows :
         {&m_tmpSolverNonContactConstraintPool, &m_tmpSolverContactFrictionConstraintPool}) {
      for (int i = 0; i < rows->size(); ++i) {
        btSolverConstraint& row = (*rows)[i];
        if (row.m_jacDiagABInv == 0)
          continue;
        const btScalar a = 1 / row.m_jacDiagABInv;
        const btScalar inverse = 1 / (a + mixing_);
        row.m_rhs *= inverse * a;
        row.m_rhsPenetration *= inverse * a;
        row.m_cfm = mixing_ * inverse;
        row.m_jacDiagABInv = inverse;
      }
    }
  }
  return residual;
}

}  // namespace cambrian
