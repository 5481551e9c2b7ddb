// cambrian: a clean stop asked for by a signal (SIGTERM or SIGUSR1). The handler only sets a
// volatile sig_atomic_t flag (async-signal-safe); rank 0 reads it at generation boundaries,
// finishes the generation, checkpoints and exits 0. Workers install the same handler, so the
// signal does not end them: they leave when rank 0 sends stop.
#pragma once

namespace cambrian {

/// Installs the handler for SIGTERM and SIGUSR1 (SA_RESTART). Safe to call more than once.
void installStopSignals();

/// True once SIGTERM or SIGUSR1 arrived after installStopSignals().
bool stopRequested();

/// The signal that asked for the stop ("SIGTERM", "SIGUSR1"), or "" when none did.
const char* stopSignalName();

/// Forgets an earlier request (tests).
void clearStopRequest();

}  // namespace cambrian
