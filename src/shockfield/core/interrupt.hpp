#pragma once
// Ctrl-C / SIGTERM handling. A signal only sets a flag; the time loop polls it at the end of a
// step, writes a checkpoint and returns, so nothing is lost. The flag is the one piece of
// process-global state in the library: a signal handler cannot reach a context object.

namespace shockfield {

/// Installs SIGINT and SIGTERM handlers that request a clean stop (idempotent).
void install_stop_handlers();
/// True once a stop was requested by a signal (or request_stop()).
bool stop_requested();
/// Requests a stop as a signal would (used by tests and by --max-steps style limits).
void request_stop();
/// Clears the request (a new run in the same process starts clean).
void clear_stop_request();

}  // namespace shockfield
