#include <verification/matrix/interruption.hpp>

#include <csignal>

namespace beamimpact::verification {
namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void record_signal(int sig) { g_signal = sig; }

}  // namespace

void forward_interruptions() {
  struct sigaction sa {};
  sa.sa_handler = record_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

int interruption() { return g_signal; }

}  // namespace beamimpact::verification
