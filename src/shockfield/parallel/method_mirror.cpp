#include "shockfield/parallel/method_mirror.hpp"

#include <stdexcept>

#include "shockfield/core/error.hpp"
#include "shockfield/core/interrupt.hpp"

namespace shockfield::parallel {

void MethodMirror::announce(MethodCall call) const {
  if (!comm_.is_root() || quit_sent_) return;
  int code = static_cast<int>(call);
  comm_.broadcast(&code, sizeof code);
  quit_sent_ = call == MethodCall::quit;
}

void MethodMirror::announce_resume(const std::string& checkpoint) const {
  if (!comm_.is_root()) return;
  announce(MethodCall::resume);
  unsigned long long length = checkpoint.size();
  comm_.broadcast(&length, sizeof length);
  std::string text = checkpoint;
  comm_.broadcast(text.data(), length);
}

void MethodMirror::serve(Method& method) const {
  Logger silent;  // this rank's stdout goes nowhere (communicator.hpp's Environment)
  RunOptions options;
  RunContext run{{}, {}, silent, options};
  // mpirun passes Ctrl-C and SIGTERM to every rank: here they only set the flag nobody polls, so
  // that this rank lives on while rank 0 stops the run (its checkpoint gathers from this rank).
  install_stop_handlers();
  for (;;) {
    int code = 0;
    comm_.broadcast(&code, sizeof code);
    try {
      switch (static_cast<MethodCall>(code)) {
        case MethodCall::start: method.start(run); break;
        case MethodCall::resume: {
          unsigned long long length = 0;
          comm_.broadcast(&length, sizeof length);
          std::string file(length, '\0');
          comm_.broadcast(file.data(), length);
          run.checkpoint = file;
          method.resume(run);
          break;
        }
        case MethodCall::advance: method.advance(); break;
        case MethodCall::check_health: method.check_health(); break;
        case MethodCall::write_outputs: method.write_outputs(); break;
        case MethodCall::write_checkpoint: method.write_checkpoint(run.checkpoint); break;
        case MethodCall::write_final_outputs: method.write_final_outputs(); break;
        case MethodCall::thermo_values: method.thermo_values(); break;
        case MethodCall::results: method.results(); break;
        case MethodCall::quit: return;
      }
    } catch (const RunError&) {
      // Rank 0 met it in the same call (the checks are collective) and reports it.
    } catch (const std::exception&) {
      comm_.abort(3);
    }
  }
}

}  // namespace shockfield::parallel
