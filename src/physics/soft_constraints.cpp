// cambrian: ODE's soft constraints in Bullet's rigid-body solver.
#include "physics/soft_constraints.hpp"

namespace cambrian {

SoftRows softRowsAt(double cfm, double erp, double time_step, double substep) {
  if (!(cfm > 0))
    return {0, erp};
  const double stiffness = erp / (time_step * cfm), damping = (1 - erp) / cfm;
  const double both = substep * stiffness + damping;
  return {1 / both, substep * stiffness / both};
}

// each row's impulse P then settles where its velocity error is mixing x P, as Bullet's contact
// rows do with m_globalCfm: the row's inverse effective mass a gains mixing, and the row's
// target impulse and its mixing term are taken over the new sum
void mixSoftRows(btConstraintArray& rows, double mixing) {
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

}  // namespace cambrian
