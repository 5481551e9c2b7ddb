// cambrian: the subcommands main() dispatches to. Each returns a process exit code.
#pragma once

namespace cambrian {

/// `cambrian simulate`: evaluates one creature and prints its outcome.
int runSimulate(int argc, char** argv);
/// `cambrian inspect FILE`: prints a genome and its body statistics.
int runInspect(int argc, char** argv);
/// `cambrian evolve`: the MPI evolution (rank 0 breeds, other ranks evaluate).
int runEvolve(int argc, char** argv);
/// `cambrian replay`: re-simulates a creature of a history file; 0 when its outcome is
/// bit-identical to the stored one, ExitCode::replay_mismatch when not. `--export` writes its
/// trajectory.
int runReplay(int argc, char** argv);
/// `cambrian audit`: checks the physics on many bodies; ExitCode::audit_failed when a body
/// creeps at rest or gains unexplained energy.
int runAudit(int argc, char** argv);

}  // namespace cambrian
