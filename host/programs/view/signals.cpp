#include "signals.hpp"

#include <csignal>

namespace pfx::app {
namespace {

volatile std::sig_atomic_t g_screenshot = 0;
volatile std::sig_atomic_t g_quit = 0;

extern "C" void on_screenshot_signal(int) { g_screenshot = 1; }
extern "C" void on_quit_signal(int) { g_quit = 1; }

}  // namespace

void install_viewer_signal_handlers() {
  struct sigaction action {};
  sigemptyset(&action.sa_mask);
  action.sa_handler = on_screenshot_signal;
  sigaction(SIGUSR1, &action, nullptr);
  action.sa_handler = on_quit_signal;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool screenshot_signalled() {
  if (!g_screenshot) return false;
  g_screenshot = 0;
  return true;
}

bool quit_signalled() {
  if (!g_quit) return false;
  g_quit = 0;
  return true;
}

}  // namespace pfx::app
